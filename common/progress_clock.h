// When a long stage should print its next progress line: at most one line per interval,
// the first one interval after the start, so fast stages print none.
#pragma once

#include <chrono>

namespace lfd {

class ProgressClock {
public:
    explicit ProgressClock(double intervalSeconds)
        : interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(intervalSeconds))),
          next_(Clock::now() + interval_)
    {
    }

    // True at most once per interval; the caller prints a line when it is.
    bool due()
    {
        const Clock::time_point now = Clock::now();
        if (now < next_)
            return false;
        next_ = now + interval_;
        return true;
    }

private:
    using Clock = std::chrono::steady_clock;
    Clock::duration interval_;
    Clock::time_point next_;
};

} // namespace lfd
