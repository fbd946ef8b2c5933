// Work counters of the visibility pipeline (docs/player/8k-panels.md "Work counters"):
// what the splat and the shading did in a frame, counted on the GPU into the
// LfdprVisibilityCountersGpu block's work* fields, which the renderer reads back frames
// later with the point count (gl::GpuReadback, no wait, no extra GL call). Compiled in only
// with LFDPR_COUNT_WORK (LfdprOptions::countWork, lfd-play / lfd-bench
// --lfdpr-work-counters); otherwise every macro below is empty and the programs are the
// ones without counters.
//
// Each invocation adds into private counts (no atomic per pixel); lfdWorkFlush, called
// once at the end of main in uniform control flow, sums them over the workgroup in shared
// memory and adds the sums with one atomic per counter and workgroup.
// Needs lfdpr_bindings.glsl first.

#ifdef LFDPR_COUNT_WORK
layout(std430, binding = LFDPR_SSBO_VIS_COUNTERS) buffer WorkCounters {
    LfdprVisibilityCountersGpu work;
};

struct LfdWorkCounts {
    uint culled, samples, atomics, lowered, shadings, culledCentres;
};
LfdWorkCounts lfdWork = LfdWorkCounts(0u, 0u, 0u, 0u, 0u, 0u); // this invocation's
shared uint lfdWorkShared[6];

#define LFDPR_COUNT(field, n) lfdWork.field += uint(n)

void lfdWorkFlush()
{
    if (gl_LocalInvocationIndex == 0u)
        for (int i = 0; i < 6; ++i)
            lfdWorkShared[i] = 0u;
    barrier();
    uint counts[6] = uint[6](lfdWork.culled, lfdWork.samples, lfdWork.atomics, lfdWork.lowered, lfdWork.shadings,
                            lfdWork.culledCentres);
    for (int i = 0; i < 6; ++i)
        if (counts[i] != 0u)
            atomicAdd(lfdWorkShared[i], counts[i]);
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        if (lfdWorkShared[0] != 0u)
            atomicAdd(work.workCulled, lfdWorkShared[0]);
        if (lfdWorkShared[1] != 0u)
            atomicAdd(work.workSamples, lfdWorkShared[1]);
        if (lfdWorkShared[2] != 0u)
            atomicAdd(work.workAtomics, lfdWorkShared[2]);
        if (lfdWorkShared[3] != 0u)
            atomicAdd(work.workLowered, lfdWorkShared[3]);
        if (lfdWorkShared[4] != 0u)
            atomicAdd(work.workShadings, lfdWorkShared[4]);
        if (lfdWorkShared[5] != 0u)
            atomicAdd(work.workCulledCentres, lfdWorkShared[5]);
    }
}
#else
#define LFDPR_COUNT(field, n)
void lfdWorkFlush() {}
#endif
