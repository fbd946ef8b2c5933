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
// win a pixel - lfdpr_visibility_splat.comp writes only pixels whose centre lies inside the
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


// A triangle in one view, ready for per-pixel tests: window positions (on the sub-pixel
// grid, lfdSnapToSubpixels), 1 / w at its
// vertices, its orientation (+1 counter-clockwise, -1 clockwise, 0 degenerate) from the
// canonical edge function, as lfdInsideTriangle decides it, and its three edges in
// canonical order (lfdCanonicalEdge), decided here once rather than at every pixel.
// Edge k is the one opposite vertex k: it starts at edgeStart[k], runs along edgeRun[k]
// (the canonical end minus the canonical start), and its value at p is edgeSign[k] times
// lfdEdge(start, end, p) - the very operations lfdCanonicalEdge does, so the values are
// bit-identical to it and the two triangles sharing an edge still get exactly negated
// values. edgeOwnsTies[k]: whether a sample exactly on edge k belongs to this triangle
// (lfdSetCanonicalEdge's tie rule).
struct LfdViewTriangle {
    vec2 s0;
    vec2 s1;
    vec2 s2;
    vec3 invW;
    float orientation;
    vec2 edgeStart[3];
    vec2 edgeRun[3];
    vec3 edgeSign;
    bvec3 edgeOwnsTies;
};

// Window positions snapped to the rasteriser's sub-pixel grid (GL_SUBPIXEL_BITS: 8 on
// Mesa's llvmpipe and on NVIDIA's driver), as it snaps vertices before its edge tests, so
// that lfdpr decides the pixel centres that lie within a fraction of a sub-pixel of an
// edge as the rasteriser does (mvr, and gstd's sub-views) instead of by float rounding.
// On the grid the edge values of the small triangles a bake makes are exact in float (run
// and offset are multiples of 1/256 pixel), so a sample exactly on an edge gives exactly 0
// and the tie rule decides it.
#define LFDPR_SUBPIXEL_STEPS 256.0
vec2 lfdSnapToSubpixels(vec2 s)
{
    return floor(s * LFDPR_SUBPIXEL_STEPS + 0.5) / LFDPR_SUBPIXEL_STEPS;
}
float lfdSnapToSubpixels(float s)
{
    return floor(s * LFDPR_SUBPIXEL_STEPS + 0.5) / LFDPR_SUBPIXEL_STEPS;
}

// Edge (a, b) of t in canonical order, as slot k. Tie rule (a sample exactly on the edge):
// the rasteriser's left / bottom-edge convention. Walked counter-clockwise (GL window
// coordinates, y up), the edge owns its samples when it goes down (the triangle lies to
// its right: a left edge) or, horizontal, when it goes right (the triangle lies above it:
// a bottom edge). The two triangles sharing an edge walk it in opposite directions, so
// exactly one owns each sample on it.
void lfdSetCanonicalEdge(inout LfdViewTriangle t, int k, vec2 a, vec2 b)
{
    bool forward = lfdVertexLess(a, b);
    vec2 start = forward ? a : b, end = forward ? b : a;
    t.edgeStart[k] = start;
    precise vec2 run = end - start;
    t.edgeRun[k] = run;
    t.edgeSign[k] = forward ? 1.0 : -1.0;
    vec2 counterClockwise = run * (t.orientation * t.edgeSign[k]);
    t.edgeOwnsTies[k] = counterClockwise.y < 0.0 || (counterClockwise.y == 0.0 && counterClockwise.x > 0.0);
}

// The triangle of vertices already on the sub-pixel grid (the splat snaps their window y
// once per point and x once per view: docs/player/8k-panels.md "Splat culling").
LfdViewTriangle lfdViewTriangleSnapped(vec2 s0, vec2 s1, vec2 s2, vec3 invW)
{
    LfdViewTriangle t;
    t.s0 = s0;
    t.s1 = s1;
    t.s2 = s2;
    t.invW = invW;
    float area = lfdCanonicalEdge(s0, s1, s2);
    t.orientation = area > 0.0 ? 1.0 : (area < 0.0 ? -1.0 : 0.0);
    lfdSetCanonicalEdge(t, 0, s1, s2);
    lfdSetCanonicalEdge(t, 1, s2, s0);
    lfdSetCanonicalEdge(t, 2, s0, s1);
    return t;
}

// s0..s2 are snapped here (lfdSnapToSubpixels; the snap is idempotent, so a caller that
// snapped them already for its pixel bounds gets the same triangle).
LfdViewTriangle lfdViewTriangle(vec2 s0, vec2 s1, vec2 s2, vec3 invW)
{
    return lfdViewTriangleSnapped(lfdSnapToSubpixels(s0), lfdSnapToSubpixels(s1), lfdSnapToSubpixels(s2), invW);
}

// Canonical edge k's value at p (= lfdCanonicalEdge of the edge, bit for bit: lfdEdge's
// products and difference on the same operands).
float lfdViewTriangleEdge(LfdViewTriangle t, int k, vec2 p)
{
    precise vec2 d = p - t.edgeStart[k];
    precise float value = t.edgeRun[k].x * d.y - t.edgeRun[k].y * d.x;
    return t.edgeSign[k] * value;
}

// The three canonical edge values at p: opposite s0, s1 and s2 (each triangle sharing an
// edge gets exactly the negated value, lfdCanonicalEdge), which are also p's unnormalised
// screen barycentrics.
vec3 lfdEdgeValues(LfdViewTriangle t, vec2 p)
{
    return vec3(lfdViewTriangleEdge(t, 0, p), lfdViewTriangleEdge(t, 1, p), lfdViewTriangleEdge(t, 2, p));
}

// Whether t owns sample p, from p's precomputed edge values (a sample on a shared edge
// belongs to exactly one of the two triangles: lfdSetCanonicalEdge's tie rule).
bool lfdOwnsSample(LfdViewTriangle t, vec3 e)
{
    bvec3 own = bvec3(e.x != 0.0 ? e.x * t.orientation > 0.0 : t.edgeOwnsTies.x,
                      e.y != 0.0 ? e.y * t.orientation > 0.0 : t.edgeOwnsTies.y,
                      e.z != 0.0 ? e.z * t.orientation > 0.0 : t.edgeOwnsTies.z);
    return t.orientation != 0.0 && all(own);
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
