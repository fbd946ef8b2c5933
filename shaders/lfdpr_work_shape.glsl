// How the visibility pipeline's work is cut into invocations (docs/player/lfdpr.md "Work shaped for
// a GPU"): a compile-time variant every program of the pipeline gets alike, chosen from the driver
// (LfdprOptions::WorkShape; lfd-play --lfdpr-work). Both variants write the same views byte for
// byte (tested): they cut the same work differently.
//
// LFDPR_WORK_GPU (hardware GPUs): tens of thousands of short invocations. A GPU hides
// memory latency with many invocations in flight and runs an invocation's loop as long as
// its slowest lane, so no invocation loops over many views, pixels or cells:
//   * the splat runs one invocation per point and slice of LFDPR_SPLAT_VIEWS views;
//   * a point's cell spans at most LFDPR_MAX_SPLAT_PIXELS of the finest view pixel per
//     axis (a large splat becomes several points), so a splat invocation tests at most
//     about (LFDPR_MAX_SPLAT_PIXELS + 2)^2 pixels in each of its views;
//   * a triangle of more than LFDPR_LARGE_CELLS sampling cells is sampled by a workgroup;
//   * the shading runs one workgroup per tile chunk and slice of LFDPR_SHADE_VIEWS views.
// Otherwise (Mesa's llvmpipe, a CPU rasteriser): parallelism is the core count, an untaken
// branch costs the whole SIMD row and a loop iteration its busiest lane, so invocations
// amortise per-point setup over all views (camera-line coherence) and walk whole chunks.
// Needs lfdpr_bindings.glsl first.

#ifdef LFDPR_WORK_GPU
#define LFDPR_SPLAT_VIEWS 4
#define LFDPR_MAX_SPLAT_PIXELS 4.0
#define LFDPR_LARGE_CELLS 64
#define LFDPR_SHADE_VIEWS 8
#else
#define LFDPR_SPLAT_VIEWS LFDPR_VIEW_CHUNK
#define LFDPR_LARGE_CELLS 4096
#define LFDPR_SHADE_VIEWS LFDPR_VIEW_CHUNK
#endif

// Splat slices per point: runs of LFDPR_SPLAT_VIEWS views (each inside one view chunk of
// LFDPR_VIEW_CHUNK, since LFDPR_SPLAT_VIEWS divides it).
uint lfdSplatSlices(uint viewCount)
{
    return (viewCount + uint(LFDPR_SPLAT_VIEWS) - 1u) / uint(LFDPR_SPLAT_VIEWS);
}

// Shading slices per tile chunk: runs of LFDPR_SHADE_VIEWS views of its LFDPR_VIEW_CHUNK.
uint lfdShadeSlices(uint viewCount)
{
    return (min(viewCount, uint(LFDPR_VIEW_CHUNK)) + uint(LFDPR_SHADE_VIEWS) - 1u) / uint(LFDPR_SHADE_VIEWS);
}

// The views of shading slice `slice` as a two-word chunk view mask (every view when a
// slice is the whole chunk).
uvec2 lfdShadeSliceMask(uint slice)
{
#if LFDPR_SHADE_VIEWS >= LFDPR_VIEW_CHUNK
    return uvec2(0xFFFFFFFFu);
#else
    uint first = slice * uint(LFDPR_SHADE_VIEWS);
    uint bits = ((1u << uint(LFDPR_SHADE_VIEWS)) - 1u) << (first & 31u);
    return first < 32u ? uvec2(bits, 0u) : uvec2(0u, bits);
#endif
}

// The splat's workgroups: LFDPR_GROUP_SIZE consecutive points times every slice, spread
// over y when x would exceed the guaranteed 65535 (none for no points). Both x and y grow
// monotonically with `points`, which lets point generation keep them as atomic maxima.
uvec3 lfdSplatGroups(uint points, uint viewCount)
{
    uint groups = (points + uint(LFDPR_GROUP_SIZE) - 1u) / uint(LFDPR_GROUP_SIZE) * lfdSplatSlices(viewCount);
    return uvec3(min(groups, 65535u), (groups + 65534u) / 65535u, 1u);
}
