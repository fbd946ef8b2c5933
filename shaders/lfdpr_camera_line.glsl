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
