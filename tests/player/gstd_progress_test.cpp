// gstd's progress text (issue 42): durations, the estimate of what remains, the plan line,
// and when a line is printed (first after a few seconds, then per tenth of the work or
// after a minute, never for the last batch or a frame done within the first interval).
#include "gstd_progress.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

namespace lfd::test {
namespace {

using player::GstdProgress;
using player::GstdProgressThrottle;

GstdProgress at(uint32_t done, uint32_t total = 192, uint32_t batchesDone = 0, uint32_t batches = 10)
{
    return {done, total, batchesDone, batches, 1920, 1440, true};
}

TEST(GstdProgress, DurationsGrowCoarser)
{
    EXPECT_EQ(player::formatDuration(0.0), "0.0 s");
    EXPECT_EQ(player::formatDuration(0.44), "0.4 s");
    EXPECT_EQ(player::formatDuration(9.9), "9.9 s");
    EXPECT_EQ(player::formatDuration(42.3), "42 s");
    EXPECT_EQ(player::formatDuration(59.4), "59 s");
    EXPECT_EQ(player::formatDuration(60.0), "1 min 00 s");
    EXPECT_EQ(player::formatDuration(351.0), "5 min 51 s");
    EXPECT_EQ(player::formatDuration(3599.0), "59 min 59 s");
    EXPECT_EQ(player::formatDuration(3600.0), "1 h 00 min");
    EXPECT_EQ(player::formatDuration(3840.0), "1 h 04 min");
    EXPECT_EQ(player::formatDuration(-1.0), "?");
    EXPECT_EQ(player::formatDuration(std::numeric_limits<double>::infinity()), "?");
}

TEST(GstdProgress, EstimateIsTheRateSoFar)
{
    EXPECT_FALSE(player::remainingSeconds(at(0), 10.0)) << "nothing done: no estimate";
    EXPECT_FALSE(player::remainingSeconds(at(10), 0.0)) << "no time elapsed: no estimate";
    EXPECT_DOUBLE_EQ(*player::remainingSeconds(at(48), 30.0), 90.0); // a quarter in 30 s: 90 s left
    EXPECT_DOUBLE_EQ(*player::remainingSeconds(at(192), 120.0), 0.0);
}

TEST(GstdProgress, LinesNameTheWorkTheTimeAndTheEstimate)
{
    EXPECT_EQ(player::formatGstdProgress(at(96, 192, 5, 10), 62.0),
              "96/192 sub-views (5/10 batches), 1 min 02 s elapsed, about 1 min 02 s left");
    EXPECT_EQ(player::formatGstdProgress(at(0, 192, 0, 10), 0.0), "0/192 sub-views (0/10 batches), 0.0 s elapsed");
    EXPECT_EQ(player::formatGstdPlan(at(0, 192, 0, 10)), "gstd (panel model): 192 sub-views of 1920x1440 in 10 batches");
    GstdProgress views{0, 96, 0, 48, 384, 288, false};
    EXPECT_EQ(player::formatGstdPlan(views), "gstd (views model): 96 sub-views of 384x288 in 48 batches");
    views.batches = 1;
    EXPECT_EQ(player::formatGstdPlan(views), "gstd (views model): 96 sub-views of 384x288 in 1 batch");
}

TEST(GstdProgress, ThrottlePrintsFirstAfterTheIntervalThenPerTenth)
{
    GstdProgressThrottle throttle(5.0, 60.0);
    EXPECT_FALSE(throttle.shouldPrint(at(0), 0.0)) << "the plan is not a progress line";
    EXPECT_FALSE(throttle.shouldPrint(at(2), 1.0)) << "too soon";
    EXPECT_TRUE(throttle.shouldPrint(at(4), 5.5)) << "the first line carries the first estimate";
    EXPECT_FALSE(throttle.shouldPrint(at(8), 11.0)) << "no new tenth yet (8/192)";
    EXPECT_TRUE(throttle.shouldPrint(at(20), 13.0)) << "a tenth done, 5 s after the last line";
    EXPECT_FALSE(throttle.shouldPrint(at(60), 14.0)) << "three tenths, but only 1 s after the last line";
    EXPECT_TRUE(throttle.shouldPrint(at(60), 18.5));
    EXPECT_FALSE(throttle.shouldPrint(at(61), 70.0)) << "same tenth, under a minute";
    EXPECT_TRUE(throttle.shouldPrint(at(62), 79.0)) << "a minute without a line";
    EXPECT_FALSE(throttle.shouldPrint(at(192), 500.0)) << "the last batch: the caller says it finished";
}

TEST(GstdProgress, AShortFramePrintsNothing)
{
    GstdProgressThrottle throttle(5.0, 60.0);
    for (uint32_t done = 0; done <= 192; done += 16)
        EXPECT_FALSE(throttle.shouldPrint(at(done), done * 4.0 / 192)) << done;
}

TEST(GstdProgress, PrinterWritesThePlanWithTheHint)
{
    std::ostringstream out;
    const player::GstdProgressCallback print = player::gstdProgressPrinter(out, "lfd-bench: car ", "try mvr");
    print(at(0, 192, 0, 10));
    print(at(19, 192, 1, 10)); // within the first 5 s of this test: no line
    EXPECT_EQ(out.str(), "lfd-bench: car reference: gstd (panel model): 192 sub-views of 1920x1440 in 10 batches; "
                         "try mvr\n");
}

} // namespace
} // namespace lfd::test
