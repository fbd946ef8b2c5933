#version 450 core
// LFDPR: turns the point counter into view-generation dispatch arguments on the GPU
// (glDispatchComputeIndirect), so the CPU never waits for the point count. Groups of
// LFDPR_GROUP_SIZE points, spread over y when x would exceed the guaranteed 65535 limit.
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"

layout(local_size_x = 1) in;

void main()
{
    uint points = min(counters.pointCount, u_lfd.counts.y);
    uint groups = (points + uint(LFDPR_GROUP_SIZE) - 1u) / uint(LFDPR_GROUP_SIZE);
    uint x = min(groups, 65535u);
    counters.dispatchX = max(x, 1u);
    counters.dispatchY = x == 0u ? 1u : (groups + x - 1u) / x;
    counters.dispatchZ = 1u;
}
