// The direct subpixel splat's writes (LFDPR_DIRECT, renderer lfdpr-direct;
// docs/player/direct-splat.md): lfdpr_visibility_splat.comp decides coverage, depth and
// record per view pixel exactly as for the views, and each sample it would write into view
// word (x, y, view) goes instead to every panel subpixel that shows that view pixel - whose
// phase selects `view` and whose nearest texel is (x, y), as the EIA's nearest mode reads it
// (eia_construct.comp). The inverse map is a table the CPU builds once per profile from the
// same fixed-point phase (lfdpr_direct_fanout.h): a range of subpixel indices per view word.
// Every subpixel thus receives exactly the writes its view word would, and its word ends
// equal to that view word (the same atomicMin on (key << 32 | record)), which is what makes
// direct-nearest equal the two-stage EIA byte for byte. View pixels no subpixel shows (more
// view pixels than subpixels, or none under a phase bin) have an empty range: skipped.
// Without 64-bit atomics (Mesa's llvmpipe) the words are a key and a record, as the views
// path's 32-bit words, but resolved in two passes every frame: atomicMin on the keys, then
// (LFDPR_INDEX_PASS) atomicMin on the records of the samples whose key is the minimum. The
// views path instead stores the record with a plain store and repairs raced pixels found
// by its shading; the direct path's shading has no such repair, and the index pass gives
// the 64-bit path's winner (the lowest record among the nearest) in every subpixel.
// Needs lfdpr_work_counters.glsl first.

layout(std430, binding = LFDPR_SSBO_DIRECT_OFFSETS) readonly buffer DirectOffsets {
    uint directOffsets[];
};
layout(std430, binding = LFDPR_SSBO_DIRECT_SUBPIXELS) readonly buffer DirectSubpixels {
    uint directSubpixels[];
};
#ifdef LFDPR_INT64
layout(std430, binding = LFDPR_SSBO_PANEL_WORDS) buffer PanelWords {
    uint64_t panelWords[];
};
#else
layout(std430, binding = LFDPR_SSBO_PANEL_WORDS) buffer PanelDepth {
    uint panelDepth[];
};
layout(std430, binding = LFDPR_SSBO_PANEL_INDEX) buffer PanelIndex {
    uint panelIndex[];
};
#endif

// The write of one subpixel's sample, with the views path's early-out: a plain read that
// is already nearer skips the atomic (words only decrease, so a stale read never skips a
// winner).
void lfdDirectWrite(uint subpixel, uint key, uint record)
{
#if defined(LFDPR_INT64)
    const uint64_t word = (uint64_t(key) << 32) | uint64_t(record);
    if (word < panelWords[subpixel]) {
        LFDPR_COUNT(atomics, 1u);
#ifdef LFDPR_COUNT_WORK
        LFDPR_COUNT(lowered, atomicMin(panelWords[subpixel], word) > word ? 1u : 0u);
#else
        atomicMin(panelWords[subpixel], word);
#endif
    }
#elif defined(LFDPR_INDEX_PASS)
    if (panelDepth[subpixel] == key)
        atomicMin(panelIndex[subpixel], record);
#else
    if (key < panelDepth[subpixel]) {
        LFDPR_COUNT(atomics, 1u);
#ifdef LFDPR_COUNT_WORK
        LFDPR_COUNT(lowered, atomicMin(panelDepth[subpixel], key) > key ? 1u : 0u);
#else
        atomicMin(panelDepth[subpixel], key);
#endif
    }
#endif
}

// One covered sample of view word `viewWord` (lfdViewWord order), written to every
// subpixel that shows that view pixel.
void lfdDirectFanOut(uint viewWord, uint key, uint record)
{
    const uint end = directOffsets[viewWord + 1u];
    for (uint i = directOffsets[viewWord]; i < end; ++i)
        lfdDirectWrite(directSubpixels[i], key, record);
}
