// The one way the project's CPU code uses threads (issue 9, "Baker throughput"; the
// player's image work, issue 39).
//
// A result must not depend on the thread count: baking with --threads 1, 2 or 16 gives the
// same pack bytes, and a 2-core CI machine computes the bench's error columns a 16-core
// server does. So every parallel stage has the same shape: it cuts its work into items
// whose results do not depend on each other (a mesh group, a range of triangles, a band
// of texel or image rows, a texture), computes each item into its own slot, and the caller
// then combines the slots in item order, exactly as a serial loop would have. Threads only
// decide *when* an item is computed, never *what* it computes or where it lands.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace lfd {

// Threads a stage uses when asked for `requested`: 0 means one per hardware thread
// (std::thread::hardware_concurrency(), at least 1).
unsigned resolveThreads(unsigned requested);

// The threads one stage may run at once, shared by the loops nested in it. A loop starts
// helper threads only while the stage has spare ones, and a helper hands its thread back
// as soon as it finds no item left, so a loop inside a parallel loop gets the threads its
// siblings are done with, and the stage never runs more threads than its count.
class ThreadBudget {
public:
    explicit ThreadBudget(unsigned threads); // 0: one per hardware thread
    // The thread count it was made with (the caller's own thread included).
    unsigned size() const { return size_; }
    // Takes up to `wanted` spare threads (beyond the caller's own); returns how many.
    unsigned take(unsigned wanted);
    void give(unsigned count);

private:
    unsigned size_;
    std::atomic<unsigned> spare_;
};

// Calls body(i) once for every i in [0, count) on up to `threads` threads (0: one per
// hardware thread; the calling thread is one of them, so 1 runs the loop inline). Items
// are handed out in increasing order and each one that starts runs to its end. When bodies
// throw, items not yet handed out are skipped and, after every thread has stopped, the
// exception of the lowest item that threw is rethrown: every item below it had been
// handed out before it and so ran, hence that is the error a serial loop would have
// stopped at, whatever the thread count. If a thread cannot be started, the threads that
// did start (at least the caller) take over its items.
void parallelFor(size_t count, unsigned threads, const std::function<void(size_t)>& body);
// The same with helper threads taken from `threads` (and given back as they finish).
void parallelFor(size_t count, ThreadBudget& threads, const std::function<void(size_t)>& body);

// The same loop over bands: [0, count) cut into bands of bandSize (the last one shorter),
// band(index, begin, end) called once per band on one thread per hardware thread. Each band
// writes only its own part of the output, or its own partial result the caller combines in
// band order.
void forEachBand(size_t count, size_t bandSize, const std::function<void(size_t index, size_t begin, size_t end)>& band);
// The number of bands forEachBand cuts [0, count) into: ceil(count / bandSize).
size_t bandCount(size_t count, size_t bandSize);

} // namespace lfd
