// lfd-play (and lfd-bench) end to end: a small pack written with lfd::writePack, run
// headless through the real executable. Every image a tool writes is checked for content:
// against the headless render of the same frame in this process (the shared harness, from
// the same pack and profile) or, for the EIA, against the CPU reference interleaving of the
// written views - and never blank, so a black or background-only output fails even where
// the reference would be broken the same way. Stats keys; bad input gives one stderr line,
// a non-zero status and no output files.
#include "gl_test_support.h"
#include "player_cli_fixture.h"
#include "render_test_util.h"
#include "test_scenes.h"
#include "tool_run.h"

#include "eia_builder.h"
#include "frame_uniforms.h"
#include "gpu_environment.h"
#include "image_file.h"
#include "image_metrics.h"
#include "quilt.h"
#include "renderer_gstd.h"
#include "simulated_viewer.h"
#include "quilt_video.h"

#include "lfd/display_profile.h"
#include "lfd/pack.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <tuple>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

// A tool's exit status with its stdout and stderr apart (tool_run.h's run merges them).
struct ToolResult {
    int status = -1;
    std::string out, err;
};

// `env`: "NAME=value " assignments put before the command (e.g. a PATH without ffmpeg).
ToolResult runTool(const fs::path& tool, const fs::path& dir, const std::string& args, const std::string& env = "")
{
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string command = env + "'" + tool.string() + "' " + args + " > '" + out.string() + "' 2> '" +
                                err.string() + "'";
    ToolResult r;
    const int raw = std::system(command.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = readBytes(out);
    r.err = readBytes(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

ToolResult runPlay(const fs::path& dir, const std::string& args, const std::string& env = "")
{
    return runTool(kPlay, dir, args, env);
}

// Files in `dir` other than the inputs the test put there.
std::vector<std::string> outputsIn(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name != "scene.lfdpack" && name != "profile.json" && name != "corrupt.lfdpack" &&
            name != "bad_profile.json" && name != "not_an_hdr.hdr")
            names.push_back(fs::relative(e.path(), dir).string());
    }
    return names;
}

// lfd-play's defaults: frame k is at k / 60 s on a 10 s turntable.
constexpr double kFps = 60.0, kTurntablePeriod = 10.0;

// The frame lfd-play wrote for `frame`, rendered here from the same pack and profile.
RenderedFrame referenceFrame(const std::string& renderer, const fs::path& pack, const DisplayProfile& profile,
                             uint32_t frame)
{
    return renderFrame(renderer, readPack(pack), profile,
                       {.time = double(frame) / kFps,
                        .turntablePeriod = kTurntablePeriod,
                        .eia = true,
                        .lighting = toolDefaultLighting()});
}

std::vector<std::vector<uint8_t>> pixelsOf(const std::vector<metrics::Image>& images)
{
    std::vector<std::vector<uint8_t>> out;
    for (const metrics::Image& image : images)
        out.push_back(image.pixels);
    return out;
}

metrics::Image readView(const fs::path& dir, uint32_t view)
{
    char name[32];
    std::snprintf(name, sizeof(name), "view_%03u.png", view);
    return metrics::readImage(dir / name, 4);
}

// The checks can fail: a black image, a background-only one and one shifted by a pixel
// are each refused, by the same functions that pass the real outputs below.
TEST(CliOutputChecks, BlankOrWrongImagesFail)
{
    metrics::Image reference{64, 48, 4, std::vector<uint8_t>(64 * 48 * 4, 255)};
    for (uint32_t y = 0; y < 48; ++y)
        for (uint32_t x = 0; x < 64; ++x)
            for (uint32_t c = 0; c < 3; ++c)
                reference.pixels[(y * 64 + x) * 4 + c] = uint8_t((x * 4 + y * 3 + c * 50) % 256);
    EXPECT_EQ(imageMismatch(reference, reference, 0), "");
    metrics::Image black = reference, background = reference, shifted = reference;
    for (size_t i = 0; i < black.pixels.size(); i += 4) {
        std::fill_n(&black.pixels[i], 3, uint8_t(0));
        std::fill_n(&background.pixels[i], 3, uint8_t(std::lround(player::kBackground[0] * 255.0f)));
    }
    std::rotate(shifted.pixels.begin(), shifted.pixels.begin() + 4, shifted.pixels.end());
    EXPECT_NE(imageMismatch(black, reference, 1), "");
    EXPECT_NE(imageMismatch(background, reference, 1), "");
    EXPECT_NE(imageMismatch(shifted, reference, 1), "");
    // Blank on both sides (a renderer broken for the tool and the reference alike).
    EXPECT_NE(imageMismatch(black, black, 1), "");
    EXPECT_NE(imageMismatch(background, background, 1), "");
    EXPECT_NE(blankReason(background).find("(13, 13, 13)"), std::string::npos) << blankReason(background);
}

class CliTest : public PlayerCliTest {
protected:
    CliTest() : PlayerCliTest("cli_", "cli-small") {}
};

// HeadlessWritesEveryRequestedOutput's stats: the JSON's keys and values, each stage's
// summary over the 3 frames, and the CSV's rows.
void expectHeadlessStats(const fs::path& out)
{
    const nlohmann::json stats = nlohmann::json::parse(readBytes(out / "stats.json"));
    for (const char* key : {"renderer", "views", "view_width", "view_height", "frames", "gpu", "view_generation_ms",
                            "eia_ms", "total_ms", "stages", "view_buffer_bytes", "panel_width", "panel_height",
                            "profile", "pack", "triangles", "drawn_triangles"})
        EXPECT_TRUE(stats.contains(key)) << key;
    // cubeAndSphereScene draws each of its meshes once: 2 cubes of 12 + a 24x16 sphere.
    EXPECT_EQ(stats["triangles"].get<uint64_t>(), 2u * 12u + 2u * 24u * 16u);
    EXPECT_EQ(stats["drawn_triangles"].get<uint64_t>(), stats["triangles"].get<uint64_t>());
    EXPECT_EQ(stats["renderer"], "mvr");
    EXPECT_EQ(stats["views"], 4);
    EXPECT_EQ(stats["view_width"], 96);
    EXPECT_EQ(stats["frames"], 3);
    EXPECT_EQ(stats["panel_width"], 384);
    EXPECT_EQ(stats["profile"], "cli-small");
    EXPECT_EQ(stats["pack"], "scene.lfdpack");
    EXPECT_EQ(stats["view_buffer_bytes"], 4 * 96 * 72 * 8);
    for (const char* stage : {"view_generation", "eia", "total"}) {
        const double ms = stats[std::string(stage) + "_ms"];
        EXPECT_TRUE(std::isfinite(ms) && ms > 0.0) << stage << " " << ms;
        const nlohmann::json& s = stats["stages"][stage];
        EXPECT_EQ(s["samples"], 3) << stage;
        EXPECT_LE(double(s["min"]), double(s["median"]));
        EXPECT_LE(double(s["median"]), double(s["max"]));
    }
    EXPECT_GE(double(stats["total_ms"]), double(stats["view_generation_ms"]));
    // CSV: header + 3 frames x 3 stages.
    const std::string csv = readBytes(out / "stats.csv");
    EXPECT_EQ(csv.rfind("frame,stage,ms\n", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 3);
}

TEST_F(CliTest, HeadlessWritesEveryRequestedOutput)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const ToolResult r = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                          " --views 4 --view-size 96x72 --frames 3 --out " + quoted(out / "eia.png") +
                                          " --quilt " + quoted(out / "quilt.png") + " --views-out " + quoted(out / "views") +
                                          " --stats " + quoted(out / "stats.json") + " --viewer-out " +
                                          quoted(out / "viewer.png") + " --viewer-pos 1.5");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("OpenGL"), std::string::npos) << "start-up line names the GL driver: " << r.out;

    const metrics::Image eia = metrics::readImage(out / "eia.png", 4);
    EXPECT_EQ(eia.width, 384u);
    EXPECT_EQ(eia.height, 216u);
    // 4 views of 96x72 on a 16:9 panel: the quilt layout chooses its tiles; with --frames 3
    // (and no --frame) one numbered quilt per frame.
    fs::path quilt;
    size_t quilts = 0;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().filename().string().rfind("quilt_000", 0) == 0) {
            ++quilts;
            quilt = e.path();
        }
    EXPECT_EQ(quilts, 3u) << "quilt_0000_qs*.png .. quilt_0002_qs*.png";
    ASSERT_FALSE(quilt.empty()) << "no quilt_000?_qs*.png written";
    const metrics::Image quiltImage = metrics::readImage(quilt);
    EXPECT_EQ(quiltImage.width % 96, 0u);
    EXPECT_EQ(quiltImage.height % 72, 0u);
    EXPECT_GE((quiltImage.width / 96) * (quiltImage.height / 72), 4u);
    for (int v = 0; v < 4; ++v) {
        char name[32];
        std::snprintf(name, sizeof(name), "view_%03d.png", v);
        const metrics::Image view = metrics::readImage(out / "views" / name);
        EXPECT_EQ(view.width, 96u);
        EXPECT_EQ(view.height, 72u);
    }
    EXPECT_FALSE(fs::exists(out / "views" / "view_004.png"));
    const metrics::Image viewer = metrics::readImage(out / "viewer.png", 4);
    EXPECT_EQ(viewer.width, 96u);
    EXPECT_EQ(viewer.height, 72u);

    // Content: the last of 3 frames (time 2 / 60 s), rendered here from the same pack;
    // the same driver and code give the same bytes (1 level of slack for PNG round trips
    // elsewhere: none is expected here).
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 96, 72);
    const RenderedFrame reference = referenceFrame("mvr", pack_, profile, 2);
    std::vector<metrics::Image> views;
    for (uint32_t v = 0; v < 4; ++v) {
        views.push_back(readView(out / "views", v));
        EXPECT_EQ(imageMismatch(views[v], reference.views[v], 1), "") << "view " << v;
    }
    EXPECT_EQ(imageMismatch(eia, reference.eia, 1), "") << "EIA";
    const metrics::Image cpuEia{384, 216, 4, player::buildEiaCpu(profile, pixelsOf(views), 96, 72)};
    EXPECT_EQ(imageMismatch(eia, cpuEia, 0), "") << "EIA against the CPU interleaving of the written views";
    const player::QuiltLayout layout = player::chooseQuiltLayout(profile);
    const metrics::Image expectedQuilt{layout.width(), layout.height(), 4,
                                      player::assembleQuilt(layout, pixelsOf(reference.views))};
    EXPECT_EQ(imageMismatch(metrics::readImage(quilt, 4), expectedQuilt, 1), "") << "quilt";
    const metrics::Image expectedViewer{96, 72, 4, player::simulateViewer(profile, reference.eia.pixels, 1.5)};
    EXPECT_EQ(imageMismatch(viewer, expectedViewer, 1), "") << "simulated viewer";

    expectHeadlessStats(out);
}

TEST_F(CliTest, LayeredRendererAndExplicitFrame)
{
    if (!caps().layerFromVertexShader)
        LFD_SKIP_OR_FAIL("driver lacks GL_ARB_shader_viewport_layer_array");
    const fs::path a = dir_ / "a", b = dir_ / "b";
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 64x48";
    ASSERT_EQ(runPlay(dir_, common + " --renderer mvr --frames 1 --frame 30 --views-out " + quoted(a)).status, 0);
    const ToolResult r = runPlay(dir_, common + " --renderer mvr-layered --frames 2 --frame 30 --views-out " + quoted(b));
    ASSERT_EQ(r.status, 0) << r.err;
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 64, 48);
    const RenderedFrame frame30 = referenceFrame("mvr", pack_, profile, 30);
    for (uint32_t v = 0; v < 4; ++v) {
        EXPECT_EQ(imageMismatch(readView(a, v), frame30.views[v], 1), "") << "mvr, view " << v;
        EXPECT_EQ(imageMismatch(readView(b, v), frame30.views[v], 1), "") << "mvr-layered, view " << v;
    }
    // A different frame shows the turntable at another angle.
    const fs::path c = dir_ / "c";
    ASSERT_EQ(runPlay(dir_, common + " --frames 1 --views-out " + quoted(c)).status, 0);
    EXPECT_GT(metrics::rmse(metrics::readImage(a / "view_000.png"), metrics::readImage(c / "view_000.png")), 1.0);
}

TEST_F(CliTest, DefaultPrototypeProfileGivesAFullPanelEia)
{
    const fs::path eia = dir_ / "eia.png", views = dir_ / "views";
    const ToolResult r = runPlay(dir_, "--headless " + quoted(pack_) + " --views 8 --view-size 120x90 --out " + quoted(eia) +
                                          " --views-out " + quoted(views));
    ASSERT_EQ(r.status, 0) << r.err;
    const metrics::Image image = metrics::readImage(eia, 4);
    EXPECT_EQ(image.width, 3840u);
    EXPECT_EQ(image.height, 2160u);
    // Content: the prototype's interleaving of the views lfd-play wrote beside it.
    const DisplayProfile profile = withViews(prototypeDisplayProfile(), 8, 120, 90);
    std::vector<metrics::Image> written;
    for (uint32_t v = 0; v < 8; ++v)
        written.push_back(readView(views, v));
    const metrics::Image cpuEia{3840, 2160, 4, player::buildEiaCpu(profile, pixelsOf(written), 120, 90)};
    EXPECT_EQ(imageMismatch(image, cpuEia, 0), "");
}

// Each bad input: non-zero status, exactly one stderr line naming the culprit, no files.
// `--environment FILE.hdr`: a Radiance panorama lights the scene, exactly as the same
// file uploaded here does; its rotation and exposure flags change the views.
TEST_F(CliTest, EnvironmentFileLightsTheScene)
{
    // A 64 x 32 sky: a bright warm disc at the horizon to the +X side, a blue gradient above.
    metrics::HdrImage sky{64, 32, std::vector<float>(64 * 32 * 3)};
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            float* p = &sky.rgb[(size_t(y) * 64 + size_t(x)) * 3];
            const float up = 1.0f - float(y) / 31.0f;
            const bool sun = std::hypot(float(x) - 32.0f, float(y) - 16.0f) < 3.0f;
            p[0] = sun ? 20.0f : 0.1f + 0.2f * up;
            p[1] = sun ? 16.0f : 0.2f + 0.3f * up;
            p[2] = sun ? 10.0f : 0.4f + 0.6f * up;
        }
    const fs::path file = dir_ / "sky.hdr";
    metrics::writeHdrImage(file, sky);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 96x72";
    auto render = [&](const std::string& flags, const std::string& name) {
        const ToolResult r = runPlay(dir_, common + " " + flags + " --views-out " + quoted(dir_ / name));
        EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
        return readView(dir_ / name, 1);
    };
    const metrics::Image fromFile = render("--environment " + quoted(file), "sky");
    const metrics::Image neutral = render("", "neutral");
    const metrics::Image turned = render("--environment " + quoted(file) + " --environment-rotation 120", "turned");
    const metrics::Image brighter = render("--environment " + quoted(file) + " --exposure 1", "brighter");

    player::FrameLighting lighting = toolDefaultLighting();
    const std::shared_ptr<const player::GpuEnvironment> uploaded =
        player::uploadEnvironment(lighting::chooseEnvironment(file.string()));
    lighting.environment = uploaded.get();
    const RenderedFrame reference =
        renderFrame("mvr", readPack(pack_), tenthPrototypeProfile("cli-small", 4, 96, 72),
                    {.turntablePeriod = kTurntablePeriod, .lighting = lighting});
    EXPECT_EQ(imageMismatch(fromFile, reference.views[1], 1), "") << "lfd-play --environment against the upload here";
    const double vsNeutral = metrics::rmse(fromFile, neutral), vsTurned = metrics::rmse(fromFile, turned);
    double sumFile = 0.0, sumBright = 0.0;
    for (size_t i = 0; i < fromFile.pixels.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            sumFile += fromFile.pixels[i + size_t(c)];
            sumBright += brighter.pixels[i + size_t(c)];
        }
    std::printf("[ numbers  ] sky.hdr vs neutral RMSE %.1f, turned 120 deg RMSE %.1f, +1 EV: mean level %.1f -> %.1f\n",
                vsNeutral, vsTurned, sumFile / double(fromFile.pixels.size() / 4 * 3),
                sumBright / double(fromFile.pixels.size() / 4 * 3));
    EXPECT_GT(vsNeutral, 3.0);
    EXPECT_GT(vsTurned, 1.0);
    EXPECT_GT(sumBright, sumFile * 1.05);
}

TEST_F(CliTest, BadInputFailsCleanly)
{
    // A corrupt pack: a valid one with bytes flipped in the middle (checksums catch it).
    std::string bytes = readBytes(pack_);
    for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i)
        bytes[i] = char(~bytes[i]);
    std::ofstream(dir_ / "corrupt.lfdpack", std::ios::binary) << bytes;
    std::ofstream(dir_ / "bad_profile.json") << R"({"format": "lfd-display-profile/1", "panel_width": 0})";
    std::ofstream(dir_ / "not_an_hdr.hdr") << "#?NOT RADIANCE\n";

    const std::string outputs = " --out " + quoted(dir_ / "eia.png") + " --quilt " + quoted(dir_ / "quilt.png") +
                                " --views-out " + quoted(dir_ / "views") + " --stats " + quoted(dir_ / "stats.json");
    const std::string small = " --display " + quoted(profile_) + " --views 4 --view-size 64x48";
    const std::pair<std::string, std::string> cases[] = {
        {"--headless " + quoted(dir_ / "missing.lfdpack") + small + outputs, "missing.lfdpack"},
        {"--headless " + quoted(dir_ / "corrupt.lfdpack") + small + outputs, "corrupt.lfdpack"},
        {"--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --view-size 96x" + outputs, "--view-size"},
        {"--headless " + quoted(pack_) + small + " --renderer warp-drive" + outputs, "warp-drive"},
        {"--headless " + quoted(pack_) + " --display " + quoted(dir_ / "bad_profile.json") + outputs, "bad_profile.json"},
        {"--headless " + quoted(pack_) + small + " --views 0" + outputs, "--views"},
        {"--headless " + quoted(pack_) + small + " --frames 0" + outputs, "--frames"},
        {"--headless " + quoted(pack_) + small + " --out " + quoted(dir_ / "no_such_dir" / "eia.png"), "no_such_dir"},
        {"--headless " + quoted(pack_) + small + " --bogus-flag", "--bogus-flag"},
        {"--headless " + quoted(pack_) + small + " --environment " + quoted(dir_ / "no_sky.hdr") + outputs, "no_sky.hdr"},
        {"--headless " + quoted(pack_) + small + " --environment " + quoted(dir_ / "not_an_hdr.hdr") + outputs, "not_an_hdr.hdr"},
        {"--headless " + quoted(pack_) + small + " --tone-map aces" + outputs, "--tone-map"},
        {"--headless " + quoted(pack_) + small + " --exposure inf" + outputs, "--exposure"},
        // Beyond GL limits (docs/player/quilts.md "8K panels"): refused before anything is
        // allocated.
        {"--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 100000 --view-size 64x48" + outputs,
         "--views"},
        {"--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 100000x16" + outputs,
         "view_width"},
        // Within the profile's rules but past the driver's (frame_limits.h, docs/player/quilts.md
        // "8K panels"): 2^29 lfdpr view-buffer texels against llvmpipe's 2^27 (any driver's is
        // below 2^29).
        {"--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --renderer lfdpr --views 8 --view-size 8192x8192" +
             outputs,
         "GL_MAX_TEXTURE_BUFFER_SIZE"},
    };
    for (const auto& [args, culprit] : cases) {
        const ToolResult r = runPlay(dir_, args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
        EXPECT_NE(r.err.find(culprit), std::string::npos) << "error must name " << culprit << ": " << r.err;
        EXPECT_EQ(outputsIn(dir_), std::vector<std::string>{}) << args;
    }
}

} // namespace
} // namespace lfd::test

namespace lfd::test {
namespace {

TEST_F(CliTest, LfdprRendererWithAblationFlagsWritesItsStats)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 96x72";
    const ToolResult r = runPlay(dir_, common + " --renderer lfdpr --stats " + quoted(out / "lfdpr.json") + " --out " +
                                          quoted(out / "lfdpr_eia.png") + " --views-out " + quoted(out / "lfdpr_views"));
    ASSERT_EQ(r.status, 0) << r.err;
    // Content: lfdpr's frame 0 rendered here (identical on llvmpipe). RMSE rather than
    // equality: a driver's 32-bit visibility path may resolve a depth tie to either point
    // between runs, so a pixel may differ where two points meet.
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 96, 72);
    const RenderedFrame reference = referenceFrame("lfdpr", pack_, profile, 0);
    for (uint32_t v = 0; v < 4; ++v) {
        const metrics::Image view = readView(out / "lfdpr_views", v);
        EXPECT_EQ(blankReason(view), "") << "view " << v;
        EXPECT_LT(metrics::rmse(view, reference.views[v]), 1.0) << "view " << v;
    }
    const metrics::Image eia = metrics::readImage(out / "lfdpr_eia.png", 4);
    EXPECT_EQ(blankReason(eia), "");
    std::printf("[ numbers  ] lfd-play --renderer lfdpr: EIA RMSE %.3f, max difference %d against lfdpr here\n",
                metrics::rmse(eia, reference.eia), metrics::maxAbsDiff(eia, reference.eia));
    EXPECT_LT(metrics::rmse(eia, reference.eia), 1.0);
    const nlohmann::json stats = nlohmann::json::parse(readBytes(out / "lfdpr.json"));
    for (const char* key : {"points", "bytes_per_point", "point_generation_ms", "view_generation_ms", "eia_ms",
                            "total_ms", "point_buffer_bytes", "view_buffer_bytes", "atomics"})
        EXPECT_TRUE(stats.contains(key)) << key;
    EXPECT_EQ(stats["renderer"], "lfdpr");
    EXPECT_GT(stats["points"].get<double>(), 0.0);

    // Isotropic sampling (the LFD-biased innovation off) needs more points on the same frame.
    const ToolResult iso = runPlay(dir_, common + " --renderer lfdpr --no-lfd-sampling --stats " + quoted(out / "iso.json"));
    ASSERT_EQ(iso.status, 0) << iso.err;
    const nlohmann::json isoStats = nlohmann::json::parse(readBytes(out / "iso.json"));
    EXPECT_GT(isoStats["points"].get<double>(), stats["points"].get<double>());

    const ToolResult bad = runPlay(dir_, common + " --renderer lfdpr --atomics 16");
    EXPECT_NE(bad.status, 0);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// Per-frame work counters (docs/player/lfd-play.md, --stats): with --lfdpr-work-counters a
// third file, STEM.work.csv, holds one row per timed frame; its last row is the frame the
// JSON reports.
TEST_F(CliTest, WorkCountersArePerFrameInTheStatsWorkCsv)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                               " --views 4 --view-size 96x72 --frames 3 --lfdpr-work-counters";
    for (const char* renderer : {"lfdpr", "mvr"}) {
        const fs::path json = out / (std::string(renderer) + ".json");
        const ToolResult r = runPlay(dir_, common + " --renderer " + renderer + " --stats " + quoted(json));
        ASSERT_EQ(r.status, 0) << r.err;
        const nlohmann::json stats = nlohmann::json::parse(readBytes(json));
        std::istringstream csv(readBytes(out / (std::string(renderer) + ".work.csv")));
        std::string header, row;
        std::getline(csv, header);
        std::vector<std::string> names;
        for (std::istringstream h(header); std::getline(h, row, ',');)
            names.push_back(row);
        ASSERT_GE(names.size(), 3u) << header;
        EXPECT_EQ(names[0], "frame");
        std::vector<std::vector<double>> rows;
        while (std::getline(csv, row)) {
            std::vector<double> values;
            std::istringstream cells(row);
            for (std::string cell; std::getline(cells, cell, ',');)
                values.push_back(std::stod(cell));
            ASSERT_EQ(values.size(), names.size()) << row;
            rows.push_back(values);
        }
        ASSERT_EQ(rows.size(), 3u) << renderer;
        const std::string busiest = std::string(renderer) == "mvr" ? "work_triangle_views" : "work_samples";
        const size_t column = size_t(std::find(names.begin(), names.end(), busiest) - names.begin());
        ASSERT_LT(column, names.size()) << header;
        for (size_t f = 0; f < rows.size(); ++f) {
            EXPECT_EQ(rows[f][0], double(f));
            EXPECT_GT(rows[f][column], 0.0) << renderer << " frame " << f << " " << busiest;
        }
        for (size_t c = 1; c < names.size(); ++c) {
            EXPECT_EQ(names[c].rfind("work_", 0), 0u) << names[c];
            EXPECT_EQ(rows.back()[c], stats[names[c]].get<double>()) << renderer << " " << names[c];
        }
        // The test scene turns between frames, so lfdpr's point and sample counts move with it
        // (each row is its own frame, not the last frame's counts copied); mvr draws every
        // triangle in every view, so its counts stay.
        if (std::string(renderer) == "lfdpr")
            EXPECT_NE(rows.front()[column], rows.back()[column]) << "frames 0 and 2 counted alike";
        else
            EXPECT_EQ(rows.front()[column], rows.back()[column]);
    }
    // Without the counters there is no work file.
    const ToolResult plain = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                              " --views 4 --view-size 96x72 --renderer lfdpr --stats " +
                                              quoted(out / "plain.json"));
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_FALSE(fs::exists(out / "plain.work.csv"));
}

TEST_F(CliTest, GstdRendererHeadlessWithFactor)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 96x72";
    const ToolResult r = runPlay(dir_, common + " --renderer gstd --gstd-factor 2 --stats " + quoted(out / "gstd.json") +
                                          " --views-out " + quoted(out / "gstd_views"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(readBytes(out / "gstd.json"));
    EXPECT_EQ(stats["renderer"], "gstd");
    EXPECT_EQ(stats["gstd_factor"], 2.0);
    EXPECT_EQ(stats["gstd_samples"], 32.0);
    EXPECT_EQ(stats["gstd_sub_views"], 4.0) << "the panel model's default";
    EXPECT_EQ(stats["gstd_model_panel"], 1.0);
    EXPECT_GE(stats["anisotropy"].get<double>(), 1.0);
    // Content: gstd is seeded, so the views are the ones rendered here with factor 2.
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 96, 72);
    const RenderedFrame reference = renderFrame(*player::createGstdRenderer({.factor = 2}), readPack(pack_), profile,
                                                {.turntablePeriod = kTurntablePeriod, .lighting = toolDefaultLighting()});
    for (uint32_t v = 0; v < 4; ++v)
        EXPECT_EQ(imageMismatch(readView(out / "gstd_views", v), reference.views[v], 1), "") << "view " << v;

    const ToolResult bad = runPlay(dir_, common + " --renderer gstd --gstd-factor 0");
    EXPECT_NE(bad.status, 0);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("--gstd-factor"), std::string::npos) << bad.err;
    for (const auto& [flags, named] : {std::pair{" --gstd-model light", "--gstd-model"},
                                       std::pair{" --gstd-sub-views 17", "--gstd-sub-views"}}) {
        const ToolResult refused = runPlay(dir_, common + " --renderer gstd" + flags);
        EXPECT_NE(refused.status, 0) << flags;
        EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
        EXPECT_NE(refused.err.find(named), std::string::npos) << refused.err;
    }
}

// The two gold-standard models from the command line: the panel model's EIA is its own
// integral (the one the renderer writes in a test render), the views model interleaves its
// 2-sub-view views like any method.
TEST_F(CliTest, GstdModelsFromTheCommandLine)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 48x36" +
                               " --renderer gstd --gstd-factor 2";
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 48, 36);
    for (const player::GstdModel model : {player::GstdModel::Panel, player::GstdModel::Views}) {
        const std::string name = player::gstdModelName(model);
        const fs::path eia = out / (name + "_eia.png"), stats = out / (name + ".json");
        const ToolResult r = runPlay(dir_, common + " --gstd-model " + name + " --gstd-sub-views 3 --out " + quoted(eia) +
                                              " --stats " + quoted(stats));
        ASSERT_EQ(r.status, 0) << r.err;
        const nlohmann::json json = nlohmann::json::parse(readBytes(stats));
        EXPECT_EQ(json["gstd_sub_views"], 3.0) << name;
        EXPECT_EQ(json["gstd_model_panel"], model == player::GstdModel::Panel ? 1.0 : 0.0) << name;
        player::GstdOptions options;
        options.factor = 2;
        options.subViews = 3;
        options.model = model;
        const RenderedFrame reference =
            renderFrame(*player::createGstdRenderer(options), readPack(pack_), profile,
                        {.turntablePeriod = kTurntablePeriod, .eia = true, .lighting = toolDefaultLighting()});
        EXPECT_EQ(imageMismatch(metrics::readImage(eia, 4), reference.eia, 1), "") << name;
    }
}

TEST_F(CliTest, BenchPrintsRatiosAndWritesResults)
{
    ASSERT_TRUE(fs::exists(kBenchTool)) << kBenchTool << " not built (build target lfd-bench)";
    const fs::path out = dir_ / "bench";
    const ToolResult r = runTool(kBenchTool, dir_, quoted(pack_) + " --display " + quoted(profile_) +
                                                  " --views 4 --view-size 96x72 --frames 2 --warmup 1 --out " + quoted(out) +
                                                  " --gstd-cache " + quoted(dir_ / "gstd-cache"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("gstd: quality frame rendered"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lfdpr/mvr total-time ratio:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lfdpr/mvr-layered:"), std::string::npos) << r.out;
    for (const char* file : {"bench.json", "bench.csv", "speed_vs_error.svg", "lfdpr_eia.png", "mvr_eia.png"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    // Content: the quality frame (frame 0) rendered here; lfdpr's EIA close to mvr's
    // (measured on llvmpipe: RMSE 0.64; the visibility pipeline shades like mvr).
    const DisplayProfile profile =
        tenthPrototypeProfile("cli-small", 4, 96, 72);
    const RenderedFrame mvr = referenceFrame("mvr", pack_, profile, 0);
    EXPECT_EQ(imageMismatch(metrics::readImage(out / "mvr_eia.png", 4), mvr.eia, 1), "") << "mvr EIA";
    const metrics::Image lfdprEia = metrics::readImage(out / "lfdpr_eia.png", 4);
    EXPECT_EQ(blankReason(lfdprEia), "");
    const double lfdprRmse = metrics::rmse(lfdprEia, mvr.eia);
    std::printf("[ numbers  ] lfd-bench EIA RMSE: lfdpr against mvr rendered here %.3f\n", lfdprRmse);
    EXPECT_LT(lfdprRmse, 3.0) << "lfdpr against mvr";
    const nlohmann::json bench = nlohmann::json::parse(readBytes(out / "bench.json"));
    EXPECT_FALSE(bench.dump().find("\"lfdpr\"") == std::string::npos) << "bench.json names lfdpr";
    // gstd is the default reference; every renderer's quality carries FLIP next to RMSE, SSIM.
    EXPECT_EQ(bench["options"]["reference"], "gstd");
    for (const nlohmann::json& e : bench["renderers"]) {
        ASSERT_TRUE(e["quality"]["eia"]["flip"].is_number()) << e.dump();
        EXPECT_TRUE(e["quality"]["centre_view"]["flip"].is_number()) << e.dump();
        if (e["name"] != "gstd") {
            EXPECT_GT(e["quality"]["eia"]["flip"].get<double>(), 0.0) << e["name"];
        }
    }
    // The second run takes gstd's views from the cache; --reference mvr still works.
    const ToolResult again = runTool(kBenchTool, dir_, quoted(pack_) + " --display " + quoted(profile_) +
                                                      " --views 4 --view-size 96x72 --frames 1 --warmup 0 --renderers mvr"
                                                      " --gstd-cache " + quoted(dir_ / "gstd-cache"));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.out.find("quality frame from the gstd cache"), std::string::npos) << again.out;
    const ToolResult vsMvr = runTool(kBenchTool, dir_, quoted(pack_) + " --display " + quoted(profile_) +
                                                      " --views 4 --view-size 96x72 --frames 1 --warmup 0"
                                                      " --renderers lfdpr --reference mvr");
    ASSERT_EQ(vsMvr.status, 0) << vsMvr.err;
    EXPECT_NE(vsMvr.out.find("against mvr"), std::string::npos) << vsMvr.out;

    const ToolResult missing = runTool(kBenchTool, dir_, quoted(dir_ / "missing.lfdpack"));
    EXPECT_NE(missing.status, 0);
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    EXPECT_NE(missing.err.find("missing.lfdpack"), std::string::npos) << missing.err;
}

} // namespace
} // namespace lfd::test

// ---- Driving a display: camera flags, quilt input and output, preview --------------------
namespace lfd::test {
namespace {

// Centroid x and count of the pixels that differ from the background (player::kBackground).
std::pair<double, size_t> coverage(const metrics::Image& view)
{
    const std::vector<uint8_t> mask = coverageMask(view);
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            sum += double(i % view.width);
            ++n;
        }
    return {n ? sum / double(n) : 0.0, n};
}

// The issue's round trip: a quilt written by --quilt and read back with --quilt-in gives
// the EIA of direct rendering, byte for byte. 12 views of 96x72 fill a 4x3 quilt; 8 views
// leave one tile of a 3x3 quilt empty, which --quilt-views 8 skips.
TEST_F(CliTest, QuiltWrittenAndReadBackGivesTheDirectEia)
{
    for (const auto& [views, quiltPrefix, extra] :
         {std::tuple<int, std::string, std::string>{12, "q12_qs4x3a1.78", ""},
          std::tuple<int, std::string, std::string>{8, "q8_qs3x3a1.78", " --quilt-views 8"}}) {
        SCOPED_TRACE(views);
        const fs::path out = dir_ / ("round_trip_" + std::to_string(views));
        fs::create_directories(out);
        const std::string tag = "q" + std::to_string(views);
        const ToolResult direct = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views " +
                                                   std::to_string(views) + " --view-size 96x72 --frame 20 --out " +
                                                   quoted(out / "direct.png") + " --quilt " + quoted(out / (tag + ".png")));
        ASSERT_EQ(direct.status, 0) << direct.err;
        const fs::path quilt = out / (quiltPrefix + ".png");
        ASSERT_TRUE(fs::exists(quilt)) << quilt;
        const ToolResult back = runPlay(dir_, "--headless --quilt-in " + quoted(quilt) + " --display " + quoted(profile_) +
                                                 extra + " --out " + quoted(out / "back.png"));
        ASSERT_EQ(back.status, 0) << back.err;
        const metrics::Image a = metrics::readImage(out / "direct.png"), b = metrics::readImage(out / "back.png");
        ASSERT_EQ(a.width, b.width);
        EXPECT_TRUE(a.pixels == b.pixels) << "max difference " << metrics::maxAbsDiff(a, b);
    }
}

// Each camera flag changes the views as documented (the exact geometry is checked against
// hand-worked projections in camera_controls_test.cpp).
TEST_F(CliTest, CameraFlagsChangeTheViewsAsDocumented)
{
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                               " --views 4 --view-size 96x72 --no-turntable --views-out ";
    auto render = [&](const std::string& name, const std::string& flags) {
        const ToolResult r = runPlay(dir_, common + quoted(dir_ / name) + " " + flags);
        EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
        return std::array<metrics::Image, 2>{metrics::readImage(dir_ / name / "view_000.png"),
                                            metrics::readImage(dir_ / name / "view_003.png")};
    };
    const auto base = render("base", "");
    const auto [baseX, baseCount] = coverage(base[1]);
    ASSERT_GT(baseCount, 200u);

    // --zoom 2: the scene covers about four times the pixels (clipped at the view's edges).
    EXPECT_GT(coverage(render("zoom", "--zoom 2")[1]).second, 2 * baseCount);
    // --pan 5,0: 5 mm right on a 34.54 mm screen of 96 view pixels = 13.9 px in every view.
    const auto pan = render("pan", "--pan 5,0");
    EXPECT_NEAR(coverage(pan[1]).first - baseX, 13.9, 2.0);
    EXPECT_NEAR(coverage(pan[0]).first - coverage(base[0]).first, 13.9, 2.0);
    // --orbit: another side of the scene.
    EXPECT_GT(metrics::rmse(render("orbit", "--orbit 90,0")[1], base[1]), 5.0);
    // --focal-depth 5: the scene moves 5 mm behind the screen, so it shifts right from the
    // leftmost to the rightmost camera (e = -/+80.4 mm) by about 160.8 * 5 / 305 mm = 7.3 px more.
    const auto focal = render("focal", "--focal-depth 5");
    const double disparityBase = baseX - coverage(base[0]).first;
    const double disparityFocal = coverage(focal[1]).first - coverage(focal[0]).first;
    EXPECT_NEAR(disparityFocal - disparityBase, 7.3, 2.0);
    // --depthiness 0: every camera central, every view the same.
    const auto flat = render("flat", "--depthiness 0");
    EXPECT_EQ(metrics::maxAbsDiff(flat[0], flat[1]), 0);
    EXPECT_GT(metrics::maxAbsDiff(base[0], base[1]), 0);
    // --no-turntable: frame 30 (0.5 s) shows what frame 0 shows.
    const auto later = render("later", "--frame 30");
    EXPECT_EQ(metrics::maxAbsDiff(later[1], base[1]), 0);
}

// --frames N with --quilt writes the animation as numbered quilts; --quilt-video encodes
// them with ffmpeg; without ffmpeg the sequence stays and the video step fails in one line.
TEST_F(CliTest, AnimatedQuiltSequenceAndVideo)
{
    const fs::path out = dir_ / "anim";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                               " --views 12 --view-size 96x72 --frames 3 --fps 4 --quilt " + quoted(out / "spin.png");
    const bool haveFfmpeg = !player::findOnPath("ffmpeg").empty();
    const ToolResult r = runPlay(dir_, common + (haveFfmpeg ? " --quilt-video " + quoted(out / "spin.mp4") : ""));
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<metrics::Image> frames;
    for (const char* name : {"spin_0000_qs4x3a1.78.png", "spin_0001_qs4x3a1.78.png", "spin_0002_qs4x3a1.78.png"}) {
        ASSERT_TRUE(fs::exists(out / name)) << name;
        frames.push_back(metrics::readImage(out / name));
    }
    EXPECT_GT(metrics::rmse(frames[0], frames[1]), 1.0) << "the turntable turns between frames";
    if (haveFfmpeg) {
        const fs::path video = out / "spin_qs4x3a1.78.mp4";
        ASSERT_TRUE(fs::exists(video)) << r.out;
        EXPECT_GT(fs::file_size(video), 1000u);
        if (!player::findOnPath("ffprobe").empty()) {
            const ToolResult probe = runTool(player::findOnPath("ffprobe"), out,
                                            "-v error -count_frames -select_streams v:0 -show_entries "
                                            "stream=nb_read_frames,width,height,codec_name -of csv=p=0 " + quoted(video));
            EXPECT_EQ(probe.out, "h264,384,216,3\n") << probe.err;
        }
    } else {
        std::printf("[ NOTE     ] ffmpeg not installed: the video half was not run\n");
    }

    // No ffmpeg on PATH: the sequence is written, the video step fails with one line.
    const fs::path noFfmpeg = dir_ / "no_ffmpeg";
    fs::create_directories(noFfmpeg);
    const ToolResult missing = runPlay(dir_,
                                      "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                          " --views 12 --view-size 96x72 --frames 2 --quilt " + quoted(noFfmpeg / "s.png") +
                                          " --quilt-video " + quoted(noFfmpeg / "s.mp4"),
                                      "PATH=/nonexistent ");
    EXPECT_EQ(missing.status, 1);
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    EXPECT_NE(missing.err.find("ffmpeg is missing"), std::string::npos) << missing.err;
    EXPECT_TRUE(fs::exists(noFfmpeg / "s_0001_qs4x3a1.78.png"));
    EXPECT_FALSE(fs::exists(noFfmpeg / "s_qs4x3a1.78.mp4"));
    // A video alone (no --quilt to keep) fails before rendering and leaves nothing.
    const fs::path videoOnly = dir_ / "video_only";
    fs::create_directories(videoOnly);
    const ToolResult early = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                              " --views 4 --view-size 96x72 --quilt-video " + quoted(videoOnly / "v.mp4"),
                                    "PATH=/nonexistent ");
    EXPECT_EQ(early.status, 1);
    EXPECT_NE(early.err.find("ffmpeg is missing"), std::string::npos) << early.err;
    EXPECT_TRUE(fs::is_empty(videoOnly));
}

// --first-frame F renders frames F .. F + N - 1 alone, each equal to the same frame of a run
// from 0, with the numbered outputs (EIA pattern, quilt sequence, video) under the frames' own
// numbers; --frame names a frame by its number; bad combinations fail in one line.
TEST_F(CliTest, FirstFrameRendersALateRangeAsARunFromZero)
{
    const fs::path out = dir_ / "first";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                               " --renderer mvr --views 6 --view-size 96x72 --fps 4";
    ASSERT_EQ(runPlay(dir_, common + " --frames 4 --out " + quoted(out / "all_%04d.png") + " --quilt " +
                                quoted(out / "all.png")).status,
              0);
    const bool haveFfmpeg = !player::findOnPath("ffmpeg").empty();
    const ToolResult late = runPlay(dir_, common + " --first-frame 2 --frames 2 --out " + quoted(out / "late_%04d.png") +
                                              " --quilt " + quoted(out / "late.png") +
                                              (haveFfmpeg ? " --quilt-video " + quoted(out / "late.mp4") : ""));
    ASSERT_EQ(late.status, 0) << late.err;
    for (const char* frame : {"0000", "0001"}) {
        EXPECT_FALSE(fs::exists(out / ("late_" + std::string(frame) + ".png"))) << frame;
        EXPECT_FALSE(fs::exists(out / ("late_" + std::string(frame) + "_qs3x2a1.78.png"))) << frame;
    }
    for (const char* frame : {"0002", "0003"}) {
        const std::string f(frame);
        ASSERT_TRUE(fs::exists(out / ("late_" + f + ".png"))) << f;
        EXPECT_EQ(imageMismatch(metrics::readImage(out / ("late_" + f + ".png")),
                                metrics::readImage(out / ("all_" + f + ".png")), 0),
                  "")
            << "EIA of frame " << f;
        ASSERT_TRUE(fs::exists(out / ("late_" + f + "_qs3x2a1.78.png"))) << f;
        EXPECT_EQ(imageMismatch(metrics::readImage(out / ("late_" + f + "_qs3x2a1.78.png")),
                                metrics::readImage(out / ("all_" + f + "_qs3x2a1.78.png")), 0),
                  "")
            << "quilt of frame " << f;
    }
    EXPECT_GT(metrics::rmse(metrics::readImage(out / "late_0002.png"), metrics::readImage(out / "late_0003.png")), 1.0)
        << "the turntable turns between frames";
    if (haveFfmpeg && !player::findOnPath("ffprobe").empty()) {
        const ToolResult probe = runTool(player::findOnPath("ffprobe"), out,
                                         "-v error -count_frames -select_streams v:0 -show_entries "
                                         "stream=nb_read_frames -of csv=p=0 " + quoted(out / "late_qs3x2a1.78.mp4"));
        EXPECT_EQ(probe.out, "2\n") << "the video holds frames 2 and 3: " << probe.err;
    }
    // One frame, named by its number: --first-frame 1 --frames 2 --frame 3 renders frames 1
    // and 2, then frame 3 once more for the outputs.
    ASSERT_EQ(runPlay(dir_, common + " --first-frame 1 --frames 2 --frame 3 --out " + quoted(out / "three.png")).status, 0);
    EXPECT_EQ(imageMismatch(metrics::readImage(out / "three.png"), metrics::readImage(out / "all_0003.png"), 0), "");

    const std::pair<std::string, std::string> bad[] = {
        {common + " --first-frame 3 --frame 1 --out " + quoted(out / "bad.png"), "--frame: 1 is before --first-frame 3"},
        {common + " --first-frame 4294967295 --frames 2 --out " + quoted(out / "bad.png"), "--first-frame"},
        {"--headless --quilt-in " + quoted(out / "no_qs2x2a1.png") + " --display " + quoted(profile_) + " --first-frame 2",
         "--first-frame: needs a pack"},
    };
    for (const auto& [args, message] : bad) {
        const ToolResult r = runPlay(dir_, args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(out / "bad.png"));
}

// --preview always (headless timing of the window's preview): every 2nd view at half size,
// interleaved into the full panel.
TEST_F(CliTest, PreviewRendersFewerSmallerViewsIntoTheFullPanel)
{
    const fs::path out = dir_ / "preview";
    fs::create_directories(out);
    const ToolResult r = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                          " --views 8 --view-size 96x72 --preview always --stats " +
                                          quoted(out / "s.json") + " --out " + quoted(out / "eia.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("(preview), 4 views of 48x36"), std::string::npos) << r.out;
    const nlohmann::json stats = nlohmann::json::parse(readBytes(out / "s.json"));
    EXPECT_EQ(stats["views"], 4);
    EXPECT_EQ(stats["view_width"], 48);
    const metrics::Image eia = metrics::readImage(out / "eia.png");
    EXPECT_EQ(eia.width, 384u);
    EXPECT_EQ(eia.height, 216u);
    // Three views at a third of the size with --preview-view-step 3 --preview-size-divisor 3.
    const ToolResult custom = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                               " --views 8 --view-size 96x72 --preview always --preview-view-step 3"
                                               " --preview-size-divisor 3");
    ASSERT_EQ(custom.status, 0) << custom.err;
    EXPECT_NE(custom.out.find("(preview), 3 views of 32x24"), std::string::npos) << custom.out;
}

TEST_F(CliTest, DisplayDrivingBadInputFailsCleanly)
{
    std::ofstream(dir_ / "plain.png") << "not a quilt";
    const std::string small = " --display " + quoted(profile_) + " --views 4 --view-size 64x48 --out " + quoted(dir_ / "e.png");
    const std::string pack = "--headless " + quoted(pack_) + small;
    const std::pair<std::string, std::string> cases[] = {
        {"--headless --quilt-in " + quoted(dir_ / "missing_qs2x2a1.png") + " --display " + quoted(profile_), "missing_qs2x2a1.png"},
        {"--headless --quilt-in " + quoted(dir_ / "plain.png") + " --display " + quoted(profile_), "plain.png"},
        {pack + " --quilt-in " + quoted(dir_ / "x_qs2x2a1.png"), "--quilt-in"},
        {"--headless --quilt-in " + quoted(dir_ / "x_qs2x2a1.png") + small, "--views"},
        {"--headless --display " + quoted(profile_), "PACK"},
        {pack + " --monitor 1", "--monitor"},
        {pack + " --fullscreen", "--fullscreen"},
        {pack + " --orbit 30", "--orbit"},
        {pack + " --pan 1,x", "--pan"},
        {pack + " --depthiness 9", "--depthiness"},
        {pack + " --zoom 0", "--zoom"},
        {pack + " --preview sometimes", "--preview"},
        {pack + " --preview-view-step 0", "--preview-view-step"},
        {pack + " --quilt-video " + quoted(dir_ / "clip.avi"), "--quilt-video"},
        {quoted(pack_) + small + " --quilt-video " + quoted(dir_ / "clip.mp4"), "--quilt-video: needs --headless"},
        {"--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --out " + quoted(dir_ / "e_%s.png"), "--out"},
        {"--quilt-in " + quoted(dir_ / "x_qs2x2a1.mp4") + " --display " + quoted(profile_) + " --quilt-frame 1", "--quilt-frame"},
    };
    for (const auto& [args, culprit] : cases) {
        const ToolResult r = runPlay(dir_, args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
        EXPECT_NE(r.err.find(culprit), std::string::npos) << "error must name " << culprit << ": " << r.err;
        EXPECT_EQ(outputsIn(dir_), std::vector<std::string>{"plain.png"}) << args;
    }
}

// --quilt-layout: a quilt written with other tiles and aspect, and a quilt whose name has
// no aspect (older tools' "old_qs4x3.png") read back with the flag - the direct EIA.
TEST_F(CliTest, QuiltLayoutFlagWritesAndReadsOtherLayouts)
{
    const fs::path out = dir_ / "layout";
    fs::create_directories(out);
    const std::string common = "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 12 --view-size 96x72";
    const ToolResult direct = runPlay(dir_, common + " --frame 20 --out " + quoted(out / "direct.png") + " --quilt " +
                                               quoted(out / "q.png") + " --quilt-layout 6x2a2");
    ASSERT_EQ(direct.status, 0) << direct.err;
    const fs::path written = out / "q_qs6x2a2.png";
    ASSERT_TRUE(fs::exists(written));
    EXPECT_EQ(metrics::readImage(written).width, 6u * 96u);
    const ToolResult tooFew = runPlay(dir_, common + " --quilt " + quoted(out / "few.png") + " --quilt-layout 3x3");
    EXPECT_EQ(tooFew.status, 1);
    EXPECT_NE(tooFew.err.find("fewer tiles"), std::string::npos) << tooFew.err;

    fs::copy_file(written, out / "old_qs6x2.png");
    for (const std::string& flags : {std::string(""), std::string(" --quilt-layout 6x2a1.78")}) {
        const ToolResult back = runPlay(dir_, "--headless --quilt-in " + quoted(out / "old_qs6x2.png") + " --display " +
                                                 quoted(profile_) + flags + " --out " + quoted(out / "back.png"));
        ASSERT_EQ(back.status, 0) << back.err;
        const metrics::Image a = metrics::readImage(out / "direct.png"), b = metrics::readImage(out / "back.png");
        EXPECT_EQ(metrics::maxAbsDiff(a, b), 0) << flags;
    }
    const ToolResult bad = runPlay(dir_, common + " --quilt-layout 6by2");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--quilt-layout"), std::string::npos) << bad.err;
}

// Headless without an output flag renders (a timing run) and says that nothing was
// written and which flags write; --help says --quilt-video needs --headless.
TEST_F(CliTest, HeadlessWithoutOutputsSaysNothingWasWritten)
{
    const ToolResult r = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                          " --views 4 --view-size 64x48");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("lfd-play: no output written (timing only; --out"), std::string::npos) << r.out;
    EXPECT_TRUE(outputsIn(dir_).empty());
    const ToolResult withOutput = runPlay(dir_, "--headless " + quoted(pack_) + " --display " + quoted(profile_) +
                                                   " --views 4 --view-size 64x48 --out " + quoted(dir_ / "e.png"));
    EXPECT_EQ(withOutput.out.find("no output written"), std::string::npos) << withOutput.out;
    const ToolResult help = runPlay(dir_, "--help");
    EXPECT_NE(help.out.find("headless only (--headless)"), std::string::npos);
}

// A pack whose tessellation bound was made for another display (BakeSettings) plays with
// one warning line saying so; for the same display and views, none.
TEST_F(CliTest, PackBakedForAnotherDisplayWarns)
{
    Scene scene = cubeAndSphereScene();
    scene.settings.displayProfile = "looking_glass_portrait_visual";
    scene.settings.viewWidth = 420;
    scene.settings.viewHeight = 560;
    scene.settings.viewCount = 48;
    const fs::path other = dir_ / "other.lfdpack";
    writePack(other, scene);
    const std::string args = " --display " + quoted(profile_) + " --views 4 --view-size 64x48";
    const ToolResult r = runPlay(dir_, "--headless " + quoted(other) + args);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("lfd-play: warning: other.lfdpack: its tessellation bound (100 view pixels) was made for "
                         "display 'looking_glass_portrait_visual' with 420x560 views, this is 'cli-small' with "
                         "64x48 views"),
              std::string::npos)
        << r.err;
    scene.settings.displayProfile = "cli-small";
    scene.settings.viewWidth = 64;
    scene.settings.viewHeight = 48;
    writePack(other, scene);
    const ToolResult same = runPlay(dir_, "--headless " + quoted(other) + args);
    EXPECT_EQ(same.err, "");
    // Views of the same display no larger than the baked ones keep the bound (an edge spans
    // fewer pixels of smaller views); larger ones warn by how much: 64x48 against 32x32 is
    // twice as wide, so up to 2 x 100 pixels.
    scene.settings.viewWidth = 128;
    scene.settings.viewHeight = 96;
    writePack(other, scene);
    EXPECT_EQ(runPlay(dir_, "--headless " + quoted(other) + args).err, "");
    scene.settings.viewWidth = 32;
    scene.settings.viewHeight = 32;
    writePack(other, scene);
    const ToolResult larger = runPlay(dir_, "--headless " + quoted(other) + args);
    EXPECT_EQ(larger.err, "lfd-play: warning: other.lfdpack: its tessellation bound (100 view pixels) was made for 32x32 "
                          "views of display 'cli-small', these are 64x48: edges may span up to 200 view pixels\n");
}

} // namespace
} // namespace lfd::test
