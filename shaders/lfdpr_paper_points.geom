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
#include "lfdpr_triangle_setup.glsl"

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
    LfdprPaperTriangleGpu recordsOut[];
};
layout(std430, binding = LFDPR_SSBO_SAMPLING) coherent writeonly buffer TriangleSamplingOut {
    LfdprPaperSamplingGpu samplingOut[];
};

uint packOct(vec3 v)
{
    return dot(v, v) > 0.0 ? packSnorm2x16(lfdOctEncode(v)) : packSnorm2x16(vec2(0.0, 1.0));
}

void main()
{
    // Steps 1-7 (lfdpr_triangle_setup.glsl): cull, LFD-biased spacings, texture-based
    // splatting, T_align / S_ortho, coarsening, the margin, multiview mipmapping.
    vec3 p0 = v_position[0], p1 = v_position[1], p2 = v_position[2];
    LfdTriangleSetup s;
    if (!lfdSetupTriangle(p0, p1, p2, v_outside[0], v_outside[1], v_outside[2], u_material, u_node,
                          u_streams, u_firstTriangle + uint(gl_PrimitiveIDIn), s))
        return;
    if (s.coarsened)
        atomicAdd(counters.coarsenedCount, 1u);
    if (lfdTileCount(s.extent, float(LFDPR_TILE_SIZE)) > 1.0)
        atomicAdd(counters.oversizedCount, 1u);
    bool doubleSided = s.doubleSided, mirrored = s.mirrored;
    vec2 q0 = s.q0, q1 = s.q1, q2 = s.q2, extent = s.extent, spacing = s.spacing;
    LfdFrame frame = s.frame;
    vec3 origin = s.origin;
    float texPerWorld = s.texPerWorld, vpuvMin = s.vpuvMin, vpuvMax = s.vpuvMax;

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
