// Bands handed out to threads through one atomic counter: a thread that finishes early
// takes the next band, so uneven bands (an image's busy half) do not leave cores idle.
#include "parallel_bands.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace lfd::metrics {

size_t bandCount(size_t count, size_t bandSize)
{
    bandSize = std::max<size_t>(bandSize, 1);
    return (count + bandSize - 1) / bandSize;
}

void forEachBand(size_t count, size_t bandSize, const std::function<void(size_t index, size_t begin, size_t end)>& band)
{
    bandSize = std::max<size_t>(bandSize, 1);
    const size_t bands = bandCount(count, bandSize);
    const size_t threads = std::min<size_t>(bands, std::max(1u, std::thread::hardware_concurrency()));
    auto run = [&](size_t i) { band(i, i * bandSize, std::min(count, (i + 1) * bandSize)); };
    if (threads <= 1) {
        for (size_t i = 0; i < bands; ++i)
            run(i);
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto work = [&] {
        for (size_t i = next++; i < bands; i = next++) {
            try {
                run(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure)
                    failure = std::current_exception();
                next = bands; // the other threads stop after their current band
            }
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (size_t t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& thread : pool)
        thread.join();
    if (failure)
        std::rethrow_exception(failure);
}

} // namespace lfd::metrics
