#version 450 core
// LFDPR shading, step 2 of 3: turn each shading group's entry count (groupDispatch[g].w,
// counted by lfdpr_shade_list.comp) into the indirect dispatch lfdpr_shade.comp runs for it:
// one workgroup per entry and view slice, LFDPR_SHADE_DISPATCH_WIDTH per row, so no
// dimension exceeds GL's limit.
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_work_shape.glsl"

layout(local_size_x = 64) in;

layout(location = LFDPR_LOC_SHADE_GROUPS) uniform uint u_groups;

layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;

void main()
{
    uint group = gl_GlobalInvocationID.x;
    if (group >= u_groups)
        return;
    uint tiles = groupDispatch[group].w;
    uint width = min(tiles, uint(LFDPR_SHADE_DISPATCH_WIDTH));
    uint rows = (tiles + LFDPR_SHADE_DISPATCH_WIDTH - 1u) / LFDPR_SHADE_DISPATCH_WIDTH;
    // z: the slices of each chunk's views (lfdpr_work_shape.glsl). An empty group
    // dispatches nothing (0 x 0 x 0 workgroups is a valid indirect dispatch).
    groupDispatch[group].xyz = uvec3(width, rows, tiles == 0u ? 0u : lfdShadeSlices(u_lfd.counts.x));
}
