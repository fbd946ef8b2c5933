#version 450 core
// LFDPR, the paper's pipeline: turns the point counter into the splat's dispatch arguments
// on the GPU (glDispatchComputeIndirect), so the CPU never waits for the point count.
// Groups of LFDPR_GROUP_SIZE points, spread over y when x would exceed the guaranteed
// 65535 limit. (The visibility pipeline's point generation keeps its splat's arguments
// as it reserves points: lfdpr_visibility_points.comp.)
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"

layout(local_size_x = 1) in;

// (x, y, z) workgroups covering `points` points; at least one in x and y, so a frame
// without points dispatches one empty group (the passes check the count).
uvec3 pointGroups(uint points)
{
    uint groups = (points + uint(LFDPR_GROUP_SIZE) - 1u) / uint(LFDPR_GROUP_SIZE);
    uint x = min(groups, 65535u);
    return uvec3(max(x, 1u), x == 0u ? 1u : (groups + x - 1u) / x, 1u);
}

void main()
{
    uvec3 g = pointGroups(min(counters.pointCount, u_lfd.counts.y));
    counters.dispatchX = g.x;
    counters.dispatchY = g.y;
    counters.dispatchZ = g.z;
}
