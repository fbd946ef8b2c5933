// Issue 42: an error about a flag names the flag and the value that was given, so a user
// sees what to fix without re-reading the command line. Each case runs the real tool on a
// pack that does not exist: the flags are checked first, so the flag's own message comes
// out (exit 2), not the missing pack's. And gstd's option checks name the value.
#include "player_cli_fixture.h"
#include "renderer_gstd.h"

#include "tool_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;


TEST(FlagMessages, NameTheFlagAndTheValue)
{
    const std::string missing = " /nonexistent/flag-messages.lfdpack ";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"--fps -1", "--fps: must be a positive number, got -1"},
        {"--fps 0", "--fps: must be a positive number, got 0"},
        {"--turntable-period -2.5", "--turntable-period: must be >= 0 seconds, got -2.5"},
        {"--exposure 99", "--exposure: must be a number of stops between -64 and 64, got 99"},
        {"--environment-rotation inf", "--environment-rotation: must be a finite number of degrees, got inf"},
        {"--frames 0", "--frames: must be at least 1, got 0"},
    };
    for (const fs::path& tool : {kPlay, kBenchTool}) {
        ASSERT_TRUE(fs::exists(tool)) << tool << " not built";
        const std::string prefix = "'" + tool.string() + "'" + (tool == kPlay ? " --headless" : "") + missing;
        for (const auto& [args, message] : cases) {
            const RunResult r = run(prefix + args);
            EXPECT_EQ(r.exitCode, 2) << tool.filename() << " " << args << ": " << r.out;
            EXPECT_NE(r.out.find(message), std::string::npos) << tool.filename() << " " << args << ": " << r.out;
        }
    }
    // lfd-play's own flags.
    const std::string play = "'" + kPlay.string() + "' --headless";
    const std::vector<std::pair<std::string, std::string>> playCases{
        {missing + "--preview-view-step 0", "--preview-view-step: must be at least 1, got 0"},
        {missing + "--preview-size-divisor 0", "--preview-size-divisor: must be at least 1, got 0"},
        {missing + "--preview-hold -1", "--preview-hold: must be >= 0 seconds, got -1"},
        {missing + "--viewer-out v.png --viewer-pos 99", "--viewer-pos: must be in [0, 48), got 99"},
        {" --quilt-in /nonexistent/quilts --slide-seconds 0", "--slide-seconds: must be a positive number, got 0"},
        // An image output it cannot write is refused before anything renders.
        {missing + "--out eia.xyz", "--out: 'eia.xyz': cannot write this image format '.xyz' (write .png, .jpg, .bmp or .tga)"},
        {missing + "--out eia_%04d", "--out: 'eia_%04d': has no image extension"},
        {missing + "--quilt q.GIF", "--quilt: 'q.GIF': cannot write this image format '.gif'"},
        {missing + "--viewer-out v.exr", "--viewer-out: 'v.exr': cannot write this image format '.exr'"},
        {missing + "--screenshot s.webp", "--screenshot: 's.webp': cannot write this image format '.webp'"},
    };
    for (const auto& [args, message] : playCases) {
        const RunResult r = run(play + args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.out;
        EXPECT_NE(r.out.find(message), std::string::npos) << args << ": " << r.out;
    }
}

TEST(FlagMessages, GstdOptionChecksNameTheValue)
{
    player::GstdOptions options;
    options.filterDiameter = -1.0;
    try {
        player::validateGstdOptions(options);
        FAIL() << "a negative filter diameter was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("filter diameter must be positive, got -1"), std::string::npos)
            << e.what();
    }
    options = {};
    options.maxAnisotropy = 0.5f;
    try {
        player::validateGstdOptions(options);
        FAIL() << "an anisotropy below 1 was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("anisotropy must be at least 1, got 0.5"), std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace lfd::test
