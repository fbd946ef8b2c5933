// parallelFor and ThreadBudget (common/parallel.h): every item runs once, the error is the
// one a serial loop stops at whatever the thread count, nested loops share one budget.
#include "parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace lfd {
namespace {

TEST(Parallel, ResolveThreadsZeroMeansHardware)
{
    EXPECT_GE(resolveThreads(0), 1u);
    EXPECT_EQ(resolveThreads(1), 1u);
    EXPECT_EQ(resolveThreads(7), 7u);
}

TEST(Parallel, EveryItemRunsExactlyOnce)
{
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        for (size_t count : {size_t(0), size_t(1), size_t(2), size_t(1000)}) {
            std::vector<std::atomic<int>> runs(count);
            parallelFor(count, threads, [&](size_t i) { ++runs[i]; });
            for (size_t i = 0; i < count; ++i)
                EXPECT_EQ(runs[i].load(), 1) << "item " << i << " of " << count << ", " << threads << " threads";
        }
    }
}

TEST(Parallel, RethrowsTheLowestFailingItemForAnyThreadCount)
{
    // Items 300 and 700 fail; a serial loop stops at 300, so every thread count must report 300,
    // even when the thread that reaches 700 gets there first (item 300 is made slow).
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        std::string message;
        try {
            parallelFor(1000, threads, [](size_t i) {
                if (i == 300) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(20));
                    throw std::runtime_error("item 300");
                }
                if (i == 700)
                    throw std::runtime_error("item 700");
            });
        } catch (const std::runtime_error& e) {
            message = e.what();
        }
        EXPECT_EQ(message, "item 300") << threads << " threads";
    }
}

TEST(Parallel, ItemsBelowAFailureAllRun)
{
    for (unsigned threads : {2u, 4u}) {
        std::vector<std::atomic<int>> runs(200);
        EXPECT_THROW(parallelFor(200, threads,
                                 [&](size_t i) {
                                     ++runs[i];
                                     if (i == 150)
                                         throw std::runtime_error("stop");
                                 }),
                     std::runtime_error);
        for (size_t i = 0; i <= 150; ++i)
            EXPECT_EQ(runs[i].load(), 1) << "item " << i << ", " << threads << " threads";
    }
}

TEST(Parallel, NestedLoopsNeverRunMoreThreadsThanTheBudget)
{
    // An outer loop of uneven items, each with an inner loop on the same budget: the
    // threads busy at once never exceed the budget, and once the short outer items are
    // done the long one's inner loop gets the threads back.
    for (unsigned budgetThreads : {1u, 2u, 3u}) {
        ThreadBudget budget(budgetThreads);
        std::atomic<int> busy{0}, mostBusy{0};
        std::atomic<int> innerRuns{0};
        auto task = [&] {
            const int now = ++busy;
            for (int seen = mostBusy.load(); now > seen && !mostBusy.compare_exchange_weak(seen, now);) {
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            --busy;
        };
        parallelFor(6, budget, [&](size_t outer) {
            const size_t inner = outer == 0 ? 64 : 4;
            parallelFor(inner, budget, [&](size_t) {
                task();
                ++innerRuns;
            });
        });
        EXPECT_EQ(innerRuns.load(), 64 + 5 * 4);
        EXPECT_LE(mostBusy.load(), int(budgetThreads)) << budgetThreads << " threads";
        // Every thread came back to the budget.
        EXPECT_EQ(budget.take(100), budgetThreads - 1);
    }
}

} // namespace
} // namespace lfd
