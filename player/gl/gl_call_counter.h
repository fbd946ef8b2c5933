// Counts the GL calls that decide how a frame runs on a real GPU - compute dispatches,
// draws, memory barriers, and every call that makes the CPU wait for the GPU - by swapping
// libepoxy's function pointers (every GL call in this project goes through them) for
// counting wrappers while a GlCallCounter is alive. lfd-bench reports the counts per frame
// of each configuration; the tests assert that no steady-state frame waits for the GPU.
//
// "Waits for the GPU" (GlCallCounts::syncs): glFinish; glClientWaitSync and glWaitSync;
// reading buffer or texture contents back (glGet[Named]BufferSubData, glReadPixels,
// glGetTex[ture]Image, glGetTextureSubImage, their compressed forms); mapping a buffer
// (glMap[Named]Buffer[Range]); and a query result asked for with GL_QUERY_RESULT (blocking
// until the GPU has written it; GL_QUERY_RESULT_AVAILABLE and GL_QUERY_RESULT_NO_WAIT do
// not wait). glGetError and state queries (glGetIntegerv, ...) are not counted: they read
// client-side state and do not wait for the GPU's work on any driver we run.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace lfd::gl {

struct GlCallCounts {
    uint64_t dispatches = 0; // glDispatchCompute, glDispatchComputeIndirect
    uint64_t draws = 0;      // glDraw*, glMultiDraw*
    uint64_t barriers = 0;   // glMemoryBarrier, glMemoryBarrierByRegion, glTextureBarrier
    uint64_t syncs = 0;      // calls that wait for the GPU (see above)
    std::map<std::string, uint64_t> syncCalls; // which ones, by GL name

    GlCallCounts operator-(const GlCallCounts& earlier) const;
};

// Installs the counting wrappers for its lifetime (one counter at a time: a second one
// throws std::logic_error). Needs no context; works across context creation.
class GlCallCounter {
public:
    GlCallCounter();
    ~GlCallCounter();
    GlCallCounter(const GlCallCounter&) = delete;
    GlCallCounter& operator=(const GlCallCounter&) = delete;

    // Totals since construction (or the last reset()).
    GlCallCounts counts() const;
    void reset();
};

} // namespace lfd::gl
