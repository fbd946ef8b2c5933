// Camera-line coherence (lfdpr_bindings.glsl, LfdprCameraLineBlock): a scene point is
// projected once, and its window x in any view is one multiply-add from there. Window y,
// w and depth are the same in every view. Needs lfdpr_bindings.glsl first.

// Camera offset of `view` along the line, from view 0 (display mm).
float lfdViewOffset(uint view)
{
    return u_line.viewOffsets[view / 4u][view % 4u];
}

// A projected point: window x = x0 + e * xPerOffset (pixels, GL row 0 = bottom), window y,
// and 1 / w (its depth key; equal in every view).
struct LfdLinePoint {
    float x0;
    float xPerOffset;
    float y;
    float invW;
};

LfdLinePoint lfdProjectOnLine(vec3 p, vec2 viewSize)
{
    vec4 h = vec4(p, 1.0);
    float w = dot(u_line.row3, h);
    LfdLinePoint r;
    r.invW = 1.0 / w;
    r.x0 = (dot(u_line.row0, h) * r.invW * 0.5 + 0.5) * viewSize.x;
    r.xPerOffset = dot(u_line.row0PerOffset, h) * r.invW * 0.5 * viewSize.x;
    r.y = (dot(u_line.row1, h) * r.invW * 0.5 + 0.5) * viewSize.y;
    return r;
}

vec2 lfdWindowInView(LfdLinePoint p, float offset)
{
    return vec2(p.x0 + offset * p.xPerOffset, p.y);
}

// lfdProjectOnLine with the sampling frame's rows (u_line.cull*).
LfdLinePoint lfdProjectForCulling(vec3 p, vec2 viewSize)
{
    vec4 h = vec4(p, 1.0);
    LfdLinePoint r;
    r.invW = 1.0 / dot(u_line.cullRow3, h);
    r.x0 = (dot(u_line.cullRow0, h) * r.invW * 0.5 + 0.5) * viewSize.x;
    r.xPerOffset = dot(u_line.cullRow0PerOffset, h) * r.invW * 0.5 * viewSize.x;
    r.y = (dot(u_line.cullRow1, h) * r.invW * 0.5 + 0.5) * viewSize.y;
    return r;
}

// Pixel-centre culling (beyond the paper; LfdprOptions::pixelCentreCulling): false when
// triangle (p0, p1, p2) holds no view pixel centre in any view, so no point of it could
// win a pixel - lfdpr_visibility.comp writes only pixels whose centre lies inside the
// point's own triangle. Tested on the window bounding box: its rows are the same in every
// view, and its columns move with the camera offset e, where the smallest vertex x is
// concave in e and the largest convex, so over the whole view cone they reach their
// extremes at its two ends (u_line.cullOffsets.xy), whatever views are splatted inside
// it. The margin (1/64 pixel) absorbs the rounding between this test and the splat's
// per-view arithmetic; a vertex behind a camera plane, or a NaN, never culls.
bool lfdMayCoverPixelCentre(vec3 p0, vec3 p1, vec3 p2)
{
    vec2 viewSize = u_lfd.viewSize.xy;
    LfdLinePoint v0 = lfdProjectForCulling(p0, viewSize), v1 = lfdProjectForCulling(p1, viewSize);
    LfdLinePoint v2 = lfdProjectForCulling(p2, viewSize);
    if (!(v0.invW > 0.0 && v1.invW > 0.0 && v2.invW > 0.0))
        return true;
    const float margin = 1.0 / 64.0;
    float eLo = u_line.cullOffsets.x, eHi = u_line.cullOffsets.y;
    vec3 xLoEnd = vec3(v0.x0, v1.x0, v2.x0) + eLo * vec3(v0.xPerOffset, v1.xPerOffset, v2.xPerOffset);
    vec3 xHiEnd = vec3(v0.x0, v1.x0, v2.x0) + eHi * vec3(v0.xPerOffset, v1.xPerOffset, v2.xPerOffset);
    vec3 x3 = min(xLoEnd, xHiEnd), X3 = max(xLoEnd, xHiEnd);
    vec2 lo = vec2(min(min(x3.x, x3.y), x3.z), min(min(v0.y, v1.y), v2.y)) - margin;
    vec2 hi = vec2(max(max(X3.x, X3.y), X3.z), max(max(v0.y, v1.y), v2.y)) + margin;
    // First and last pixel centre (c + 0.5) inside [lo, hi], within the view.
    vec2 first = max(ceil(lo - 0.5), vec2(0.0));
    vec2 last = min(floor(hi - 0.5), viewSize - 1.0);
    return !(first.x > last.x) && !(first.y > last.y);
}


// A triangle in one view, ready for per-pixel tests: window positions, 1 / w at its
// vertices, and its orientation (+1 counter-clockwise, -1 clockwise, 0 degenerate) from
// the canonical edge function, as lfdInsideTriangle decides it.
struct LfdViewTriangle {
    vec2 s0;
    vec2 s1;
    vec2 s2;
    vec3 invW;
    float orientation;
};

LfdViewTriangle lfdViewTriangle(vec2 s0, vec2 s1, vec2 s2, vec3 invW)
{
    LfdViewTriangle t;
    t.s0 = s0;
    t.s1 = s1;
    t.s2 = s2;
    t.invW = invW;
    float area = lfdCanonicalEdge(s0, s1, s2);
    t.orientation = area > 0.0 ? 1.0 : (area < 0.0 ? -1.0 : 0.0);
    return t;
}

// The three canonical edge values at p: opposite s0, s1 and s2 (each triangle sharing an
// edge gets exactly the negated value, lfdCanonicalEdge), which are also p's unnormalised
// screen barycentrics.
vec3 lfdEdgeValues(LfdViewTriangle t, vec2 p)
{
    precise vec3 e = vec3(lfdCanonicalEdge(t.s1, t.s2, p), lfdCanonicalEdge(t.s2, t.s0, p),
                          lfdCanonicalEdge(t.s0, t.s1, p));
    return e;
}

// lfdInsideTriangle from precomputed edge values (same tie rule as lfdEdgeOwns: a sample
// on a shared edge belongs to exactly one of the two triangles).
bool lfdOwnsSample(LfdViewTriangle t, vec3 e)
{
    vec3 v = e * t.orientation;
    bool own0 = v.x != 0.0 ? v.x > 0.0 : t.orientation * (lfdVertexLess(t.s1, t.s2) ? 1.0 : -1.0) > 0.0;
    bool own1 = v.y != 0.0 ? v.y > 0.0 : t.orientation * (lfdVertexLess(t.s2, t.s0) ? 1.0 : -1.0) > 0.0;
    bool own2 = v.z != 0.0 ? v.z > 0.0 : t.orientation * (lfdVertexLess(t.s0, t.s1) ? 1.0 : -1.0) > 0.0;
    return t.orientation != 0.0 && own0 && own1 && own2;
}

// Depth key of the triangle's plane at a pixel from its edge values: 1 / w interpolated
// with the screen barycentrics (exact for a plane), mapped so that a smaller key is nearer
// and 0xFFFFFFFF stays "empty". The visibility pass and the shading pass's check both
// use it, so the same pixel and triangle give bit-identical keys.
uint lfdPlaneDepthKey(LfdViewTriangle t, vec3 e)
{
    precise float w = dot(e, t.invW) / (e.x + e.y + e.z);
    return 0x7F800000u - floatBitsToUint(w);
}

// The key of 1 / w (for the clip test: keys of the near and far planes).
uint lfdDepthKey(float invW)
{
    return 0x7F800000u - floatBitsToUint(invW);
}
