// Reads of the visibility pipeline's per-view-pixel words (lfdViewWord order) by the
// shading pass: through buffer textures over the storage buffers the
// splat wrote (LFDPR_UNIT_VIEW_*), for the reason given in lfdpr_scene_access.glsl
// (llvmpipe loops over the SIMD lanes for a storage-buffer load at a per-pixel address;
// texelFetch is one vectorised gather). Writes still go to the storage buffers; every
// pass that reads here runs after a GL_TEXTURE_FETCH_BARRIER_BIT barrier on them.
// Needs lfdpr_bindings.glsl first.

#ifdef LFDPR_INT64
layout(binding = LFDPR_UNIT_VIEW_DEPTH) uniform usamplerBuffer t_viewWords; // RG32UI: record, key
#else
layout(binding = LFDPR_UNIT_VIEW_DEPTH) uniform usamplerBuffer t_viewDepth; // R32UI: depth key
layout(binding = LFDPR_UNIT_VIEW_INDEX) uniform usamplerBuffer t_viewIndex; // R32UI: the winner's record
#endif

// The depth key stored for this pixel (0xFFFFFFFF: no point covers it).
uint lfdPixelKey(uint pixel)
{
#ifdef LFDPR_INT64
    return texelFetch(t_viewWords, int(pixel)).y; // little-endian: the key is the high word
#else
    return texelFetch(t_viewDepth, int(pixel)).x;
#endif
}

// The triangle record of the point that won this pixel, or 0xFFFFFFFF.
uint lfdPixelWinner(uint pixel)
{
#ifdef LFDPR_INT64
    uvec2 word = texelFetch(t_viewWords, int(pixel)).xy;
    return word.y == 0xFFFFFFFFu ? 0xFFFFFFFFu : word.x;
#else
    // Both words start as all ones, and whenever the splat lowers a pixel's depth it also
    // writes a record there (the repair's reset is written again by the index pass before
    // anything reads it), so the record word alone tells a covered pixel.
    return texelFetch(t_viewIndex, int(pixel)).x;
#endif
}
