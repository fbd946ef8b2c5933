#version 450 core
// LFDPR: turns the point counter into the splat's dispatch arguments on the GPU
// (glDispatchComputeIndirect), so the CPU never waits for the point count. Groups of
// LFDPR_GROUP_SIZE points (the visibility pipeline: times its view slices), spread over y
// when x would exceed the guaranteed 65535 limit.
// Both pipelines: the paper's counter block (LfdprCounters), or with
// LFDPR_VISIBILITY_PIPELINE the visibility pipeline's (LfdprVisCountersGpu).
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"
#ifdef LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_work_shape.glsl"
#endif

layout(local_size_x = 1) in;

#ifdef LFDPR_VISIBILITY_PIPELINE
layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) buffer VisCounters {
    LfdprVisCountersGpu vis;
};
#endif

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
#ifdef LFDPR_VISIBILITY_PIPELINE
    // Every point in every slice of views (lfdpr_work_shape.glsl).
    uvec3 g = lfdSplatGroups(min(vis.pointCount, u_lfd.counts.y), u_lfd.counts.x);
    vis.splatGroupsX = g.x;
    vis.splatGroupsY = g.y;
    vis.splatGroupsZ = g.z;
#else
    uvec3 g = pointGroups(min(counters.pointCount, u_lfd.counts.y));
    counters.dispatchX = g.x;
    counters.dispatchY = g.y;
    counters.dispatchZ = g.z;
#endif
}
