#version 450 core
// LFDPR shading, step 1 of 3 (the visibility pipeline): classify the view pixels. Each
// workgroup is one LFDPR_SHADE_TILE-square tile position of every view of one view chunk
// (up to LFDPR_VIEW_CHUNK views; each invocation walks its pixel through those views). A
// pixel no point covers is marked shaded (the views were cleared to the background
// before); a covered pixel records the shading group of its point's material as its
// state (LFDPR_IMAGE_PIXEL_STATES) and sets its view's bit in that group's view mask (shared
// memory). At the end the workgroup appends one entry per group present - (tile chunk,
// view mask) - to that group's list, so each shading dispatch (lfdpr_shade.comp) visits
// only the tiles, and in them only the views, with work for it.
// Why a workgroup spans the views: llvmpipe pays a fixed cost per workgroup (measured:
// classifying the prototype's 48 views of 480x360 as one workgroup per 8x8 tile of one
// view - 129,600 workgroups - cost about 100 ms with an empty shader body on the 2-core
// machine); with the views inside, 48x fewer workgroups do the same work, and the 48
// words a pixel owns (lfdViewWord: views interleaved) are read in one cache-friendly run.
//   u_pass 0 classifies every pixel; u_pass 2 (after the 32-bit path's repair) only the
//   pixels flagged LFDPR_PIXEL_REPAIR. LFDPR_REPAIR_LIST: the repair pass over only the
//   tile chunks lfdpr_shade.comp listed for its flagged pixels (one workgroup per entry; a
//   chunk listed several times is visited several times - a later visit finds its pixels
//   classified already and lists nothing).
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

#include "lfdpr_math.glsl"
#define LFDPR_SCENE_TEXELS
#include "lfdpr_scene_access.glsl"
#include "lfdpr_pixel_access.glsl"
#include "lfdpr_shade_chunks.glsl"
layout(binding = LFDPR_UNIT_MATERIAL_GROUPS) uniform usamplerBuffer t_materialGroups;
layout(binding = LFDPR_IMAGE_PIXEL_STATES, r32ui) uniform writeonly uimageBuffer u_pixelStates;
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;

// Per shading group, the views of this chunk in which it holds a pixel of this tile.
shared uint s_views[LFDPR_MAX_SHADE_GROUPS * LFDPR_VIEW_MASK_WORDS];

const uint kWorkgroupSize = LFDPR_SHADE_TILE * LFDPR_SHADE_TILE;

// The shading group of one pixel, or LFDPR_PIXEL_SHADED if no point covers it.
uint pixelGroup(uint pixel)
{
#ifdef LFDPR_ONLY_GROUP
    return lfdPixelKey(pixel) == 0xFFFFFFFFu ? LFDPR_PIXEL_SHADED : LFDPR_ONLY_GROUP;
#else
    uint index = lfdPixelWinner(pixel);
    if (index == 0xFFFFFFFFu)
        return LFDPR_PIXEL_SHADED;
    return texelFetch(t_materialGroups, int(lfdDraw(lfdRecord(lfdPoint(index).x).draw).material)).x;
#endif
}

void main()
{
    uint lane = gl_LocalInvocationIndex;
    for (uint i = lane; i < uint(LFDPR_MAX_SHADE_GROUPS * LFDPR_VIEW_MASK_WORDS); i += kWorkgroupSize)
        s_views[i] = 0u;
    barrier();

    // Step 1: this workgroup's tile chunk (lfdShadeEntry order).
    uvec2 size = uvec2(u_lfd.viewSize.xy);
    uvec2 tiles = (size + uvec2(LFDPR_SHADE_TILE - 1)) / uvec2(LFDPR_SHADE_TILE);
#ifdef LFDPR_REPAIR_LIST
    uint chunkTile = groupTiles[shadeCounters.repairBase + gl_WorkGroupID.x];
#else
    uint chunkTile = (gl_WorkGroupID.z * tiles.y + gl_WorkGroupID.y) * tiles.x + gl_WorkGroupID.x;
#endif
    LfdShadeChunk c = lfdShadeChunk(chunkTile, tiles, u_lfd.counts.x);
    uvec2 xy = c.tile * LFDPR_SHADE_TILE + gl_LocalInvocationID.xy; // x, GL row

    // Step 2: the pixel in every view of the chunk.
    if (all(lessThan(xy, size))) {
        for (uint view = c.firstView; view < c.endView; ++view) {
            uint pixel = lfdViewWord(view, xy.x, xy.y, size.x, u_lfd.counts.x);
#ifdef LFDPR_REPAIR_LIST
            if (lfdPixelState(pixel) != LFDPR_PIXEL_REPAIR)
                continue;
#else
            if (u_pass == 2u && lfdPixelState(pixel) != LFDPR_PIXEL_REPAIR)
                continue;
#endif
            uint group = pixelGroup(pixel);
            imageStore(u_pixelStates, int(pixel), uvec4(group));
            if (group != LFDPR_PIXEL_SHADED) {
                uint v = view - c.firstView;
                atomicOr(s_views[group * uint(LFDPR_VIEW_MASK_WORDS) + (v >> 5)], 1u << (v & 31u));
            }
        }
    }
    barrier();

    // Step 3: one entry per group present in the chunk.
    uint entries = lfdShadeEntryCount(tiles, u_lfd.counts.x);
    for (uint group = lane; group < uint(LFDPR_MAX_SHADE_GROUPS); group += kWorkgroupSize) {
        uvec2 mask = uvec2(s_views[group * uint(LFDPR_VIEW_MASK_WORDS)], s_views[group * uint(LFDPR_VIEW_MASK_WORDS) + 1u]);
        if (mask == uvec2(0u))
            continue;
        uint slot = atomicAdd(groupDispatch[group].w, 1u);
        uint base = (group * entries + slot) * 3u;
        groupTiles[base] = chunkTile;
        groupTiles[base + 1u] = mask.x;
        groupTiles[base + 2u] = mask.y;
    }
}
