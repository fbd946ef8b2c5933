// The 32-bit path's repair list (LfdprVisibilityShadeCountersGpu, lfdpr_bindings.glsl): the
// tile chunks whose records must be written again by the index pass and shaded again. The
// shading lists the chunk of each pixel whose record lost a race
// (lfdpr_visibility_shade.comp); the splat lists a tied point's chunks when the tie queue is
// full (lfdpr_visibility_splat.comp queueTies). Needs LFDPR_SHADE_WORK_BUFFER declared
// writable first.

// Appends tile chunk `chunkIndex` (lfdShadeChunkIndex) to the list. Past its capacity the
// entry is dropped but still counted: a count above the capacity makes the repair shade
// the whole frame again (lfdpr_visibility_repair_dispatch.comp).
void lfdListRepair(uint chunkIndex)
{
    uint entry = atomicAdd(shadeCounters.repairCount, 1u);
    if (entry < shadeCounters.repairCapacity)
        groupTiles[shadeCounters.repairBase + entry] = chunkIndex;
}
