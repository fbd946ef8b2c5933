// forEachBand (common/parallel.h): every band exactly once with its own
// range, failures rethrown, and the metrics built on it independent of how the bands are
// spread over threads.
#include "image_metrics.h"
#include "parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace lfd::metrics {
namespace {

TEST(ParallelBands, EveryBandOnceWithItsOwnRange)
{
    struct Case {
        size_t count, bandSize;
    };
    for (const Case c : {Case{0, 4}, Case{1, 4}, Case{4, 4}, Case{5, 4}, Case{1000, 7}, Case{4096, 32}, Case{9, 0}}) {
        const size_t bands = bandCount(c.count, c.bandSize);
        std::vector<std::atomic<int>> visits(bands);
        std::vector<std::atomic<int>> covered(c.count);
        forEachBand(c.count, c.bandSize, [&](size_t index, size_t begin, size_t end) {
            const size_t size = c.bandSize == 0 ? 1 : c.bandSize;
            ASSERT_LT(index, bands);
            EXPECT_EQ(begin, index * size);
            EXPECT_EQ(end, std::min(c.count, begin + size));
            ++visits[index];
            for (size_t i = begin; i < end; ++i)
                ++covered[i];
        });
        for (size_t b = 0; b < bands; ++b)
            EXPECT_EQ(visits[b].load(), 1) << "count " << c.count << ", band " << b;
        for (size_t i = 0; i < c.count; ++i)
            EXPECT_EQ(covered[i].load(), 1) << "count " << c.count << ", item " << i;
    }
    EXPECT_EQ(bandCount(0, 8), 0u);
    EXPECT_EQ(bandCount(17, 8), 3u);
}

TEST(ParallelBands, UsesSeveralThreadsWhereThereAreCores)
{
    if (std::thread::hardware_concurrency() < 2)
        GTEST_SKIP() << "one hardware thread: the bands run on the caller's";
    std::mutex mutex;
    std::vector<std::thread::id> ids;
    forEachBand(64, 1, [&](size_t, size_t, size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        const std::lock_guard<std::mutex> lock(mutex);
        if (std::find(ids.begin(), ids.end(), std::this_thread::get_id()) == ids.end())
            ids.push_back(std::this_thread::get_id());
    });
    EXPECT_GE(ids.size(), 2u);
}

TEST(ParallelBands, AFailingBandIsRethrownAfterTheOthersStop)
{
    std::atomic<int> ran{0};
    EXPECT_THROW(forEachBand(100, 1,
                             [&](size_t index, size_t, size_t) {
                                 ++ran;
                                 if (index == 3)
                                     throw std::runtime_error("band 3");
                             }),
                 std::runtime_error);
    EXPECT_GE(ran.load(), 4);
}

// SSIM sums its windows per band and the bands in order, and FLIP's per-pixel steps and
// filters write disjoint rows: a panel-size pair (68 bands of 32 rows, 34 of 64 windows)
// gives the same result bit for bit on every run, however the threads took the bands.
TEST(ParallelBands, PanelSizeMetricsAreTheSameOnEveryRun)
{
    const int w = 960, h = 540;
    RgbImage a{w, h, std::vector<float>(size_t(w) * h * 3)}, b = a;
    uint32_t state = 12345u;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        state = state * 1664525u + 1013904223u;
        a.rgb[i] = float((i / 3 % size_t(w)) * 255 / size_t(w));
        b.rgb[i] = float(std::clamp(int(a.rgb[i]) + int(state >> 28) - 8, 0, 255));
    }
    const double ssim0 = ssim(a, b), flip0 = flip(a, b);
    EXPECT_GT(ssim0, 0.5);
    EXPECT_LT(ssim0, 1.0);
    EXPECT_GT(flip0, 0.0);
    for (int run = 0; run < 3; ++run) {
        EXPECT_EQ(ssim(a, b), ssim0);
        EXPECT_EQ(flip(a, b), flip0);
    }
}

} // namespace
} // namespace lfd::metrics
