#version 450 core
// LFDPR visibility pipeline, 32-bit path: the repair's dispatches, made on the GPU from the
// first shading pass's count of raced pixels (shadeCounters.repairCount), so the frame
// never reads the count back to decide (docs/player/lfdpr.md "Frames that never wait"). Each of the
// three indirect dispatches of LfdprVisibilityRepairGpu gets zero workgroups when it has nothing to
// do: without races the repair costs three empty dispatches.
//   indexPass: lfdpr_visibility_splat.comp LFDPR_INDEX_PASS over every point (as the splat);
//   listRepair: lfdpr_visibility_shade_list.comp LFDPR_REPAIR_LIST, one invocation per (repair-list
//     entry, group), when the repair list holds every raced pixel;
//   listAll: lfdpr_visibility_shade_list.comp over every (group, chunk) again, when it does not.
// One invocation.
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_shade_chunks.glsl"

layout(local_size_x = 1) in;

layout(location = LFDPR_LOC_SHADE_GROUPS) uniform uint u_groups;

layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) readonly buffer VisCounters {
    LfdprVisibilityCountersGpu vis;
};
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) readonly LFDPR_SHADE_WORK_BUFFER;
layout(std430, binding = LFDPR_SSBO_REPAIR) writeonly buffer Repair {
    LfdprVisibilityRepairGpu repair;
};

// Workgroups of 64 invocations covering `invocations`, LFDPR_SHADE_DISPATCH_WIDTH per row
// (lfdpr_visibility_shade_list.comp's (x, y) order); none for none.
uvec3 listGroups(uint invocations)
{
    uint groups = (invocations + 63u) / 64u;
    uint width = min(groups, uint(LFDPR_SHADE_DISPATCH_WIDTH));
    return groups == 0u ? uvec3(0u) : uvec3(width, (groups + width - 1u) / width, 1u);
}

void main()
{
    uint repairs = shadeCounters.repairCount;
    bool fromList = repairs <= shadeCounters.repairCapacity;
    uint entries = lfdShadeEntryCount(lfdShadeTiles(uvec2(u_lfd.viewSize.xy)), u_lfd.counts.x);
    uvec3 index = repairs > 0u ? uvec3(vis.splatGroupsX, vis.splatGroupsY, vis.splatGroupsZ) : uvec3(0u);
    repair.indexPass = uvec4(index, repairs);
    repair.listRepair = uvec4(repairs > 0u && fromList ? listGroups(repairs * u_groups) : uvec3(0u), 0u);
    repair.listAll = uvec4(repairs > 0u && !fromList ? listGroups(entries * u_groups) : uvec3(0u), 0u);
}
