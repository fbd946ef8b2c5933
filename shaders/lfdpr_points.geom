#version 450 core
// LFDPR point generation, geometry stage (paper section 3.1): per triangle, cull, choose
// the two LFD-biased sampling spacings, reduce them by texture (eq.
// lfd_texelSplatDensity), set up multiview mipmapping (eqs. minVPUVSize, maxVPUVSize),
// align the triangle with the sampling view (T_align) and scale it (S_ortho) so that one
// sampling-viewport pixel is one point, and emit it. The formulas live in
// lfdpr_math.glsl (tested on the CPU); this file only strings them together.
//
// What is emitted: the triangle's sampling-space bounding box (1 pixel margin), as one
// quad per LFDPR_TILE_SIZE^2 tile of the sampling viewport, with the tile's origin as a
// flat output. The fragment shader keeps exactly the pixels whose square overlaps the
// triangle (conservative rasterisation), so every triangle yields at least one point -
// however small or thin - and the splats of a triangle cover all of it. Triangles larger
// than LFDPR_MAX_TILES tiles are sampled coarser (their splats grow) and counted.
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 64) out; // 4 * LFDPR_MAX_TILES

layout(location = 0) in vec3 v_position[];
layout(location = 1) in vec3 v_normal[];
layout(location = 2) in vec4 v_tangent[];
layout(location = 3) in vec2 v_uv[];
layout(location = 4) flat in uint v_outside[];

layout(location = 0) flat out uint g_record;
layout(location = 1) flat out vec2 g_tileOrigin; // sampling coordinates of viewport (0, 0)

layout(location = LFD_LOC_NODE) uniform uint u_node;
layout(location = LFD_LOC_MATERIAL) uniform uint u_material;
layout(location = LFD_LOC_STREAMS) uniform uint u_streams;
layout(location = LFDPR_LOC_RECORD_BASE) uniform uint u_recordBase;
layout(location = LFDPR_LOC_FIRST_TRIANGLE) uniform uint u_firstTriangle;

layout(std430, binding = LFDPR_SSBO_TRIANGLES) coherent writeonly buffer TriangleRecordsOut {
    TriangleRecordGpu recordsOut[];
};
layout(std430, binding = LFDPR_SSBO_SAMPLING) coherent writeonly buffer TriangleSamplingOut {
    TriangleSamplingGpu samplingOut[];
};

uint packOct(vec3 v)
{
    return dot(v, v) > 0.0 ? packSnorm2x16(lfdOctEncode(v)) : packSnorm2x16(vec2(0.0, 1.0));
}

void main()
{
    // Step 1: cull triangles outside every view (all vertices outside one hull plane),
    // degenerate ones, and single-sided ones that every view sees from behind (the
    // cameras lie on a segment, so facing is decided by its two ends).
    if ((v_outside[0] & v_outside[1] & v_outside[2]) != 0u)
        return;
    vec3 p0 = v_position[0], p1 = v_position[1], p2 = v_position[2];
    vec3 faceCross = cross(p1 - p0, p2 - p0);
    float faceCrossLength = length(faceCross);
    if (!(faceCrossLength > 0.0))
        return;
    vec3 faceNormal = faceCross / faceCrossLength;
    MaterialGpu material = materials[u_material];
    bool doubleSided = (material.flags & LFD_MATERIAL_DOUBLE_SIDED) != 0u;
    bool mirrored = determinant(mat3(nodes[u_node].sceneFromObject)) < 0.0;
    vec3 frontNormal = mirrored ? -faceNormal : faceNormal;
    uint viewCount = u_lfd.counts.x;
    if (!doubleSided && dot(frontNormal, views[0].eyeScene.xyz - p0) <= 0.0 &&
        dot(frontNormal, views[viewCount - 1u].eyeScene.xyz - p0) <= 0.0)
        return;

    // Step 2: the triangle's point closest to the viewing line (the horizontal line
    // through the camera centres), where its pixel footprint is smallest.
    vec3 displayX = u_lfd.displayX.xyz, displayY = u_lfd.displayY.xyz, displayZ = u_lfd.displayZ.xyz;
    vec3 w = lfdClosestBarycentricToLine(p0, p1, p2, u_lfd.viewLine.xyz, displayY, displayZ);
    vec3 closest = w.x * p0 + w.y * p1 + w.z * p2;

    // Step 3: reverse-project one view pixel's horizontal and vertical edges onto the
    // triangle plane there, in every view that sees the triangle: the finest edge per axis
    // sets the spacings; the pixel's area per view gives size_xy^v for size_vpuv.
    vec3 edgeH = displayX * u_lfd.displayX.w;
    vec3 edgeV = displayY * u_lfd.displayY.w;
    float finestH = 1e30, finestV = 1e30, pixelAreaMin = 1e30, pixelAreaMax = 0.0;
    for (uint v = 0u; v < viewCount; ++v) {
        vec3 eye = views[v].eyeScene.xyz;
        if (!doubleSided && dot(frontNormal, eye - p0) <= 0.0)
            continue;
        vec3 eh = lfdReverseProjectEdge(closest, faceNormal, eye, u_lfd.screenCenter.xyz, displayZ, edgeH);
        vec3 ev = lfdReverseProjectEdge(closest, faceNormal, eye, u_lfd.screenCenter.xyz, displayZ, edgeV);
        float lh = length(eh), lv = length(ev);
        if (lh >= 1e29 || lv >= 1e29)
            continue; // grazing in this view
        finestH = min(finestH, lh);
        finestV = min(finestV, lv);
        float pixelArea = length(cross(eh, ev));
        pixelAreaMin = min(pixelAreaMin, pixelArea);
        pixelAreaMax = max(pixelAreaMax, pixelArea);
    }
    if (finestH >= 1e29 || finestV >= 1e29)
        return; // edge-on in every view that faces it

    // Step 4: LFD-biased spacings (iVIR's isotropic spacing when switched off) and the
    // world area of the pixel footprint, size_xy.
    uint options = u_lfd.counts.z;
    vec2 spacing = lfdSamplingSpacing(finestH, finestV, (options & LFDPR_OPTION_LFD_SAMPLING) != 0u);
    float sizeXy = spacing.x * spacing.y;

    // Step 5: texture-based splatting (eq. lfd_texelSplatDensity). The baker's statistics
    // are in object space; the ratio of the triangle's scene and object areas scales them.
    TriangleStatsGpu stats = triangleStats[u_firstTriangle + uint(gl_PrimitiveIDIn)];
    float areaScale = stats.areaWorld > 0.0 ? 0.5 * faceCrossLength / stats.areaWorld : 0.0;
    bool textured = (u_streams & LFD_STREAM_UV) != 0u && areaScale > 0.0;
    float sizeUv = textured ? stats.sizeUv * areaScale : 0.0;
    float texPerWorld = textured ? stats.texPerWorld / areaScale : 0.0;
    if ((options & LFDPR_OPTION_TEXTURE_SPLATTING) != 0u)
        spacing /= lfdTexelSplatDensityScale(sizeXy, sizeUv);

    // Step 6: T_align and S_ortho: sampling coordinates of the vertices (p0 at the origin);
    // oversized triangles are tiled, and beyond LFDPR_MAX_TILES sampled coarser.
    LfdFrame frame = lfdAlignFrame(faceNormal, displayX, displayY, displayZ);
    vec2 q0 = lfdSamplingFromScene(p0, p0, frame, spacing);
    vec2 q1 = lfdSamplingFromScene(p1, p0, frame, spacing);
    vec2 q2 = lfdSamplingFromScene(p2, p0, frame, spacing);
    vec2 lo = min(min(q0, q1), q2), hi = max(max(q0, q1), q2);
    float coarsening = lfdCoarsening(hi - lo, float(LFDPR_TILE_SIZE), float(LFDPR_MAX_TILES));
    if (coarsening > 1.0) {
        spacing *= coarsening;
        q0 /= coarsening;
        q1 /= coarsening;
        q2 /= coarsening;
        lo /= coarsening;
        hi /= coarsening;
        atomicAdd(counters.coarsenedCount, 1u);
    }
    // One pixel of margin on each side for the conservative pixels.
    vec2 shift = vec2(1.0) - lo;
    q0 += shift;
    q1 += shift;
    q2 += shift;
    vec2 extent = ceil(hi - lo + vec2(2.0));
    if (lfdTileCount(extent, float(LFDPR_TILE_SIZE)) > 1.0)
        atomicAdd(counters.oversizedCount, 1u);
    vec3 origin = lfdSceneFromSampling(-shift, p0, frame, spacing);

    // Step 7: multiview mipmapping setup (eqs. minVPUVSize, maxVPUVSize).
    float vpuvMin = lfdVpuvSize(pixelAreaMin, texPerWorld);
    float vpuvMax = lfdVpuvSize(pixelAreaMax, texPerWorld);

    // Step 8: the triangle's records (read by the point FS and by view generation).
    uint record = u_recordBase + uint(gl_PrimitiveIDIn);
    uint flags = (doubleSided ? uint(LFDPR_TRIANGLE_DOUBLE_SIDED) : 0u) |
                 (mirrored ? uint(LFDPR_TRIANGLE_MIRRORED) : 0u) |
                 ((u_streams & LFD_STREAM_NORMAL) == 0u ? uint(LFDPR_TRIANGLE_FACE_NORMAL) : 0u);
    recordsOut[record].p0 = vec4(p0, uintBitsToFloat(u_material));
    recordsOut[record].p1 = vec4(p1, texPerWorld);
    recordsOut[record].p2 = vec4(p2, uintBitsToFloat(flags));
    recordsOut[record].axisU = vec4(frame.u, spacing.x);
    recordsOut[record].axisV = vec4(frame.v, spacing.y);
    recordsOut[record].mip = vec4(vpuvMin, vpuvMax, 0.0, 0.0);
    samplingOut[record].origin = vec4(origin, 0.0);
    samplingOut[record].q01 = vec4(q0, q1);
    samplingOut[record].q2uv0 = vec4(q2, v_uv[0]);
    samplingOut[record].uv12 = vec4(v_uv[1], v_uv[2]);
    samplingOut[record].normals = uvec4(packOct(v_normal[0]), packOct(v_normal[1]), packOct(v_normal[2]), 0u);
    samplingOut[record].tangents =
        uvec4(packOct(v_tangent[0].xyz), packOct(v_tangent[1].xyz), packOct(v_tangent[2].xyz),
              (v_tangent[0].w < 0.0 ? 1u : 0u) | (v_tangent[1].w < 0.0 ? 2u : 0u) |
                  (v_tangent[2].w < 0.0 ? 4u : 0u));
    // note: the fragments of this primitive read the records; make the writes visible.
    memoryBarrierBuffer();
    atomicAdd(counters.triangleCount, 1u);

    // Step 9: emit the bounding box, one viewport-sized tile at a time.
    const float tile = float(LFDPR_TILE_SIZE);
    int tilesX = int(ceil(extent.x / tile)), tilesY = int(ceil(extent.y / tile));
    for (int ty = 0; ty < tilesY; ++ty) {
        for (int tx = 0; tx < tilesX; ++tx) {
            vec2 tileOrigin = vec2(tx, ty) * tile;
            vec2 a = vec2(0.0);
            vec2 b = min(extent - tileOrigin, vec2(tile));
            vec2 ndcA = a / tile * 2.0 - 1.0, ndcB = b / tile * 2.0 - 1.0;
            g_record = record; g_tileOrigin = tileOrigin;
            gl_Position = vec4(ndcA.x, ndcA.y, 0.0, 1.0);
            EmitVertex();
            g_record = record; g_tileOrigin = tileOrigin;
            gl_Position = vec4(ndcB.x, ndcA.y, 0.0, 1.0);
            EmitVertex();
            g_record = record; g_tileOrigin = tileOrigin;
            gl_Position = vec4(ndcA.x, ndcB.y, 0.0, 1.0);
            EmitVertex();
            g_record = record; g_tileOrigin = tileOrigin;
            gl_Position = vec4(ndcB.x, ndcB.y, 0.0, 1.0);
            EmitVertex();
            EndPrimitive();
        }
    }
}
