// LFDPR's counter blocks through the generated structs (named fields, never array
// positions): LfdprPaperCountersGpu (the paper's pipeline, LfdprPaperCounters block) and
// LfdprVisibilityCountersGpu (the visibility pipeline). The renderers read them back frames later
// through gl::GpuReadback, never waiting for them.
#pragma once

#include "lfdpr_bindings_gpu.h"

#include <cstdint>
#include <deque>

namespace lfd::player {

using lfdpr_bindings::LfdprPaperCountersGpu;
using lfdpr_bindings::LfdprVisibilityCountersGpu;

// The point capacity each submitted frame ran with, kept until its counters come back
// (frames later): a count is judged against the capacity of its own frame, not the one
// the buffer has grown to since.
class LfdprFrameCapacities {
public:
    void submitted(uint64_t tag, uint32_t capacity) { frames_.push_back({tag, capacity}); }
    // The capacity frame `tag` ran with (`fallback` if it was never submitted); forgets it
    // and every older frame (their counters come back in order).
    uint32_t counted(uint64_t tag, uint32_t fallback)
    {
        uint32_t capacity = fallback;
        while (!frames_.empty() && frames_.front().tag <= tag) {
            if (frames_.front().tag == tag)
                capacity = frames_.front().capacity;
            frames_.pop_front();
        }
        return capacity;
    }

private:
    struct Frame {
        uint64_t tag;
        uint32_t capacity;
    };
    std::deque<Frame> frames_; // frames whose counters have not come back
};

} // namespace lfd::player
