// LFDPR formulas shared by the GPU and the CPU tests (paper section 3). This file is
// written in the common subset of GLSL 4.50 and C++/glm: plain functions over float,
// vec2, vec3, vec4 and small structs; no inout/out parameters, no swizzles, no
// constructors of structs, float literals with the f suffix. The shaders #include it;
// player/render/lfdpr/lfdpr_math.h includes it inside namespace lfd::player::lfdpr_math with
// `using namespace glm`, so tests/player/lfdpr_math_test.cpp tests the code the GPU runs.
//
// Notation (paper): size_xy = world area of one reverse-projected view pixel; size_uv =
// A_ws / n_tex (baker, eq. lfd_UVSize); size_vpuv = texture area of one view pixel (eqs.
// minVPUVSize / maxVPUVSize); LOD (eqs. minLOD / maxLOD); tv (eq. interplateTexValue).

#ifndef LFD_FN
#define LFD_FN // C++ defines it as `inline`
#endif
#ifndef LFD_PRECISE
#define LFD_PRECISE // GLSL defines it as `precise` (no fused multiply-adds)
#endif

// ---------------------------------------------------------------------------------------
// Reverse projection of pixel edges (section 3.1, figure LFD2Dsampling).
//
// A view pixel is a rectangle on the screen plane (the zero-parallax plane every view
// shares). The ray from `eye` through surface point p hits the screen at S, with
// p - eye = t (S - eye), t = ((eye - p) . z) / ((eye - screenPoint) . z) (z: screen
// normal). Moving the screen point by `edge` moves the ray's hit on the plane (p, n) by
//   X(S + edge) - X(S) = t (edge - (p - eye) (n . edge) / (n . (p - eye)))
// (derivative of the hit point along the screen; p - eye = t (S - eye) turns the term
// (S - eye) / (n . (S - eye)) into (p - eye) / (n . (p - eye))). This is the first-order
// footprint; a pixel is tiny against the viewing distance, so its relative error is
// about (pixel / distance) / cos(incidence) (0.1% for a frontal surface on the
// prototype). Returns that vector (it lies in the surface plane and scales linearly with
// `edge`). At grazing angles (n . (p - eye) ~ 0) the
// footprint is unbounded: returns a vector of length 1e30.
LFD_FN vec3 lfdReverseProjectEdge(vec3 p, vec3 n, vec3 eye, vec3 screenPoint, vec3 screenNormal,
                                  vec3 edge)
{
    vec3 d = p - eye;
    float denominator = dot(eye - screenPoint, screenNormal);
    float t = denominator != 0.0f ? dot(eye - p, screenNormal) / denominator : 0.0f;
    float nd = dot(n, d);
    if (abs(nd) <= 1e-7f * length(d) * length(n))
        return normalize(edge) * 1e30f;
    return t * (edge - d * (dot(n, edge) / nd));
}

// ---------------------------------------------------------------------------------------
// Closest point of a triangle to the viewing line (the horizontal line through the camera
// centres). Distances to a line are distances in the plane perpendicular to it, so the
// triangle is projected onto that plane (axes `axisY`, `axisZ`, both perpendicular to the
// line) and the 2D closest point to the line's trace is found; barycentrics survive the
// (linear) projection, so the same weights give the 3D point. Robust for triangles that
// project to a segment or a point (e.g. a triangle containing the line direction).

LFD_FN float lfdCross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Barycentric weights (of a, b, c) of the point of segment-or-triangle closest to o.
LFD_FN vec3 lfdClosestBarycentric2d(vec2 a, vec2 b, vec2 c, vec2 o)
{
    // Inside: the weights are the signed sub-areas.
    float area = lfdCross2(b - a, c - a);
    float scale = dot(b - a, b - a) + dot(c - a, c - a);
    if (abs(area) > 1e-9f * scale) {
        float w0 = lfdCross2(b - o, c - o) / area;
        float w1 = lfdCross2(c - o, a - o) / area;
        float w2 = 1.0f - w0 - w1;
        if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f) {
            vec3 inside = vec3(w0, w1, w2);
            return inside;
        }
    }
    // Outside (or degenerate): the best of the three edges.
    vec2 ab = b - a;
    vec2 bc = c - b;
    vec2 ca = a - c;
    float lab = dot(ab, ab);
    float lbc = dot(bc, bc);
    float lca = dot(ca, ca);
    float sab = lab > 0.0f ? clamp(dot(o - a, ab) / lab, 0.0f, 1.0f) : 0.0f;
    float sbc = lbc > 0.0f ? clamp(dot(o - b, bc) / lbc, 0.0f, 1.0f) : 0.0f;
    float sca = lca > 0.0f ? clamp(dot(o - c, ca) / lca, 0.0f, 1.0f) : 0.0f;
    vec2 pab = a + ab * sab;
    vec2 pbc = b + bc * sbc;
    vec2 pca = c + ca * sca;
    float dab = dot(pab - o, pab - o);
    float dbc = dot(pbc - o, pbc - o);
    float dca = dot(pca - o, pca - o);
    vec3 best = vec3(1.0f - sab, sab, 0.0f);
    float bestDistance = dab;
    if (dbc < bestDistance) {
        best = vec3(0.0f, 1.0f - sbc, sbc);
        bestDistance = dbc;
    }
    if (dca < bestDistance)
        best = vec3(sca, 0.0f, 1.0f - sca);
    return best;
}

// Barycentrics of the triangle point closest to the line through `linePoint` whose
// perpendicular plane is spanned by the unit vectors axisY, axisZ.
LFD_FN vec3 lfdClosestBarycentricToLine(vec3 a, vec3 b, vec3 c, vec3 linePoint, vec3 axisY,
                                        vec3 axisZ)
{
    vec2 a2 = vec2(dot(a - linePoint, axisY), dot(a - linePoint, axisZ));
    vec2 b2 = vec2(dot(b - linePoint, axisY), dot(b - linePoint, axisZ));
    vec2 c2 = vec2(dot(c - linePoint, axisY), dot(c - linePoint, axisZ));
    return lfdClosestBarycentric2d(a2, b2, c2, vec2(0.0f, 0.0f));
}

// ---------------------------------------------------------------------------------------
// T_align: the sampling view's frame (section 3.1; iVIR's T_align, extended with LFD axes).
//
// Derivation. iVIR rotates each triangle so that its normal points down the axis of an
// orthographic sampling view; any in-plane rotation would do for isotropic sampling. LFDPR
// samples with two densities, so the in-plane rotation matters: the sampling view's x
// axis must be the direction in the triangle that the LFD views see as horizontal. The
// views are displaced along the display x axis and all share the display's x and y axes
// (off-axis frusta, no toe-in), so the in-plane direction closest to display x, its
// orthogonal projection U = normalize(x - n (n . x)), is the one the views see as
// horizontal (exactly so whenever the plane contains x, e.g. floors and walls facing the
// viewer; in general it is the in-plane direction with the largest display-x component).
// The vertical axis is the in-plane perpendicular V = n x U, signed to point up (V . y >= 0), and the third axis
// is the normal N = U x V. T_align is the rotation with rows U, V, N: it maps the
// triangle into the plane z = const of the sampling view with display-horizontal along
// sampling x. When the plane is (nearly) perpendicular to x, x projects to ~nothing;
// then the display depth axis z, projected likewise, stands in (in the views such a
// triangle is seen edge-on from the centre and its in-plane depth direction is the one
// that moves horizontally with parallax). A triangle parallel to the viewing direction
// (n . z = 0, e.g. a floor) needs no special case: U = x, V = -z or +z signed by y.
struct LfdFrame {
    vec3 u; // sampling x: the triangle's "horizontal" axis
    vec3 v; // sampling y: the triangle's "vertical" axis
    vec3 n; // sampling z: the triangle normal (u x v)
    int choices; // lfdAlignFrameChoices: what lfdAlignFrameWith needs to rebuild this frame
};

// The frame's two discrete choices, as bits: 1, u from the depth axis (display x projects
// to almost nothing); 2, v negated so that it points up. Each is decided by a sign or a
// threshold that a nearly horizontal (or nearly side-on) triangle sits on, where two
// programs that round differently could decide apart: the visibility pipeline stores the
// choices with the triangle's record (lfdSignedSpacing), so the splat rebuilds the very
// frame point generation sampled in (lfdAlignFrameWith).
LFD_FN int lfdAlignFrameChoices(vec3 faceNormal, vec3 displayX, vec3 displayY, vec3 displayZ)
{
    vec3 n = normalize(faceNormal);
    vec3 h = displayX - n * dot(n, displayX);
    int choices = 0;
    if (dot(h, h) < 1e-6f) {
        h = displayZ - n * dot(n, displayZ);
        choices = 1;
    }
    vec3 v = cross(n, normalize(h));
    if (dot(v, displayY) < 0.0f)
        choices += 2;
    return choices;
}

LFD_FN LfdFrame lfdAlignFrameWith(vec3 faceNormal, vec3 displayX, vec3 displayZ, int choices)
{
    vec3 n = normalize(faceNormal);
    vec3 h = (choices & 1) != 0 ? displayZ - n * dot(n, displayZ) : displayX - n * dot(n, displayX);
    vec3 u = normalize(h);
    vec3 v = cross(n, u);
    if ((choices & 2) != 0)
        v = -v;
    LfdFrame frame;
    frame.u = u;
    frame.v = normalize(v);
    frame.n = cross(frame.u, frame.v);
    frame.choices = choices;
    return frame;
}

LFD_FN LfdFrame lfdAlignFrame(vec3 faceNormal, vec3 displayX, vec3 displayY, vec3 displayZ)
{
    return lfdAlignFrameWith(faceNormal, displayX, displayZ, lfdAlignFrameChoices(faceNormal, displayX, displayY, displayZ));
}

// A record's spacings with the frame's choices in their signs (spacings are positive):
// x negative for choice 1, y negative for choice 2 (lfdAlignFrameChoices).
LFD_FN vec2 lfdSignedSpacing(vec2 spacing, int choices)
{
    return vec2((choices & 1) != 0 ? -spacing.x : spacing.x, (choices & 2) != 0 ? -spacing.y : spacing.y);
}
LFD_FN int lfdSpacingChoices(vec2 signedSpacing)
{
    return (signedSpacing.x < 0.0f ? 1 : 0) + (signedSpacing.y < 0.0f ? 2 : 0);
}

// ---------------------------------------------------------------------------------------
// S_ortho: the two sampling spacings (world lengths of one sampling pixel along U and V).
//
// The finest reverse-projected pixel edges over all views give the spacings (hx, hy);
// S_ortho = diag(1 / hx, 1 / hy, 1) then makes one sampling-viewport pixel exactly one
// point, so rasterising the aligned, scaled triangle yields points spaced hx along U and
// hy along V, i.e. one point per view pixel in the view that samples the triangle most
// finely, in each axis separately (LFD-biased sampling). Without LFD-biased sampling
// (iVIR) both axes use the finer spacing.
LFD_FN vec2 lfdSamplingSpacing(float horizontalEdge, float verticalEdge, bool lfdBiased)
{
    if (lfdBiased)
        return vec2(horizontalEdge, verticalEdge);
    float finest = min(horizontalEdge, verticalEdge);
    return vec2(finest, finest);
}

// Eq. lfd_texelSplatDensity: the factor applied to S_ortho (both densities). When one
// texel covers more world area than one view pixel (size_uv > size_xy), the density drops
// by sqrt(size_xy / size_uv), so there is about one point per texel; the spacings (and
// the splat) grow by the inverse factor.
LFD_FN float lfdTexelSplatDensityScale(float sizeXy, float sizeUv)
{
    if (sizeUv > sizeXy && sizeXy > 0.0f)
        return sqrt(sizeXy / sizeUv);
    return 1.0f;
}

// Sampling transform samplingFromScene = S_ortho * T_align (plus a translation that puts
// `origin` at sampling coordinates (0, 0)): q = ((p - origin) . U / hx, (p - origin) . V / hy).
LFD_FN vec2 lfdSamplingFromScene(vec3 p, vec3 origin, LfdFrame frame, vec2 spacing)
{
    vec3 d = p - origin;
    return vec2(dot(d, frame.u) / spacing.x, dot(d, frame.v) / spacing.y);
}

// Its inverse on the triangle plane: the scene point of sampling coordinates q.
LFD_FN vec3 lfdSceneFromSampling(vec2 q, vec3 origin, LfdFrame frame, vec2 spacing)
{
    return origin + frame.u * (q.x * spacing.x) + frame.v * (q.y * spacing.y);
}

// Triangles whose sampling-space extent exceeds maxTiles tiles of tileSize pixels (the
// geometry shader emits one quad per tile) are sampled coarser: returns the factor (>= 1)
// by which both spacings grow so the extent (plus a 2-pixel margin) fits.
LFD_FN float lfdTileCount(vec2 extent, float tileSize)
{
    return ceil(extent.x / tileSize) * ceil(extent.y / tileSize);
}

LFD_FN float lfdCoarsening(vec2 extent, float tileSize, float maxTiles)
{
    float f = 1.0f;
    for (int i = 0; i < 128; ++i) {
        if (lfdTileCount(extent / f + vec2(2.0f, 2.0f), tileSize) <= maxTiles)
            break;
        f = f * 1.25f;
    }
    return f;
}

// ---------------------------------------------------------------------------------------
// Multiview mipmapping (section 3.3).

// Eqs. minVPUVSize / maxVPUVSize, one view's term: size_xy^v * A_ts / A_ws.
LFD_FN float lfdVpuvSize(float pixelAreaWorld, float texPerWorld)
{
    return pixelAreaWorld * texPerWorld;
}

// Eqs. minLOD / maxLOD: LOD = 0.5 log2(size_vpuv * X_t * Y_t). Guarded for untextured
// triangles (size 0) so the result is finite: LOD 0.
LFD_FN float lfdLod(float sizeVpuv, float texelCount)
{
    float texelsPerPixel = sizeVpuv * texelCount;
    if (!(texelsPerPixel > 0.0f))
        return 0.0f;
    return 0.5f * log2(texelsPerPixel);
}

// Eq. interpolationParameter, first line: the splat's texture area, increased in inverse
// proportion to the part of a view pixel the splat covers (never decreased). splatNdcArea
// is the splat's area in normalised device coordinates ([-1, 1]^2, so * 0.25 * Xv * Yv
// gives view pixels).
LFD_FN float lfdSplatTextureArea(float splatUvArea, float splatNdcArea, vec2 viewSize)
{
    float coveredPixels = splatNdcArea * 0.25f * viewSize.x * viewSize.y;
    return splatUvArea / max(min(1.0f, coveredPixels), 1e-12f);
}

// Eq. interpolationParameter, second line, and the weight of eq. interplateTexValue:
// clamp to [size_vpuv^min, size_vpuv^max] and map to [0, 1]. Guarded: equal bounds
// (one view, or a triangle every view sees alike) give 0, i.e. tv = tv_min.
LFD_FN float lfdMipInterpolation(float sizeVse, float vpuvMin, float vpuvMax)
{
    float range = vpuvMax - vpuvMin;
    if (!(range > 0.0f))
        return 0.0f;
    float sizeVs = clamp(sizeVse, vpuvMin, vpuvMax);
    return (sizeVs - vpuvMin) / range;
}

// Eq. interplateTexValue: tv = tv_min + (tv_max - tv_min) * weight.
LFD_FN vec4 lfdInterpolateTexValue(vec4 tvMin, vec4 tvMax, float weight)
{
    return tvMin + (tvMax - tvMin) * weight;
}

// Texture footprint of a pixel (beyond the paper: the visibility pipeline shades each view
// pixel with textureGrad). The derivative along one window axis of a perspective-correct
// attribute at the pixel centre - one column of the footprint's Jacobian, as EWA filtering
// takes it. `edges`: the pixel's screen barycentrics (its three edge values); `dEdges`:
// their derivatives along the axis (constant: edge functions are affine in the window
// position); `invW`: 1 / w at the vertices; a0..a2: the attribute there. With
// w_k = e_k invW_k the perspective-correct barycentrics are w_k / sum(w), so
//   d a / dx = sum_k dE_k invW_k (a_k - a) / sum(w),   a = sum_k w_k a_k / sum(w).
// A one-pixel forward difference would be the secant half a pixel away: on a receding
// surface always towards the wider footprint, so textures came out blurrier than the
// rasteriser's 2x2-quad differences, which use the nearer secant on half the rows.
LFD_FN vec2 lfdPerspectiveDerivative(vec3 edges, vec3 dEdges, vec3 invW, vec2 a0, vec2 a1, vec2 a2)
{
    vec3 w = edges * invW;
    float invSum = 1.0f / (w.x + w.y + w.z);
    vec2 a = (w.x * a0 + w.y * a1 + w.z * a2) * invSum;
    vec3 dw = dEdges * invW;
    return (dw.x * (a0 - a) + dw.y * (a1 - a) + dw.z * (a2 - a)) * invSum;
}

// ---------------------------------------------------------------------------------------
// Coverage tests (section 3.2).

// Edge function of the directed edge a -> b at p (positive left of the edge).
LFD_FN float lfdEdge(vec2 a, vec2 b, vec2 p)
{
    LFD_PRECISE float value = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    return value;
}

LFD_FN bool lfdVertexLess(vec2 a, vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// The same value as lfdEdge(a, b, p), always evaluated with the endpoints in one fixed
// order, so the two triangles sharing an edge get exactly negated values (no cracks, no
// double coverage from rounding).
LFD_FN float lfdCanonicalEdge(vec2 a, vec2 b, vec2 p)
{
    if (lfdVertexLess(a, b))
        return lfdEdge(a, b, p);
    return -lfdEdge(b, a, p);
}

// Does the edge a -> b of a triangle with orientation sign `orientation` (+1 CCW, -1 CW)
// own sample p? Inside when orientation * value > 0. A sample exactly on the edge belongs
// to exactly one of the two triangles sharing it: the one whose orientation times the
// canonical direction of the edge is positive (the two triangles see the shared edge in
// opposite canonical directions when they lie on opposite sides of it).
LFD_FN bool lfdEdgeOwns(vec2 a, vec2 b, vec2 p, float orientation)
{
    float value = lfdCanonicalEdge(a, b, p) * orientation;
    if (value != 0.0f)
        return value > 0.0f;
    float direction = lfdVertexLess(a, b) ? 1.0f : -1.0f;
    return orientation * direction > 0.0f;
}

// Sample p inside triangle (a, b, c) (either winding); zero-area triangles own nothing.
LFD_FN bool lfdInsideTriangle(vec2 a, vec2 b, vec2 c, vec2 p)
{
    float area = lfdCanonicalEdge(a, b, c);
    if (area == 0.0f)
        return false;
    float orientation = area > 0.0f ? 1.0f : -1.0f;
    return lfdEdgeOwns(a, b, p, orientation) && lfdEdgeOwns(b, c, p, orientation) &&
           lfdEdgeOwns(c, a, p, orientation);
}

// Convex quad (either winding) contains p, edges inclusive: a projected splat cell
// (splats overlap slightly, so samples on a shared cell edge are never lost).
// lfdInsideQuadWithSlack moves each edge outwards by edgeSlack, in edge-function units:
// lfdQuadEdgeSlack scales a slack in pixels by the edges' L1 lengths (>= the Euclidean
// ones, so a point within `slack` pixels of the quad always passes; one within sqrt(2)
// slack may).
LFD_FN bool lfdInsideQuadWithSlack(vec2 a, vec2 b, vec2 c, vec2 d, vec4 edgeSlack, vec2 p)
{
    float e0 = lfdEdge(a, b, p);
    float e1 = lfdEdge(b, c, p);
    float e2 = lfdEdge(c, d, p);
    float e3 = lfdEdge(d, a, p);
    return (e0 >= -edgeSlack.x && e1 >= -edgeSlack.y && e2 >= -edgeSlack.z && e3 >= -edgeSlack.w) ||
           (e0 <= edgeSlack.x && e1 <= edgeSlack.y && e2 <= edgeSlack.z && e3 <= edgeSlack.w);
}
LFD_FN bool lfdInsideQuad(vec2 a, vec2 b, vec2 c, vec2 d, vec2 p)
{
    return lfdInsideQuadWithSlack(a, b, c, d, vec4(0.0f), p);
}
LFD_FN vec4 lfdQuadEdgeSlack(vec2 a, vec2 b, vec2 c, vec2 d, float slack)
{
    vec2 ab = abs(b - a), bc = abs(c - b), cd = abs(d - c), da = abs(a - d);
    return slack * vec4(ab.x + ab.y, bc.x + bc.y, cd.x + cd.y, da.x + da.y);
}

// Conservative rasterisation in the sampling viewport: does the unit pixel square centred
// at `center` overlap triangle (a, b, c)? Separating-axis test: the two box axes (the
// caller's bounding box) and the three edge normals; for an edge, the square is outside
// when even its corner farthest inside is outside, i.e. value + 0.5 (|nx| + |ny|) < 0.
// Degenerate triangles (segments, points) still overlap the pixels they touch.
LFD_FN bool lfdPixelOverlapsTriangle(vec2 center, vec2 a, vec2 b, vec2 c)
{
    float s = lfdEdge(a, b, c) < 0.0f ? -1.0f : 1.0f;
    vec2 lo = min(min(a, b), c);
    vec2 hi = max(max(a, b), c);
    if (center.x + 0.5f < lo.x || center.x - 0.5f > hi.x || center.y + 0.5f < lo.y ||
        center.y - 0.5f > hi.y)
        return false;
    vec2 e0 = b - a;
    vec2 e1 = c - b;
    vec2 e2 = a - c;
    if (s * lfdEdge(a, b, center) + 0.5f * (abs(e0.x) + abs(e0.y)) < 0.0f)
        return false;
    if (s * lfdEdge(b, c, center) + 0.5f * (abs(e1.x) + abs(e1.y)) < 0.0f)
        return false;
    if (s * lfdEdge(c, a, center) + 0.5f * (abs(e2.x) + abs(e2.y)) < 0.0f)
        return false;
    return true;
}

// Barycentrics of p (in the triangle's plane, 2D coordinates) clamped onto the triangle:
// samples of conservatively rasterised pixels may lie just outside it, and their
// attributes (uv above all: atlas neighbours) must come from inside.
LFD_FN vec3 lfdClampedBarycentric(vec2 a, vec2 b, vec2 c, vec2 p)
{
    float area = lfdCross2(b - a, c - a);
    if (area == 0.0f)
        return lfdClosestBarycentric2d(a, b, c, p);
    float w0 = lfdCross2(b - p, c - p) / area;
    float w1 = lfdCross2(c - p, a - p) / area;
    float w2 = 1.0f - w0 - w1;
    if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f) {
        vec3 inside = vec3(w0, w1, w2);
        return inside;
    }
    return lfdClosestBarycentric2d(a, b, c, p);
}

// ---------------------------------------------------------------------------------------
// Octahedral unit-vector encoding (point buffer normals, 2 x snorm16).
LFD_FN vec2 lfdSignNotZero(vec2 v) { return vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f); }

LFD_FN vec2 lfdOctEncode(vec3 n)
{
    vec3 m = n / (abs(n.x) + abs(n.y) + abs(n.z));
    vec2 p = vec2(m.x, m.y);
    if (m.z < 0.0f)
        p = (vec2(1.0f, 1.0f) - abs(vec2(p.y, p.x))) * lfdSignNotZero(p);
    return p;
}

LFD_FN vec3 lfdOctDecode(vec2 e)
{
    vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    if (v.z < 0.0f) {
        vec2 xy = (vec2(1.0f, 1.0f) - abs(vec2(e.y, e.x))) * lfdSignNotZero(e);
        v = vec3(xy.x, xy.y, v.z);
    }
    return normalize(v);
}
