// Quilt videos as input (lfd-play --quilt-in clip.mp4, docs/player/quilts.md "Quilt videos"): the
// streaming decoder (frame count, rate, rewinding), the headless round trip through the real
// executable - an animation exported with --quilt-video and played back gives the direct render's
// EIAs within the codec's error - and bad videos failing in one line.
#include "player_cli_fixture.h"
#include "tool_run.h"

#include "image_metrics.h"
#include "quilt_video.h"
#include "quilt_video_reader.h"


#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

// The codec's error the round trip allows: H.264 at CRF 15 in 4:2:0 (quilt_video.cpp),
// measured on the interleaved EIA (docs/player/quilts.md "Quilt videos" gives the measured values).
constexpr double kMinEiaPsnrDb = 35.0;

// stderr only (stdout names the GPU), so a failure's one line can be counted.
RunResult runPlayStderr(const std::string& args)
{
    return run("(" + quoted(kPlay) + " " + args + " 2>&1 1>/dev/null)");
}

std::string numbered(const std::string& stem, uint32_t frame)
{
    char name[64];
    std::snprintf(name, sizeof(name), "%s_%04u.png", stem.c_str(), frame);
    return name;
}

class QuiltVideoTest : public PlayerCliTest {
protected:
    QuiltVideoTest() : PlayerCliTest("quilt_video_", "video-small") {}
    // Renders 3 frames of the turning scene (12 views of 96x72: a 4x3 quilt), their EIAs as
    // direct_000K.png and the quilts as a video; returns the video (empty without ffmpeg).
    fs::path exportVideo()
    {
        if (player::findOnPath("ffmpeg").empty())
            return {};
        const RunResult r = run(quoted(kPlay) + " --headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                " --views 12 --view-size 96x72 --frames 3 --fps 4 --out " +
                                quoted(dir_ / "direct_%04d.png") + " --quilt-video " + quoted(dir_ / "clip.mp4"));
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return dir_ / "clip_qs4x3a1.78.mp4";
    }
};

TEST_F(QuiltVideoTest, ReaderCountsFramesAndRewinds)
{
    const fs::path video = exportVideo();
    if (video.empty())
        GTEST_SKIP() << "ffmpeg not installed: no quilt video to read";
    player::QuiltVideoReader reader(video);
    EXPECT_EQ(reader.frameCount(), 3u);
    EXPECT_DOUBLE_EQ(reader.framesPerSecond(), 4.0);
    const metrics::Image first = reader.frame(0);
    EXPECT_EQ(first.width, 384u);
    EXPECT_EQ(first.height, 216u);
    const metrics::Image last = reader.frame(2);
    EXPECT_GT(metrics::rmse(first, last), 1.0) << "the turntable turns between frames";
    EXPECT_EQ(metrics::maxAbsDiff(reader.frame(0), first), 0) << "rewinding decodes the same frame";
    EXPECT_THROW(reader.frame(3), player::VideoError);
}

// The round trip: every frame played back from the video is the direct render's
// EIA within the codec's error, frame K is not frame 0, and --quilt-frame K renders the
// same frame K alone.
TEST_F(QuiltVideoTest, PlaybackMatchesTheDirectRenderWithinTheCodecError)
{
    const fs::path video = exportVideo();
    if (video.empty())
        GTEST_SKIP() << "ffmpeg not installed: the round trip needs it to export the video";
    ASSERT_TRUE(fs::exists(video));
    const RunResult back = run(quoted(kPlay) + " --headless --quilt-in " + quoted(video) + " --display " +
                               quoted(profile_) + " --out " + quoted(dir_ / "back_%04d.png"));
    ASSERT_EQ(back.exitCode, 0) << back.out;
    EXPECT_NE(back.out.find("3 frame(s)"), std::string::npos) << "every frame of the video: " << back.out;
    for (uint32_t k = 0; k < 3; ++k) {
        const metrics::Image direct = metrics::readImage(dir_ / numbered("direct", k));
        const metrics::Image played = metrics::readImage(dir_ / numbered("back", k));
        ASSERT_EQ(direct.width, played.width);
        const double psnr = metrics::psnr(direct, played);
        std::printf("[ numbers  ] quilt video round trip, frame %u: EIA PSNR %.2f dB, RMSE %.3f, max difference %d\n",
                    k, psnr, metrics::rmse(direct, played), metrics::maxAbsDiff(direct, played));
        EXPECT_GE(psnr, kMinEiaPsnrDb) << "frame " << k;
    }
    const metrics::Image frame0 = metrics::readImage(dir_ / numbered("back", 0));
    const metrics::Image frame2 = metrics::readImage(dir_ / numbered("back", 2));
    EXPECT_GT(metrics::rmse(frame0, frame2), 1.0) << "an animation plays, not a still";

    const RunResult single = run(quoted(kPlay) + " --headless --quilt-in " + quoted(video) + " --display " +
                                 quoted(profile_) + " --quilt-frame 2 --out " + quoted(dir_ / "single.png"));
    ASSERT_EQ(single.exitCode, 0) << single.out;
    EXPECT_EQ(metrics::maxAbsDiff(metrics::readImage(dir_ / "single.png"), frame2), 0);

    const RunResult beyond = runPlayStderr("--headless --quilt-in " + quoted(video) + " --display " +
                                           quoted(profile_) + " --quilt-frame 3 --out " + quoted(dir_ / "no.png"));
    EXPECT_EQ(beyond.exitCode, 2);
    EXPECT_EQ(std::count(beyond.out.begin(), beyond.out.end(), '\n'), 1) << beyond.out;
    EXPECT_NE(beyond.out.find("has 3 frames"), std::string::npos) << beyond.out;
    EXPECT_FALSE(fs::exists(dir_ / "no.png"));
}

// A file that is no video, one cut off in its header and a missing one: one line naming the file,
// a non-zero status, nothing written.
TEST_F(QuiltVideoTest, UnreadableVideosFailInOneLine)
{
    std::ofstream(dir_ / "junk_qs4x3a1.78.mp4") << "this is not a video";
    std::vector<std::string> names = {"junk_qs4x3a1.78.mp4", "missing_qs4x3a1.78.mp4"};
    if (const fs::path video = exportVideo(); !video.empty()) {
        const std::string bytes = readBytes(video);
        std::ofstream(dir_ / "cut_qs4x3a1.78.mp4", std::ios::binary) << bytes.substr(0, 200);
        names.push_back("cut_qs4x3a1.78.mp4");
    }
    for (const std::string& name : names) {
        const RunResult r = runPlayStderr("--headless --quilt-in " + quoted(dir_ / name) + " --display " +
                                          quoted(profile_) + " --out " + quoted(dir_ / "eia.png"));
        EXPECT_NE(r.exitCode, 0) << name;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << name << ": " << r.out;
        EXPECT_NE(r.out.find(name), std::string::npos) << "names the file: " << r.out;
        EXPECT_FALSE(fs::exists(dir_ / "eia.png")) << name;
    }
}

} // namespace
} // namespace lfd::test
