// lfd-play end to end: a small pack written with lfd::writePack, run headless through the
// real executable; output files, sizes, stats keys; bad input gives one stderr line,
// a non-zero status and no output files.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "image_output.h"

#include "lfd/pack.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

const fs::path kPlay = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct RunResult {
    int status = -1;
    std::string out, err;
};

const fs::path kBench = fs::path(LFD_BINARY_DIR) / "player" / "lfd-bench";

RunResult runTool(const fs::path& tool, const fs::path& dir, const std::string& args)
{
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string command = "'" + tool.string() + "' " + args + " > '" + out.string() + "' 2> '" +
                                err.string() + "'";
    RunResult r;
    const int raw = std::system(command.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = readText(out);
    r.err = readText(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

RunResult runPlay(const fs::path& dir, const std::string& args) { return runTool(kPlay, dir, args); }

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// Files in `dir` other than the inputs the test put there.
std::vector<std::string> outputsIn(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name != "scene.lfdpack" && name != "profile.json" && name != "corrupt.lfdpack" &&
            name != "bad_profile.json")
            names.push_back(fs::relative(e.path(), dir).string());
    }
    return names;
}

class CliTest : public GlTest {
protected:
    void SetUp() override
    {
        GlTest::SetUp();
        if (IsSkipped())
            return;
        ASSERT_TRUE(fs::exists(kPlay)) << kPlay << " not built (build target lfd-play)";
        dir_ = testOutputDir(std::string("cli_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        pack_ = dir_ / "scene.lfdpack";
        writePack(pack_, cubeAndSphereScene());
        profile_ = dir_ / "profile.json";
        std::ofstream(profile_) << tenthPrototypeProfileJson("cli-small");
    }
    fs::path dir_, pack_, profile_;
};

TEST_F(CliTest, HeadlessWritesEveryRequestedOutput)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const RunResult r = runPlay(dir_, "--headless " + q(pack_) + " --display " + q(profile_) +
                                          " --views 4 --view-size 96x72 --frames 3 --out " + q(out / "eia.png") +
                                          " --quilt " + q(out / "quilt.png") + " --views-out " + q(out / "views") +
                                          " --stats " + q(out / "stats.json") + " --viewer-out " +
                                          q(out / "viewer.png") + " --viewer-pos 1.5");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("OpenGL"), std::string::npos) << "start-up line names the GL driver: " << r.out;

    const player::Image eia = player::readImage(out / "eia.png");
    EXPECT_EQ(eia.width, 384u);
    EXPECT_EQ(eia.height, 216u);
    // 4 views of 96x72 on a 16:9 panel: the quilt layout chooses its tiles; find the file.
    fs::path quilt;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().filename().string().rfind("quilt_qs", 0) == 0)
            quilt = e.path();
    ASSERT_FALSE(quilt.empty()) << "no quilt_qs*.png written";
    const player::Image quiltImage = player::readImage(quilt);
    EXPECT_EQ(quiltImage.width % 96, 0u);
    EXPECT_EQ(quiltImage.height % 72, 0u);
    EXPECT_GE((quiltImage.width / 96) * (quiltImage.height / 72), 4u);
    for (int v = 0; v < 4; ++v) {
        char name[32];
        std::snprintf(name, sizeof(name), "view_%03d.png", v);
        const player::Image view = player::readImage(out / "views" / name);
        EXPECT_EQ(view.width, 96u);
        EXPECT_EQ(view.height, 72u);
    }
    EXPECT_FALSE(fs::exists(out / "views" / "view_004.png"));
    const player::Image viewer = player::readImage(out / "viewer.png");
    EXPECT_EQ(viewer.width, 96u);
    EXPECT_EQ(viewer.height, 72u);

    const nlohmann::json stats = nlohmann::json::parse(readText(out / "stats.json"));
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
    const std::string csv = readText(out / "stats.csv");
    EXPECT_EQ(csv.rfind("frame,stage,ms\n", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 3);
}

TEST_F(CliTest, LayeredRendererAndExplicitFrame)
{
    if (!caps().layerFromVertexShader)
        LFD_SKIP_OR_FAIL("driver lacks GL_ARB_shader_viewport_layer_array");
    const fs::path a = dir_ / "a", b = dir_ / "b";
    const std::string common = "--headless " + q(pack_) + " --display " + q(profile_) + " --views 4 --view-size 64x48";
    ASSERT_EQ(runPlay(dir_, common + " --renderer mvr --frames 1 --frame 30 --views-out " + q(a)).status, 0);
    const RunResult r = runPlay(dir_, common + " --renderer mvr-layered --frames 2 --frame 30 --views-out " + q(b));
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* name : {"view_000.png", "view_003.png"}) {
        const player::Image va = player::readImage(a / name), vb = player::readImage(b / name);
        EXPECT_LE(player::maxAbsDiff(va, vb), 1) << name;
    }
    // A different frame shows the turntable at another angle.
    const fs::path c = dir_ / "c";
    ASSERT_EQ(runPlay(dir_, common + " --frames 1 --views-out " + q(c)).status, 0);
    EXPECT_GT(player::rmse(player::readImage(a / "view_000.png"), player::readImage(c / "view_000.png")), 1.0);
}

TEST_F(CliTest, DefaultPrototypeProfileGivesAFullPanelEia)
{
    const fs::path eia = dir_ / "eia.png";
    const RunResult r = runPlay(dir_, "--headless " + q(pack_) + " --views 8 --view-size 120x90 --out " + q(eia));
    ASSERT_EQ(r.status, 0) << r.err;
    const player::Image image = player::readImage(eia);
    EXPECT_EQ(image.width, 3840u);
    EXPECT_EQ(image.height, 2160u);
}

// Each bad input: non-zero status, exactly one stderr line naming the culprit, no files.
TEST_F(CliTest, BadInputFailsCleanly)
{
    // A corrupt pack: a valid one with bytes flipped in the middle (checksums catch it).
    std::string bytes = readText(pack_);
    for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i)
        bytes[i] = char(~bytes[i]);
    std::ofstream(dir_ / "corrupt.lfdpack", std::ios::binary) << bytes;
    std::ofstream(dir_ / "bad_profile.json") << R"({"format": "lfd-display-profile/1", "panel_width": 0})";

    const std::string outputs = " --out " + q(dir_ / "eia.png") + " --quilt " + q(dir_ / "quilt.png") +
                                " --views-out " + q(dir_ / "views") + " --stats " + q(dir_ / "stats.json");
    const std::string small = " --display " + q(profile_) + " --views 4 --view-size 64x48";
    const std::pair<std::string, std::string> cases[] = {
        {"--headless " + q(dir_ / "missing.lfdpack") + small + outputs, "missing.lfdpack"},
        {"--headless " + q(dir_ / "corrupt.lfdpack") + small + outputs, "corrupt.lfdpack"},
        {"--headless " + q(pack_) + " --display " + q(profile_) + " --view-size 96x" + outputs, "--view-size"},
        {"--headless " + q(pack_) + small + " --renderer warp-drive" + outputs, "warp-drive"},
        {"--headless " + q(pack_) + " --display " + q(dir_ / "bad_profile.json") + outputs, "bad_profile.json"},
        {"--headless " + q(pack_) + small + " --views 0" + outputs, "--views"},
        {"--headless " + q(pack_) + small + " --frames 0" + outputs, "--frames"},
        {"--headless " + q(pack_) + small + " --out " + q(dir_ / "no_such_dir" / "eia.png"), "no_such_dir"},
        {"--headless " + q(pack_) + small + " --bogus-flag", "--bogus-flag"},
    };
    for (const auto& [args, culprit] : cases) {
        const RunResult r = runPlay(dir_, args);
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
    const std::string common = "--headless " + q(pack_) + " --display " + q(profile_) + " --views 4 --view-size 96x72";
    const RunResult r = runPlay(dir_, common + " --renderer lfdpr --stats " + q(out / "lfdpr.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(readText(out / "lfdpr.json"));
    for (const char* key : {"points", "bytes_per_point", "point_generation_ms", "view_generation_ms", "eia_ms",
                            "total_ms", "point_buffer_bytes", "view_buffer_bytes", "atomics"})
        EXPECT_TRUE(stats.contains(key)) << key;
    EXPECT_EQ(stats["renderer"], "lfdpr");
    EXPECT_GT(stats["points"].get<double>(), 0.0);

    // Isotropic sampling (the LFD-biased innovation off) needs more points on the same frame.
    const RunResult iso = runPlay(dir_, common + " --renderer lfdpr --no-lfd-sampling --stats " + q(out / "iso.json"));
    ASSERT_EQ(iso.status, 0) << iso.err;
    const nlohmann::json isoStats = nlohmann::json::parse(readText(out / "iso.json"));
    EXPECT_GT(isoStats["points"].get<double>(), stats["points"].get<double>());

    const RunResult bad = runPlay(dir_, common + " --renderer lfdpr --atomics 16");
    EXPECT_NE(bad.status, 0);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

TEST_F(CliTest, GstdRendererHeadlessWithFactor)
{
    const fs::path out = dir_ / "out";
    fs::create_directories(out);
    const std::string common = "--headless " + q(pack_) + " --display " + q(profile_) + " --views 4 --view-size 96x72";
    const RunResult r = runPlay(dir_, common + " --renderer gstd --gstd-factor 2 --stats " + q(out / "gstd.json") +
                                          " --views-out " + q(out / "gstd_views"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(readText(out / "gstd.json"));
    EXPECT_EQ(stats["renderer"], "gstd");
    EXPECT_EQ(stats["gstd_factor"], 2.0);
    EXPECT_EQ(stats["gstd_samples"], 32.0);
    EXPECT_EQ(stats["gstd_sub_views"], 2.0);
    EXPECT_GE(stats["anisotropy"].get<double>(), 1.0);
    EXPECT_TRUE(fs::exists(out / "gstd_views" / "view_003.png"));

    const RunResult bad = runPlay(dir_, common + " --renderer gstd --gstd-factor 0");
    EXPECT_NE(bad.status, 0);
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("--gstd-factor"), std::string::npos) << bad.err;
}

TEST_F(CliTest, BenchPrintsRatiosAndWritesResults)
{
    ASSERT_TRUE(fs::exists(kBench)) << kBench << " not built (build target lfd-bench)";
    const fs::path out = dir_ / "bench";
    const RunResult r = runTool(kBench, dir_, q(pack_) + " --display " + q(profile_) +
                                                  " --views 4 --view-size 96x72 --frames 2 --warmup 1 --out " + q(out) +
                                                  " --gstd-cache " + q(dir_ / "gstd-cache"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("gstd: quality frame rendered"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lfdpr/mvr total-time ratio:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("lfdpr/mvr-layered:"), std::string::npos) << r.out;
    for (const char* file : {"bench.json", "bench.csv", "speed_vs_error.svg", "lfdpr_eia.png", "mvr_eia.png"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    const nlohmann::json bench = nlohmann::json::parse(readText(out / "bench.json"));
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
    const RunResult again = runTool(kBench, dir_, q(pack_) + " --display " + q(profile_) +
                                                      " --views 4 --view-size 96x72 --frames 1 --warmup 0 --renderers mvr"
                                                      " --gstd-cache " + q(dir_ / "gstd-cache"));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.out.find("quality frame from the gstd cache"), std::string::npos) << again.out;
    const RunResult vsMvr = runTool(kBench, dir_, q(pack_) + " --display " + q(profile_) +
                                                      " --views 4 --view-size 96x72 --frames 1 --warmup 0"
                                                      " --renderers lfdpr --reference mvr");
    ASSERT_EQ(vsMvr.status, 0) << vsMvr.err;
    EXPECT_NE(vsMvr.out.find("against mvr"), std::string::npos) << vsMvr.out;

    const RunResult missing = runTool(kBench, dir_, q(dir_ / "missing.lfdpack"));
    EXPECT_NE(missing.status, 0);
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    EXPECT_NE(missing.err.find("missing.lfdpack"), std::string::npos) << missing.err;
}

} // namespace
} // namespace lfd::test
