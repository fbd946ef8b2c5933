#version 450 core
// LFDPR shading, step 1 of 3 (the visibility pipeline): classify the view pixels. Each
// workgroup is one LFDPR_SHADE_TILE-square tile of one view. A pixel no point covers is
// marked shaded (the views were cleared to the background before); a covered pixel records the shading group of its point's
// material in LFDPR_SSBO_MATERIAL_IDS, and the first pixel of each group in the tile
// appends the tile to that group's list (a shared-memory bit set finds it), so the
// shading dispatches (lfdpr_shade.comp) visit only tiles with work for them.
//   u_pass 0 classifies every pixel; u_pass 2 (after the 32-bit path's repair) only the
//   pixels flagged LFDPR_PIXEL_REPAIR. LFDPR_REPAIR_LIST: the repair pass over only the
//   tiles lfdpr_shade.comp listed for its flagged pixels (one workgroup per entry; a tile
//   with several such pixels is listed, and visited, more than once - a later visit finds
//   them classified already, and a tile listed twice for a group is shaded twice alike).
// LFDPR_ONLY_GROUP g: every drawn pixel shades in group g (one textured material, or none),
// so a pixel needs only its coverage, not the chain point -> record -> draw -> material.
// This pass reads no triangle geometry and samples no texture: Mesa's llvmpipe runs every
// `if` under a lane mask, so a shader pays for all the code it contains whether a pixel
// needs it or not; classification is therefore a program of its own, and the costly
// shading runs only on the tiles listed here.
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#endif
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"

layout(local_size_x = LFDPR_SHADE_TILE, local_size_y = LFDPR_SHADE_TILE) in;

layout(location = LFDPR_LOC_PASS) uniform uint u_pass;

layout(std430, binding = LFDPR_SSBO_POINTS) readonly buffer Points {
    uvec2 points[];
};
layout(std430, binding = LFDPR_SSBO_RECORDS) readonly buffer Records {
    LfdprRecordGpu records[];
};
layout(std430, binding = LFDPR_SSBO_DRAWS) readonly buffer Draws {
    LfdprDrawGpu draws[];
};
layout(std430, binding = LFDPR_SSBO_MATERIAL_GROUPS) readonly buffer MaterialGroups {
    uint materialGroups[];
};
layout(std430, binding = LFDPR_SSBO_MATERIAL_IDS) buffer PixelStates {
    uint pixelStates[];
};
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;
#ifdef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewWords {
    uint64_t viewWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_VIEW_DEPTH) readonly buffer ViewDepth {
    uint viewDepth[];
};
layout(std430, binding = LFDPR_SSBO_VIEW_COLOR) readonly buffer ViewIndex {
    uint viewIndex[];
};
#endif

shared uint s_seen[LFDPR_MAX_SHADE_GROUPS / 32]; // groups already listed for this tile

// The point that won this pixel, or 0xFFFFFFFF.
uint winner(uint pixel)
{
#ifdef LFDPR_INT64
    uint64_t word = viewWords[pixel];
    return uint(word >> 32) == 0xFFFFFFFFu ? 0xFFFFFFFFu : uint(word & 0xFFFFFFFFul);
#else
    return viewDepth[pixel] == 0xFFFFFFFFu ? 0xFFFFFFFFu : viewIndex[pixel];
#endif
}

// Whether some point won this pixel (its depth word is not empty).
bool covered(uint pixel)
{
#ifdef LFDPR_INT64
    return uint(viewWords[pixel] >> 32) != 0xFFFFFFFFu;
#else
    return viewDepth[pixel] != 0xFFFFFFFFu;
#endif
}

void main()
{
    uint lane = gl_LocalInvocationIndex;
    if (lane < LFDPR_MAX_SHADE_GROUPS / 32)
        s_seen[lane] = 0u;
    barrier();

    uvec2 size = uvec2(u_lfd.viewSize.xy);
    uvec2 tiles = (size + uvec2(LFDPR_SHADE_TILE - 1)) / uvec2(LFDPR_SHADE_TILE);
#ifdef LFDPR_REPAIR_LIST
    uint listed = groupTiles[shadeCounters.repairBase + gl_WorkGroupID.x];
    uvec3 tileId = uvec3(listed / (tiles.x * tiles.y), listed % tiles.x, (listed / tiles.x) % tiles.y);
#else
    // Dispatched as (view, tile x, tile y): the views of one tile run one after another,
    // so the view-interleaved per-pixel words (lfdViewWord) they share stay in cache.
    uvec3 tileId = gl_WorkGroupID;
#endif
    uvec3 id = uvec3(tileId.yz * LFDPR_SHADE_TILE + gl_LocalInvocationID.xy, tileId.x); // x, GL row, view
    if (any(greaterThanEqual(id.xy, size)) || id.z >= u_lfd.counts.x)
        return;
    uint pixel = lfdViewWord(id.z, id.x, id.y, size.x, u_lfd.counts.x);
#ifdef LFDPR_REPAIR_LIST
    if (pixelStates[pixel] != LFDPR_PIXEL_REPAIR)
        return;
#else
    if (u_pass == 2u && pixelStates[pixel] != LFDPR_PIXEL_REPAIR)
        return;
#endif
#ifdef LFDPR_ONLY_GROUP
    if (!covered(pixel)) {
        pixelStates[pixel] = LFDPR_PIXEL_SHADED;
        return;
    }
    uint group = LFDPR_ONLY_GROUP;
#else
    uint index = winner(pixel);
    if (index == 0xFFFFFFFFu) {
        pixelStates[pixel] = LFDPR_PIXEL_SHADED;
        return;
    }
    uint group = materialGroups[draws[records[points[index].x].draw].material];
#endif
    pixelStates[pixel] = group;
    uint bit = 1u << (group & 31u);
    if ((atomicOr(s_seen[group >> 5], bit) & bit) == 0u) {
        // First pixel of this group in the tile: list the tile.
        uint tileCount = tiles.x * tiles.y * u_lfd.counts.x;
        uint tile = (id.z * tiles.y + tileId.z) * tiles.x + tileId.y;
        uint slot = atomicAdd(groupDispatch[group].w, 1u);
        groupTiles[group * tileCount + slot] = tile;
    }
}
