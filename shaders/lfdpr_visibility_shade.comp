#version 450 core
// LFDPR shading, step 2 of 2 (the visibility pipeline): each view pixel that a point won
// in lfdpr_visibility_splat.comp is shaded once, as mvr shades a fragment - the same material
// function (material_shading.glsl), the point's triangle interpolated perspective-correctly
// at the pixel centre, and every texture fetched with textureGrad at the pixel's exact
// footprint in this view (analytic uv gradients: the pixel's neighbours on the triangle
// plane, as the rasteriser's derivatives), so grazing surfaces filter like mvr's. This
// replaces the paper's per-splat shading with tv_min / tv_max (multiview mipmapping),
// which the paper's pipeline keeps.
//
// One dispatch per shading group (lfdpr_visibility_shade_list.comp): a workgroup per listed tile chunk
// (one tile position over a run of views) and slice of its views (lfdpr_work_shape.glsl:
// the whole chunk on llvmpipe, LFDPR_SHADE_VIEWS on a GPU), each invocation finding the views of the
// chunk's mask in which its pixel is group u_group's and shading those (a textured group
// also checks the material, since groups are shared past LFDPR_MAX_SHADE_GROUPS). The program is compiled per set of
// textures (LFD_TEXTURE_MASK) and the scene's vertex streams (LFD_STREAMS, a mask of
// LFD_STREAM_*): the untextured group's program has no sampling code at all, and no
// program reads a stream the scene lacks (llvmpipe would run those loads under an off mask).
// On the 32-bit path, u_pass 0 first checks that the stored record belongs to the
// stored depth key; a pixel that fails gets no index, its tile chunk goes on the repair
// list, and after lfdpr_visibility_splat.comp's index pass the listed chunks are shaded again
// (u_pass 2).
#ifdef LFDPR_INT64
#extension GL_ARB_gpu_shader_int64 : require
#endif
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_work_shape.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "lfdpr_visibility_shade_pixel.glsl"
#include "lfdpr_pixel_access.glsl"
#include "lfdpr_shade_chunks.glsl"
#include "lfdpr_work_counters.glsl"

layout(local_size_x = LFDPR_SHADE_TILE, local_size_y = LFDPR_SHADE_TILE) in;

layout(binding = LFDPR_IMAGE_VIEWS, rgba8) uniform writeonly image2DArray u_views;
layout(location = LFDPR_LOC_PASS) uniform uint u_pass;
layout(location = LFDPR_LOC_SHADE_MATERIAL) uniform uint u_shadeMaterial;
layout(location = LFDPR_LOC_SHADE_GROUP) uniform uint u_group;
layout(std430, binding = LFDPR_SSBO_SHADE_WORK) LFDPR_SHADE_WORK_BUFFER;
#ifndef LFDPR_INT64
#include "lfdpr_repair_list.glsl"
layout(std430, binding = LFDPR_SSBO_VIEW_WINNER) writeonly buffer ViewIndex {
    uint viewIndex[];
};
#endif

// Whether view pixel `pixel`'s winning point belongs to the group being shaded (the chunk
// was listed for the group's points, which may be hidden here; decided from the draw,
// before any vertex is fetched); a shared group shades one material.
bool groupWinner(uint pixel, out LfdprVisibilityRecordGpu record)
{
    uint winner = lfdPixelWinner(pixel);
    if (winner == 0xFFFFFFFFu)
        return false; // background (the views were cleared to it)
    record = lfdRecord(winner);
    LfdprVisibilityDrawGpu draw = lfdDraw(record.draw);
    return draw.group == u_group && (u_group == 0u || draw.material == u_shadeMaterial);
}

// Shades view pixel `pixel` (xy of view `view`), whose winner's record is `record`
// (steps 3-4 of main).
void shadeViewPixel(uint view, uvec2 xy, uint pixel, LfdprVisibilityRecordGpu record, uint chunkTile)
{
    ViewTriangle t = viewTriangle(record, lfdDraw(record.draw), view);
    vec2 centre = vec2(xy) + 0.5;
    LfdViewTriangle vt = lfdViewTriangle(t.s0, t.s1, t.s2, t.invW);
    vec3 edges = lfdEdgeValues(vt, centre);
#ifndef LFDPR_INT64
    // Step 3 (32-bit path): the single splat pass stores depth by atomicMin and the index
    // by a plain store, so a racing point may have left its index under another's depth.
    if (u_pass == 0u && lfdPlaneDepthKey(vt, edges) != lfdPixelKey(pixel)) {
        viewIndex[pixel] = 0xFFFFFFFFu; // lfdpr_visibility_splat.comp LFDPR_INDEX_PASS sets it again
        lfdListRepair(chunkTile); // listed again (lfdpr_visibility_shade_list.comp)
        return;
    }
#endif

    // Step 4: shade. (A repair pass shades again the listed chunks, where a pixel shaded
    // already gets the same colour.)
    LFDPR_COUNT(shadings, 1u);
    imageStore(u_views, ivec3(xy, view), shadePixel(t, view, vt, edges));
}

// One invocation's work (main): its pixel of the workgroup's tile chunk entry `slot`.
void shadeEntry(uint slot)
{
    // Step 1: this workgroup's tile chunk and its views with pixels of the group, from
    // the group's list (lfdpr_visibility_shade_list.comp).
    uvec2 size = uvec2(u_lfd.viewSize.xy);
    uvec2 tiles = lfdShadeTiles(size);
    uint base = (u_group * lfdShadeEntryCount(tiles, u_lfd.counts.x) + slot) * uint(LFDPR_SHADE_ENTRY_WORDS);
    uint chunkTile = groupTiles[base];
    // This workgroup's views of the chunk: slice gl_WorkGroupID.z (lfdpr_work_shape.glsl).
    uvec2 mask = uvec2(groupTiles[base + 1u], groupTiles[base + 2u]) & lfdShadeSliceMask(gl_WorkGroupID.z);
    LfdShadeChunk c = lfdShadeChunk(chunkTile, tiles, u_lfd.counts.x);
    uvec2 xy = c.tile * LFDPR_SHADE_TILE + gl_LocalInvocationID.xy; // x, GL row
    if (!all(lessThan(xy, size)))
        mask = uvec2(0u);
    // Step 2: the views of the mask in which this pixel's winner is the group's (a cheap
    // walk: the winner, its record and draw). Step 3 then loops over those views alone,
    // each invocation its own count. Why: a tile is rarely all one group's in every view
    // (object and material edges, background), and llvmpipe runs the shading of a loop
    // iteration for all 8 invocations of a SIMD row under a mask, so looping over the
    // tile's views paid for every row in every view; a row now pays for as many views
    // as its busiest pixel has.
    uvec2 mine = uvec2(0u);
    for (uvec2 bits = mask; bits != uvec2(0u);) {
        uint v = lfdTakeChunkView(bits);
        LfdprVisibilityRecordGpu record;
        if (groupWinner(lfdViewWord(c.firstView + v, xy.x, xy.y, size.x, u_lfd.counts.x), record))
            mine[v >> 5] |= 1u << (v & 31u);
    }
    // Step 3: shade those views.
    for (uvec2 bits = mine; bits != uvec2(0u);) {
        uint view = c.firstView + lfdTakeChunkView(bits);
        uint pixel = lfdViewWord(view, xy.x, xy.y, size.x, u_lfd.counts.x);
        // The winner again (step 2 found it is the group's; nothing changed it since).
        shadeViewPixel(view, xy, pixel, lfdRecord(lfdPixelWinner(pixel)), chunkTile);
    }
}

void main()
{
    uint slot = gl_WorkGroupID.y * LFDPR_SHADE_DISPATCH_WIDTH + gl_WorkGroupID.x;
    if (slot < groupDispatch[u_group].w)
        shadeEntry(slot);
    lfdWorkFlush(); // uniform control flow: every invocation of the workgroup gets here
}
