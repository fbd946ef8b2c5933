// TexturePrefetcher (baker/texture/texture_prefetch.h): textures come out in order and intact,
// are baked ahead on spare threads only, within the memory limit, and a failed bake is
// reported when its texture is taken.
#include "texture_prefetch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace lfd::bake {
namespace {

// Records how many bakes ran at once and on which threads.
struct BakeLog {
    std::atomic<int> running{0}, mostRunning{0};
    std::atomic<int> onCaller{0};
    std::thread::id caller = std::this_thread::get_id();

    Texture bake(uint32_t i)
    {
        const int now = ++running;
        for (int seen = mostRunning.load(); now > seen && !mostRunning.compare_exchange_weak(seen, now);) {
        }
        if (std::this_thread::get_id() == caller)
            ++onCaller;
        std::this_thread::sleep_for(std::chrono::milliseconds(5 + 7 * (i % 3)));
        Texture t;
        t.name = "texture " + std::to_string(i);
        t.width = i + 1;
        t.texels.assign(16, uint8_t(i));
        --running;
        return t;
    }
};

TEST(TexturePrefetch, TexturesComeOutInOrderForAnyThreadCount)
{
    for (unsigned threads : {1u, 2u, 4u}) {
        BakeLog log;
        ThreadBudget budget(threads);
        TexturePrefetcher prefetcher([&](uint32_t i) { return log.bake(i); }, std::vector<uint64_t>(9, 100), budget,
                                     1000);
        for (uint32_t i = 0; i < 9; ++i) {
            const Texture t = prefetcher.take(i);
            EXPECT_EQ(t.name, "texture " + std::to_string(i));
            EXPECT_EQ(t.width, i + 1);
            EXPECT_EQ(t.texels, std::vector<uint8_t>(16, uint8_t(i)));
        }
        if (threads == 1) {
            EXPECT_EQ(log.mostRunning.load(), 1);
            EXPECT_EQ(log.onCaller.load(), 9) << "one thread: every texture is baked by the caller";
        } else {
            EXPECT_GE(log.mostRunning.load(), 2) << threads << " threads: textures must be baked ahead";
            EXPECT_LE(log.mostRunning.load(), int(threads));
        }
        EXPECT_EQ(budget.take(100), threads - 1) << "every thread given back";
    }
}

TEST(TexturePrefetch, HeldTexturesStayWithinTheMemoryLimit)
{
    // 700 + 400 is over the limit: the 400 waits until the 700 is dropped; the 1500
    // alone is over it and is baked alone.
    const std::vector<uint64_t> bytes = {300, 700, 400, 200, 100, 1500, 300, 300};
    BakeLog log;
    ThreadBudget budget(4);
    TexturePrefetcher prefetcher([&](uint32_t i) { return log.bake(i); }, bytes, budget, 1000);
    for (uint32_t i = 0; i < bytes.size(); ++i)
        EXPECT_EQ(prefetcher.take(i).width, i + 1);
    EXPECT_LE(prefetcher.peakHeldBytes(), 1500u);
    EXPECT_GE(prefetcher.peakHeldBytes(), 1000u) << "something must have been baked ahead";
}

TEST(TexturePrefetch, TinyLimitMeansOneTextureAtATime)
{
    BakeLog log;
    ThreadBudget budget(4);
    TexturePrefetcher prefetcher([&](uint32_t i) { return log.bake(i); }, std::vector<uint64_t>(5, 100), budget, 150);
    for (uint32_t i = 0; i < 5; ++i)
        prefetcher.take(i);
    EXPECT_EQ(log.mostRunning.load(), 1);
    EXPECT_EQ(prefetcher.peakHeldBytes(), 100u);
}

TEST(TexturePrefetch, AFailedBakeIsReportedWhenItsTextureIsTaken)
{
    for (unsigned threads : {1u, 3u}) {
        ThreadBudget budget(threads);
        TexturePrefetcher prefetcher(
            [](uint32_t i) {
                if (i == 2)
                    throw std::runtime_error("texture 2 is broken");
                Texture t;
                t.width = i + 1;
                return t;
            },
            std::vector<uint64_t>(5, 10), budget, 1000);
        EXPECT_EQ(prefetcher.take(0).width, 1u);
        EXPECT_EQ(prefetcher.take(1).width, 2u);
        try {
            prefetcher.take(2);
            ADD_FAILURE() << "texture 2 must throw";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "texture 2 is broken");
        }
        // The writer gives up here; the destructor waits for textures 3 and 4.
    }
}

} // namespace
} // namespace lfd::bake
