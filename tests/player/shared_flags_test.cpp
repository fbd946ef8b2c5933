// The flags lfd-play and lfd-bench share (issue 42: lfd-play took --no-turntable, lfd-bench
// refused it): every flag tool_flags.h declares is accepted by both executables, with a
// valid value, through parsing and flag validation up to the missing pack (exit 2, "no
// such pack file": the step after the flags); a flag only lfd-play has is refused by
// lfd-bench, so the check can fail. Then lfd-bench's --no-turntable is --turntable-period 0,
// and its untimed gstd reference says up front what it will cost.
#include "player_cli_fixture.h"
#include "tool_flags.h"

#include "tool_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;


// A valid value for each shared flag ("" for a switch). A flag added to tool_flags.h
// without an entry here fails the test, so the list cannot fall behind.
const std::map<std::string, std::string>& sampleValues()
{
    static const std::map<std::string, std::string> values{
        {"--display", std::string(LFD_SOURCE_DIR) + "/samples/profiles/prototype.json"},
        {"--view-size", "64x48"},
        {"--fps", "30"},
        {"--turntable-period", "0"},
        {"--gstd-factor", "2"},
        {"--gstd-model", "views"},
        {"--gstd-sub-views", "2"},
        {"--lfdpr-work", "cpu"},
        {"--lfdpr-aniso", "taps"},
        {"--aniso", "4"},
        {"--environment", "none"},
        {"--environment-rotation", "90"},
        {"--exposure", "0.5"},
        {"--tone-map", "none"},
        {"--gl-debug", ""},
        {"--no-turntable", ""},
        {"--views", "8"},
        {"--frames", "2"},
        {"--aa", "view-spatial"},
        {"--reconstruction", "spatial"},
        {"--ss", "2v"},
        {"--no-lfd-sampling", ""},
        {"--no-texture-splatting", ""},
        {"--no-mv-mipmapping", ""},
        {"--no-pixel-culling", ""},
        {"--no-margin-trim", ""},
        {"--lfdpr-work-counters", ""},
        {"--lfdpr-cell-scale", "1"},
        {"--atomics", "32"},
        {"--lfdpr-pipeline", "paper"},
    };
    return values;
}

std::string shellQuoted(const std::string& text) { return "'" + text + "'"; }

// Runs `tool` on a pack that does not exist with `args`.
RunResult runOnMissingPack(const fs::path& tool, const std::string& args)
{
    const std::string headless = tool.filename() == "lfd-play" ? " --headless" : "";
    return run(shellQuoted(tool.string()) + headless + " /nonexistent/shared-flags.lfdpack " + args);
}

TEST(SharedFlags, BothToolsAcceptEverySharedFlag)
{
    for (const fs::path& tool : {kPlay, kBenchTool})
        ASSERT_TRUE(fs::exists(tool)) << tool << " not built";
    const std::vector<std::string> names = player::sharedFlagNames();
    ASSERT_GE(names.size(), 20u);
    for (const char* expected : {"--no-turntable", "--turntable-period", "--views", "--frames", "--aa",
                                 "--reconstruction", "--ss", "--atomics", "--lfdpr-pipeline"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected << " is not shared";
    for (const std::string& name : names) {
        const auto sample = sampleValues().find(name);
        ASSERT_NE(sample, sampleValues().end()) << name << ": no sample value in this test";
        const std::string args = name + (sample->second.empty() ? "" : " " + shellQuoted(sample->second));
        for (const fs::path& tool : {kPlay, kBenchTool}) {
            const RunResult r = runOnMissingPack(tool, args);
            EXPECT_EQ(r.exitCode, 2) << tool.filename() << " " << args << ": " << r.out;
            EXPECT_NE(r.out.find("no such pack file"), std::string::npos)
                << tool.filename() << " refused " << args << ": " << r.out;
        }
    }
}

TEST(SharedFlags, AFlagOneToolLacksIsRefused)
{
    // --headless is lfd-play's own (lfd-bench is always headless): the check above would
    // see a refusal like this one.
    const RunResult r = run(shellQuoted(kBenchTool.string()) + " /nonexistent/shared-flags.lfdpack --headless");
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_EQ(r.out.find("no such pack file"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--headless"), std::string::npos) << r.out;
}

TEST(SharedFlags, OneValueForLfdPlayAListForLfdBench)
{
    const RunResult play = runOnMissingPack(kPlay, "--views 4,8");
    EXPECT_EQ(play.exitCode, 2);
    EXPECT_NE(play.out.find("--views: one view count, got '4,8'"), std::string::npos) << play.out;
    const RunResult playAa = runOnMissingPack(kPlay, "--aa none,view");
    EXPECT_NE(playAa.out.find("--aa: one value, got 'none,view'"), std::string::npos) << playAa.out;
    const RunResult bench = runOnMissingPack(kBenchTool, "--views 4,8 --aa none,view --ss 1,2v");
    EXPECT_NE(bench.out.find("no such pack file"), std::string::npos) << bench.out;
    for (const fs::path& tool : {kPlay, kBenchTool}) {
        const RunResult zero = runOnMissingPack(tool, "--views 0");
        EXPECT_NE(zero.out.find("--views: expected 1..2048, got '0'"), std::string::npos) << zero.out;
        const RunResult frames = runOnMissingPack(tool, "--frames 0");
        EXPECT_NE(frames.out.find("--frames: must be at least 1, got 0"), std::string::npos) << frames.out;
    }
}

class SharedFlagsBenchTest : public PlayerCliTest {
protected:
    SharedFlagsBenchTest() : PlayerCliTest("shared_flags_", "shared-flags-small") {}

    RunResult bench(const std::string& args)
    {
        return run(shellQuoted(kBenchTool.string()) + " " + shellQuoted(pack_.string()) + " --display " +
                   shellQuoted(profile_.string()) + " --views 4 --view-size 48x36 --frames 1 --warmup 0 " + args);
    }
};

nlohmann::json readJson(const fs::path& path)
{
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

TEST_F(SharedFlagsBenchTest, NoTurntableIsTurntablePeriodZero)
{
    const RunResult still = bench("--renderers mvr --reference mvr --lens-positions 1 --quiet --no-turntable --out " +
                                  shellQuoted((dir_ / "still").string()));
    ASSERT_EQ(still.exitCode, 0) << still.out;
    const RunResult zero = bench("--renderers mvr --reference mvr --lens-positions 1 --quiet --turntable-period 0 "
                                 "--out " + shellQuoted((dir_ / "zero").string()));
    ASSERT_EQ(zero.exitCode, 0) << zero.out;
    EXPECT_EQ(readJson(dir_ / "still" / "bench.json")["options"]["turntable_period"], 0.0);
    EXPECT_EQ(readBytes(dir_ / "still" / "mvr_eia.png"), readBytes(dir_ / "zero" / "mvr_eia.png"));
    // And not the default turntable: frame 0 has angle 0 either way, frame 30 does not.
    const RunResult turning = bench("--renderers mvr --reference mvr --lens-positions 1 --quiet --quality-frame 30 "
                                    "--out " + shellQuoted((dir_ / "turning").string()));
    const RunResult stillLater = bench("--renderers mvr --reference mvr --lens-positions 1 --quiet --quality-frame 30 "
                                       "--no-turntable --out " + shellQuoted((dir_ / "still30").string()));
    ASSERT_EQ(turning.exitCode, 0) << turning.out;
    ASSERT_EQ(stillLater.exitCode, 0) << stillLater.out;
    EXPECT_NE(readBytes(dir_ / "turning" / "mvr_eia.png"), readBytes(dir_ / "still30" / "mvr_eia.png"));
    EXPECT_EQ(readBytes(dir_ / "still30" / "mvr_eia.png"), readBytes(dir_ / "still" / "mvr_eia.png"));
}

TEST_F(SharedFlagsBenchTest, GstdReferenceSaysWhatItWillCostUnlessQuiet)
{
    const std::string args = "--renderers mvr --lens-positions 1 --gstd-factor 2 --no-gstd-cache";
    const RunResult r = bench(args);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    // 4 views x 4 sub-views (the panel model's default) of 96x72 (factor 2), in one batch.
    EXPECT_NE(r.out.find("reference: gstd (panel model): 16 sub-views of 96x72 in 1 batch; not cached "
                         "(--no-gstd-cache); faster: --reference mvr"),
              std::string::npos)
        << r.out;
    const RunResult quiet = bench(args + " --quiet");
    ASSERT_EQ(quiet.exitCode, 0) << quiet.out;
    EXPECT_EQ(quiet.out.find("reference: gstd"), std::string::npos) << quiet.out;
    // With the cache: the entry it will be stored in; from the cache: no plan at all.
    const std::string cached = "--renderers mvr --lens-positions 1 --gstd-factor 2 --gstd-cache " +
                               shellQuoted((dir_ / "cache").string());
    const RunResult first = bench(cached);
    ASSERT_EQ(first.exitCode, 0) << first.out;
    EXPECT_NE(first.out.find("; stored in the gstd cache " + (dir_ / "cache").string()), std::string::npos)
        << first.out;
    const RunResult second = bench(cached);
    ASSERT_EQ(second.exitCode, 0) << second.out;
    EXPECT_EQ(second.out.find("reference: gstd"), std::string::npos) << second.out;
    EXPECT_NE(second.out.find("quality frame from the gstd cache"), std::string::npos) << second.out;
}

} // namespace
} // namespace lfd::test
