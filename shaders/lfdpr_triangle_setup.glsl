// LFDPR per-triangle sampling setup (paper section 3.1), shared by both point generators:
// the geometry shader of the paper's pipeline (lfdpr_paper_points.geom) and the compute path
// (lfdpr_visibility_points.comp). One function, so both sample every triangle identically and emit
// the same point set. Needs scene_bindings.glsl, lfdpr_bindings.glsl and lfdpr_math.glsl.
//
// Steps: cull; find the triangle's point closest to the viewing line; reverse-project one
// view pixel's edges there in every view that sees the triangle (LFD-biased spacings, the
// pixel areas for multiview mipmapping); reduce the density by texture (eq.
// lfd_texelSplatDensity); align with the sampling view (T_align) and scale (S_ortho);
// coarsen triangles beyond LFDPR_MAX_TILES tiles; add a one-pixel margin.

struct LfdTriangleSetup {
    vec3 faceNormal;    // unit, geometric (p1 - p0) x (p2 - p0)
    bool doubleSided;
    bool mirrored;      // node transform flips the winding
    LfdFrame frame;     // T_align rows
    vec2 spacing;       // final spacings (texture splatting and coarsening applied)
    vec2 q0;            // sampling coordinates of the vertices, margin shift applied
    vec2 q1;
    vec2 q2;
    vec2 extent;        // sampling pixels of the bounding box (integers), margin included
    vec3 origin;        // scene point of sampling coordinates (0, 0)
    float vpuvMin;      // eqs. minVPUVSize, maxVPUVSize
    float vpuvMax;
    float texPerWorld;  // A_ts / A_ws in scene units
    bool coarsened;     // larger than LFDPR_MAX_TILES tiles: sampled coarser
};

// The finest reverse-projected view-pixel edges (horizontal, vertical) at `closest` over
// every view that sees the triangle, and the least and greatest pixel footprint area;
// finest* stay >= 1e29 when the triangle is edge-on in every view that faces it.
struct LfdPixelEdges {
    float finestH, finestV, pixelAreaMin, pixelAreaMax;
};

LfdPixelEdges lfdFinestPixelEdges(vec3 p0, vec3 closest, vec3 faceNormal, vec3 frontNormal, bool doubleSided,
                                  uint viewCount)
{
    vec3 displayZ = u_lfd.displayZ.xyz;
    vec3 edgeH = u_lfd.displayX.xyz * u_lfd.displayX.w;
    vec3 edgeV = u_lfd.displayY.xyz * u_lfd.displayY.w;
    LfdPixelEdges e = LfdPixelEdges(1e30, 1e30, 1e30, 0.0);
    for (uint v = 0u; v < viewCount; ++v) {
        vec3 eye = views[v].eyeScene.xyz;
        if (!doubleSided && dot(frontNormal, eye - p0) <= 0.0)
            continue;
        vec3 eh = lfdReverseProjectEdge(closest, faceNormal, eye, u_lfd.screenCenter.xyz, displayZ, edgeH);
        vec3 ev = lfdReverseProjectEdge(closest, faceNormal, eye, u_lfd.screenCenter.xyz, displayZ, edgeV);
        float lh = length(eh), lv = length(ev);
        if (lh >= 1e29 || lv >= 1e29)
            continue; // grazing in this view
        e.finestH = min(e.finestH, lh);
        e.finestV = min(e.finestV, lv);
        float pixelArea = length(cross(eh, ev));
        e.pixelAreaMin = min(e.pixelAreaMin, pixelArea);
        e.pixelAreaMax = max(e.pixelAreaMax, pixelArea);
    }
    return e;
}

// T_align and S_ortho: the vertices' sampling coordinates in s.frame (p0 at the origin),
// with one pixel of margin on each side for the conservative pixels; beyond
// LFDPR_MAX_TILES tiles the triangle is sampled coarser (spacing grows, s.coarsened).
void lfdPlaceSampling(vec3 p0, vec3 p1, vec3 p2, inout vec2 spacing, inout LfdTriangleSetup s)
{
    vec2 q0 = lfdSamplingFromScene(p0, p0, s.frame, spacing);
    vec2 q1 = lfdSamplingFromScene(p1, p0, s.frame, spacing);
    vec2 q2 = lfdSamplingFromScene(p2, p0, s.frame, spacing);
    vec2 lo = min(min(q0, q1), q2), hi = max(max(q0, q1), q2);
    float coarsening = lfdCoarsening(hi - lo, float(LFDPR_TILE_SIZE), float(LFDPR_MAX_TILES));
    if (coarsening > 1.0) {
        spacing *= coarsening;
        q0 /= coarsening;
        q1 /= coarsening;
        q2 /= coarsening;
        lo /= coarsening;
        hi /= coarsening;
        s.coarsened = true;
    }
    vec2 shift = vec2(1.0) - lo;
    s.q0 = q0 + shift;
    s.q1 = q1 + shift;
    s.q2 = q2 + shift;
    s.extent = ceil(hi - lo + vec2(2.0));
    s.origin = lfdSceneFromSampling(-shift, p0, s.frame, spacing);
    s.spacing = spacing;
}

// False when the triangle is culled: outside every view (all vertices outside one hull
// plane), degenerate, facing away from every camera (single-sided), or edge-on in every
// view that faces it. `outside*`: per vertex, bit k set when outside hull plane k.
bool lfdSetupTriangle(vec3 p0, vec3 p1, vec3 p2, uint outside0, uint outside1, uint outside2,
                      uint materialIndex, uint node, uint streams, uint statsIndex,
                      out LfdTriangleSetup s)
{
    // Step 1: cull (the cameras lie on a segment, so facing is decided by its two ends).
    s.coarsened = false;
    if ((outside0 & outside1 & outside2) != 0u)
        return false;
    vec3 faceCross = cross(p1 - p0, p2 - p0);
    float faceCrossLength = length(faceCross);
    if (!(faceCrossLength > 0.0))
        return false;
    vec3 faceNormal = faceCross / faceCrossLength;
    s.faceNormal = faceNormal;
    MaterialGpu material = materials[materialIndex];
    s.doubleSided = (material.flags & LFD_MATERIAL_DOUBLE_SIDED) != 0u;
    s.mirrored = determinant(mat3(nodes[node].sceneFromObject)) < 0.0;
    vec3 frontNormal = s.mirrored ? -faceNormal : faceNormal;
    uint viewCount = u_lfd.counts.x;
    if (!s.doubleSided && dot(frontNormal, views[0].eyeScene.xyz - p0) <= 0.0 &&
        dot(frontNormal, views[viewCount - 1u].eyeScene.xyz - p0) <= 0.0)
        return false;

    // Step 2: the triangle's point closest to the viewing line (the horizontal line
    // through the camera centres), where its pixel footprint is smallest.
    vec3 displayX = u_lfd.displayX.xyz, displayY = u_lfd.displayY.xyz, displayZ = u_lfd.displayZ.xyz;
    vec3 w = lfdClosestBarycentricToLine(p0, p1, p2, u_lfd.viewLine.xyz, displayY, displayZ);
    vec3 closest = w.x * p0 + w.y * p1 + w.z * p2;

    // Step 3: reverse-project one view pixel's horizontal and vertical edges onto the
    // triangle plane there, in every view that sees the triangle: the finest edge per axis
    // sets the spacings; the pixel's area per view gives size_xy^v for size_vpuv.
    LfdPixelEdges edges = lfdFinestPixelEdges(p0, closest, faceNormal, frontNormal, s.doubleSided, viewCount);
    float finestH = edges.finestH, finestV = edges.finestV;
    float pixelAreaMin = edges.pixelAreaMin, pixelAreaMax = edges.pixelAreaMax;
    if (finestH >= 1e29 || finestV >= 1e29)
        return false; // edge-on in every view that faces it

    // Step 4: LFD-biased spacings (iVIR's isotropic spacing when switched off) and the
    // world area of the pixel footprint, size_xy.
    uint options = u_lfd.counts.z;
    vec2 spacing = lfdSamplingSpacing(finestH, finestV, (options & LFDPR_OPTION_LFD_SAMPLING) != 0u);
    float sizeXy = spacing.x * spacing.y;
    vec2 pixelSpacing = spacing;

    // Step 5: texture-based splatting (eq. lfd_texelSplatDensity). The baker's statistics
    // are in object space; the ratio of the triangle's scene and object areas scales them.
    TriangleStatsGpu stats = triangleStats[statsIndex];
    float areaScale = stats.areaWorld > 0.0 ? 0.5 * faceCrossLength / stats.areaWorld : 0.0;
    bool textured = (streams & LFD_STREAM_UV) != 0u && areaScale > 0.0;
    float sizeUv = textured ? stats.sizeUv * areaScale : 0.0;
    s.texPerWorld = textured ? stats.texPerWorld / areaScale : 0.0;
    if ((options & LFDPR_OPTION_TEXTURE_SPLATTING) != 0u)
        spacing /= lfdTexelSplatDensityScale(sizeXy, sizeUv);
#ifdef LFDPR_CELL_SCALE
    // Beyond the paper (LfdprOptions::cellScale; compute point generation of the
    // visibility pipeline only): cells of several sampling spacings, fewer points.
    spacing *= float(LFDPR_CELL_SCALE);
#endif
#if defined(LFDPR_MAX_SPLAT_PIXELS) && !defined(LFDPR_ALPHA_TEST)
    // Beyond the paper (visibility pipeline, GPU work shape: lfdpr_work_shape.glsl): a
    // cell spans at most LFDPR_MAX_SPLAT_PIXELS of the finest view pixel per axis, so a
    // coarse texture's large splat becomes several small points and no splat invocation
    // loops over many pixels. The views do not change (the splat writes only pixel centres
    // inside the point's own triangle, shaded at the pixel). Alpha-masked cells keep their
    // size: their mask is sampled per cell.
    spacing = min(spacing, pixelSpacing * LFDPR_MAX_SPLAT_PIXELS);
#endif

    // Step 6: T_align and S_ortho: sampling coordinates of the vertices (p0 at the origin);
    // beyond LFDPR_MAX_TILES tiles the triangle is sampled coarser.
    s.frame = lfdAlignFrame(faceNormal, displayX, displayY, displayZ);
    lfdPlaceSampling(p0, p1, p2, spacing, s);

    // Step 7: multiview mipmapping setup (eqs. minVPUVSize, maxVPUVSize).
    s.vpuvMin = lfdVpuvSize(pixelAreaMin, s.texPerWorld);
    s.vpuvMax = lfdVpuvSize(pixelAreaMax, s.texPerWorld);
    return true;
}

// Bit k set when scene point p is outside plane k of the union of the view frusta.
uint lfdOutsideHullBits(vec3 p)
{
    uint outside = 0u;
    for (int k = 0; k < 6; ++k)
        if (dot(u_lfd.planes[k], vec4(p, 1.0)) < 0.0)
            outside |= 1u << uint(k);
    return outside;
}
