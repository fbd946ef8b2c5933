// parallelFor: a shared counter hands out items in order; see parallel.h for the contract.
#include "parallel.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace lfd {

unsigned resolveThreads(unsigned requested)
{
    return requested > 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

ThreadBudget::ThreadBudget(unsigned threads) : size_(resolveThreads(threads)), spare_(size_ - 1) {}

unsigned ThreadBudget::take(unsigned wanted)
{
    unsigned spare = spare_.load();
    unsigned got = 0;
    do {
        got = std::min(spare, wanted);
        if (got == 0)
            return 0;
    } while (!spare_.compare_exchange_weak(spare, spare - got));
    return got;
}

void ThreadBudget::give(unsigned count) { spare_ += count; }

void parallelFor(size_t count, unsigned threads, const std::function<void(size_t)>& body)
{
    ThreadBudget budget(threads);
    parallelFor(count, budget, body);
}

void parallelFor(size_t count, ThreadBudget& threads, const std::function<void(size_t)>& body)
{
    const unsigned helpers =
        count > 1 ? threads.take(unsigned(std::min<size_t>(count - 1, std::numeric_limits<unsigned>::max()))) : 0;
    if (helpers == 0) {
        for (size_t i = 0; i < count; ++i)
            body(i);
        return;
    }

    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex errorMutex;
    size_t errorItem = std::numeric_limits<size_t>::max();
    std::exception_ptr error;

    auto work = [&] {
        while (!failed.load(std::memory_order_relaxed)) {
            const size_t i = next.fetch_add(1);
            if (i >= count)
                return;
            try {
                body(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(errorMutex);
                if (i < errorItem) {
                    errorItem = i;
                    error = std::current_exception();
                }
                failed = true;
            }
        }
    };

    std::vector<std::thread> pool;
    try {
        for (unsigned t = 0; t < helpers; ++t)
            pool.emplace_back([&] {
                work();
                threads.give(1); // no item left here: a nested loop elsewhere may use it
            });
    } catch (...) {
        // note: a thread that could not start takes no item; the started ones (and this
        // one) drain the counter, so every item still runs.
        threads.give(helpers - unsigned(pool.size()));
    }
    work();
    for (std::thread& thread : pool)
        thread.join();
    if (error)
        std::rethrow_exception(error);
}

size_t bandCount(size_t count, size_t bandSize)
{
    bandSize = std::max<size_t>(bandSize, 1);
    return (count + bandSize - 1) / bandSize;
}

void forEachBand(size_t count, size_t bandSize, const std::function<void(size_t index, size_t begin, size_t end)>& band)
{
    bandSize = std::max<size_t>(bandSize, 1);
    parallelFor(bandCount(count, bandSize), 0,
                [&](size_t i) { band(i, i * bandSize, std::min(count, (i + 1) * bandSize)); });
}

} // namespace lfd
