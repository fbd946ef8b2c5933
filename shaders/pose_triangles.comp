#version 450
// The pose pass's second step: the per-triangle statistics that depend on the triangle's
// size follow the pose (paper section 3.1, baker/triangle_stats.cpp), so lfdpr samples a
// stretched triangle as densely as a baked one of that size. A_ts and n_tex do not move
// with the vertices; A_ws (object units^2, from the posed positions), size_uv = A_ws /
// max(n_tex, 1) and A_ts / A_ws are recomputed, and the degenerate flag with them.
// One invocation per triangle of [u_firstTriangle, + u_triangleCount), all deformed.
#include "pose_buffers.glsl"

layout(local_size_x = POSE_LOCAL_SIZE) in;

vec3 posed(uint i) { return vec3(positions[3u * i], positions[3u * i + 1u], positions[3u * i + 2u]); }

void main()
{
    if (gl_GlobalInvocationID.x >= u_triangleCount)
        return;
    const uint t = u_firstTriangle + gl_GlobalInvocationID.x;
    const vec3 p0 = posed(indices[3u * t]);
    const float area = 0.5 * length(cross(posed(indices[3u * t + 1u]) - p0, posed(indices[3u * t + 2u]) - p0));
    TriangleStatsGpu s = triangleStats[t];
    // baker/triangle_stats.cpp: areas of 1e-30 or less (and NaN) are degenerate.
    const bool degenerate = !(area > 1e-30);
    s.flags = degenerate ? (s.flags | POSE_TRIANGLE_DEGENERATE) : (s.flags & ~uint(POSE_TRIANGLE_DEGENERATE));
    s.areaWorld = degenerate ? 0.0 : area;
    const bool textured = (s.flags & 1u) != 0u;
    s.sizeUv = degenerate || !textured ? 0.0 : area / max(s.texelCount, 1.0);
    s.texPerWorld = degenerate || !textured ? 0.0 : s.areaTexture / area;
    triangleStats[t] = s;
}
