#version 450 core
// LFDPR shading, step 1 of 2 (the visibility pipeline): each shading group's list of tile
// chunks to shade. lfdpr_visibility_splat.comp marked, per group and tile chunk (one
// LFDPR_SHADE_TILE-square tile position over up to LFDPR_VIEW_CHUNK views), the views in
// which a point of the group wrote a pixel there (LFDPR_SSBO_CHUNK_MASKS); every marked
// chunk becomes one entry (chunk index, view mask) of the group's list, and
// lfdpr_visibility_shade.comp runs a workgroup per entry over the views of its mask.
// Why marks from the splat rather than a pass over the pixels: classifying every view pixel
// (the chain winner -> record -> draw -> material) cost 25-50 ms per frame on
// llvmpipe for the prototype's 8.3M view pixels; a point marks each tile chunk it touches
// once per run of views (a few atomics per point), and this pass reads one mask per group
// and chunk. A group may be listed where its points were then hidden; lfdpr_visibility_shade.comp
// checks each pixel's winner.
//   Pass 0: one invocation per (group, chunk). LFDPR_REPAIR_LIST: the 32-bit path's repair,
//   one invocation per (repair-list entry, group): the listed chunks again, with the same
//   masks (a chunk listed twice is shaded twice, to the same colours). The repair's
//   dispatches are indirect (lfdpr_visibility_repair_dispatch.comp).
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_shade_chunks.glsl"
#include "lfdpr_work_shape.glsl"

layout(local_size_x = 64) in;

layout(location = LFDPR_LOC_SHADE_GROUPS) uniform uint u_groups;
#ifdef LFDPR_REPAIR_LIST
layout(std430, binding = LFDPR_SSBO_REPAIR) readonly buffer Repair {
    LfdprVisibilityRepairGpu repair; // indexPass.w: entries in the repair list (lfdpr_visibility_repair_dispatch.comp)
};
#endif

layout(std430, binding = LFDPR_SSBO_CHUNK_MASKS) readonly buffer ChunkMasks {
    uint chunkMasks[];
};
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;

void main()
{
    uvec2 tiles = lfdShadeTiles(uvec2(u_lfd.viewSize.xy));
    uint entries = lfdShadeEntryCount(tiles, u_lfd.counts.x);
    uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * 64u) + gl_GlobalInvocationID.x;
#ifdef LFDPR_REPAIR_LIST
    if (i >= repair.indexPass.w * u_groups)
        return;
    uint group = i % u_groups;
    uint chunk = groupTiles[shadeCounters.repairBase + i / u_groups];
#else
    if (i >= entries * u_groups)
        return;
    uint group = i / entries;
    uint chunk = i % entries;
#endif
    uint word = lfdChunkMaskWord(group, chunk, entries);
    uvec2 mask = uvec2(chunkMasks[word], chunkMasks[word + 1u]);
    if (mask == uvec2(0u))
        return;
    // The entry, and the group's indirect dispatch kept covering every entry so far: one
    // workgroup per entry, LFDPR_SHADE_DISPATCH_WIDTH per row (monotone maxima, so the
    // order of the entries does not matter), times the view slices of a chunk
    // (lfdpr_work_shape.glsl), set by the first entry. The renderer cleared it to (0, 1, 0),
    // which dispatches nothing.
    uint slot = atomicAdd(groupDispatch[group].w, 1u);
    if (slot == 0u)
        groupDispatch[group].z = lfdShadeSlices(u_lfd.counts.x);
    atomicMax(groupDispatch[group].x, min(slot + 1u, uint(LFDPR_SHADE_DISPATCH_WIDTH)));
    atomicMax(groupDispatch[group].y, slot / uint(LFDPR_SHADE_DISPATCH_WIDTH) + 1u);
    uint base = (group * entries + slot) * uint(LFDPR_SHADE_ENTRY_WORDS);
    groupTiles[base] = chunk;
    groupTiles[base + 1u] = mask.x;
    groupTiles[base + 2u] = mask.y;
}
