// lfd-bench's runner and report on a small in-memory scene: every renderer timed on the
// same frames, the reference compared with itself is identical, mvr-layered agrees with
// mvr, speed-ups are consistent, and the written JSON / CSV / SVG / PNGs hold what the
// table shows.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"
#include "tool_run.h"

#include "bench_report.h"
#include "bench_runner.h"
#include "image_metrics.h"
#include "renderer_lfdpr.h"
#include "renderer_registry.h"

#include "lfd/display_profile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;
using player::BenchOptions;
using player::BenchReport;

// 384x216 panel, 4 views of 64x48: a frame takes milliseconds on llvmpipe.
DisplayProfile benchProfile() { return tenthPrototypeProfile("bench-small", 4, 64, 48); }

BenchOptions options(std::vector<std::string> renderers)
{
    BenchOptions o;
    o.pack = "scene.lfdpack";
    o.renderers = std::move(renderers);
    o.reference = "mvr"; // these tests check mvr as the reference; gstd_test.cpp covers gstd
    o.frames = 3;
    o.warmup = 1;
    o.quiet = true;
    return o;
}

size_t countOf(const std::string& text, const std::string& needle)
{
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
        ++n;
    return n;
}

class BenchTest : public GlTest {};

TEST_F(BenchTest, TimesEveryRendererAndComparesWithReference)
{
    std::ostringstream progress;
    std::map<std::string, player::FrameImages> images;
    const DisplayProfile profile = benchProfile();
    const BenchReport report = player::runBenchmark(options({"mvr-layered", "mvr"}), profile, cubeAndSphereScene(),
                                                    "scene.lfdpack", "test GL", progress, &images);
    EXPECT_TRUE(progress.str().empty()) << "quiet run printed progress";
    ASSERT_EQ(report.results.size(), 2u);
    EXPECT_EQ(report.results[0].name, "mvr-layered"); // the user's order, not the run order
    EXPECT_EQ(report.results[1].name, "mvr");
    EXPECT_EQ(report.triangles, cubeAndSphereScene().triangleCount());
    for (const player::RendererResult& r : report.results) {
        EXPECT_TRUE(r.timed);
        for (const char* stage : {"view_generation", "eia", "total"}) {
            ASSERT_TRUE(r.stages.count(stage)) << r.name << " has no " << stage;
            EXPECT_EQ(r.stages.at(stage).ms.size(), 3u) << "warm-up frames must not be timed";
            EXPECT_GT(r.stages.at(stage).mean(), 0.0);
        }
        // "total" brackets the other stages.
        EXPECT_GE(r.stageMean("total") * 1.001, r.stageMean("view_generation") + r.stageMean("eia"));
        ASSERT_TRUE(images.count(r.name));
        EXPECT_EQ(images[r.name].eia.size(), size_t(profile.panelWidth) * profile.panelHeight * 4);
        EXPECT_EQ(images[r.name].centre.size(), size_t(profile.viewWidth) * profile.viewHeight * 4);
    }
    // The reference against itself; mvr-layered reproduces mvr (renderer_test: <= 1 level).
    const player::RendererResult& mvr = report.results[1];
    EXPECT_EQ(mvr.eia.rmse, 0.0);
    EXPECT_TRUE(std::isinf(mvr.eia.psnr));
    EXPECT_EQ(mvr.allViews.ssim, 1.0);
    const player::RendererResult& layered = report.results[0];
    EXPECT_LT(layered.eia.rmse, 1.0);
    EXPECT_LT(layered.allViews.rmse, 1.0);
    EXPECT_GT(layered.centreView.ssim, 0.99);
    // The images differ between renderers only as much as the metrics say.
    EXPECT_LT(metrics::rmse({profile.panelWidth, profile.panelHeight, 4, images["mvr"].eia},
                           {profile.panelWidth, profile.panelHeight, 4, images["mvr-layered"].eia}),
              1.0);
    // Speed-ups are ratios of the mean totals.
    ASSERT_TRUE(report.speedUp("mvr-layered", "mvr"));
    EXPECT_NEAR(*report.speedUp("mvr-layered", "mvr"), mvr.stageMean("total") / layered.stageMean("total"), 1e-9);
    EXPECT_NEAR(*report.speedUp("mvr", "mvr-layered") * *report.speedUp("mvr-layered", "mvr"), 1.0, 1e-9);
    EXPECT_FALSE(report.speedUp("lfdpr", "mvr"));

    const std::string table = player::benchTable(report);
    EXPECT_NE(table.find("lfdpr/mvr total-time ratio: n/a"), std::string::npos) << table;
    EXPECT_NE(table.find("4 views of 64x48"), std::string::npos) << table;
}

// Round-robin timing (the default): the configurations take turns frame by frame, each
// still timed on its own frames with its own stats; --sequential (interleave = false)
// times one configuration after the other. Both give the same quality figures and stats
// (timing order changes no image), and a stop while they take turns keeps nothing
// half-timed. The paper pipeline starts with room for 16 points, so its first frame
// overflows and renders partially (it grows for the next): the quality frame must come
// from the timed renderer, as in a sequential run, not from a fresh one.
TEST_F(BenchTest, RenderersTakeTurnsUnlessSequential)
{
    const DisplayProfile profile = benchProfile();
    BenchOptions o = options({"mvr", "lfdpr", "lfdpr-paper"});
    o.rendererOptions.lfdpr.initialPointCapacity = 16;
    o.quiet = false;
    std::ostringstream turnsProgress, sequentialProgress;
    const BenchReport turns =
        player::runBenchmark(o, profile, cubeAndSphereScene(), "scene.lfdpack", "test GL", turnsProgress);
    o.interleave = false;
    const BenchReport sequential =
        player::runBenchmark(o, profile, cubeAndSphereScene(), "scene.lfdpack", "test GL", sequentialProgress);

    EXPECT_EQ(countOf(turnsProgress.str(), "3 configuration(s) taking turns"), 1u) << turnsProgress.str();
    EXPECT_EQ(countOf(turnsProgress.str(), "(timed taking turns)"), 3u) << turnsProgress.str();
    EXPECT_EQ(countOf(sequentialProgress.str(), "taking turns"), 0u) << sequentialProgress.str();
    EXPECT_EQ(countOf(sequentialProgress.str(), "timed frame(s)"), 3u) << sequentialProgress.str();
    ASSERT_EQ(turns.results.size(), 3u);
    ASSERT_EQ(sequential.results.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        const player::RendererResult& a = turns.results[i];
        const player::RendererResult& b = sequential.results[i];
        EXPECT_EQ(a.name, b.name);
        EXPECT_TRUE(a.timed);
        for (const char* stage : {"view_generation", "eia", "total"}) {
            ASSERT_TRUE(a.stages.count(stage)) << a.name << " has no " << stage;
            EXPECT_EQ(a.stages.at(stage).ms.size(), 3u) << a.name << " " << stage;
        }
        EXPECT_EQ(a.eia.rmse, b.eia.rmse) << a.name;
        EXPECT_EQ(a.allViews.rmse, b.allViews.rmse) << a.name;
        EXPECT_EQ(a.extraValue("points"), b.extraValue("points")) << a.name;
        EXPECT_EQ(a.extraValue("overflow_frames"), b.extraValue("overflow_frames")) << a.name;
    }
    // The paper pipeline's quality frame is a full one (its first timed frame was not).
    ASSERT_TRUE(turns.results[2].extraValue("overflow_frames"));
    EXPECT_GE(*turns.results[2].extraValue("overflow_frames"), 1.0);
    EXPECT_LT(turns.results[2].eia.rmse, 10.0);
    ASSERT_TRUE(turns.results[1].extraValue("points")); // lfdpr's stats come from its timed renderer
    EXPECT_GT(*turns.results[1].extraValue("points"), 0.0);
    EXPECT_TRUE(turns.results[1].stages.count("point_generation"));

    // A stop while the configurations take turns: nothing finished, nothing reported.
    o.interleave = true;
    o.quiet = true;
    int checks = 0;
    o.shouldStop = [&] { return ++checks > 2; };
    std::ostringstream quiet;
    const BenchReport stopped =
        player::runBenchmark(o, profile, cubeAndSphereScene(), "scene.lfdpack", "test GL", quiet);
    EXPECT_TRUE(stopped.interrupted);
    EXPECT_TRUE(stopped.results.empty());
}

TEST_F(BenchTest, ReferenceOutsideTheListIsRenderedUntimed)
{
    std::ostringstream progress;
    BenchOptions o = options({"mvr-layered"});
    o.quiet = false;
    const BenchReport report =
        player::runBenchmark(o, benchProfile(), cubeAndSphereScene(), "scene.lfdpack", "test GL", progress);
    ASSERT_EQ(report.results.size(), 2u);
    EXPECT_EQ(report.results[1].name, "mvr");
    EXPECT_FALSE(report.results[1].timed);
    EXPECT_TRUE(report.results[1].stages.empty());
    EXPECT_FALSE(report.speedUp("mvr-layered", "mvr"));
    EXPECT_NE(progress.str().find("[1/2] mvr: reference only"), std::string::npos) << progress.str();
    EXPECT_NE(player::benchTable(report).find("mvr (ref, untimed)"), std::string::npos);
}

TEST_F(BenchTest, UnknownRendererIsOneLineError)
{
    std::ostringstream progress;
    try {
        player::runBenchmark(options({"mvr", "warp-drive"}), benchProfile(), cubeAndSphereScene(), "scene.lfdpack",
                             "test GL", progress);
        FAIL() << "unknown renderer accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("warp-drive"), std::string::npos);
        EXPECT_NE(what.find("lfdpr-no-mv-mipmapping"), std::string::npos) << "variants are listed";
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
    EXPECT_THROW(player::createRenderer("lfdpr-no-anything"), std::invalid_argument);
}

TEST_F(BenchTest, LfdprVariantsDisableOneInnovationEach)
{
    struct Expect {
        const char* name;
        bool lfd, texture, mip, cull;
    };
    for (const Expect& e : {Expect{"lfdpr", true, true, true, true}, Expect{"lfdpr-no-lfd-sampling", false, true, true, true},
                            Expect{"lfdpr-no-texture-splatting", true, false, true, true},
                            Expect{"lfdpr-no-pixel-culling", true, true, true, false},
                            Expect{"lfdpr-no-mv-mipmapping", true, true, false, true}}) {
        std::unique_ptr<player::Renderer> r = player::createRenderer(e.name);
        const auto* lfdpr = dynamic_cast<const player::LfdprRenderer*>(r.get());
        ASSERT_NE(lfdpr, nullptr) << e.name;
        EXPECT_EQ(lfdpr->options().lfdBiasedSampling, e.lfd) << e.name;
        EXPECT_EQ(lfdpr->options().textureSplatting, e.texture) << e.name;
        EXPECT_EQ(lfdpr->options().multiviewMipmapping, e.mip) << e.name;
        EXPECT_EQ(lfdpr->options().pixelCentreCulling, e.cull) << e.name;
        EXPECT_EQ(lfdpr->options().cellScale, 2u) << e.name;
    }
    std::unique_ptr<player::Renderer> paperDensity = player::createRenderer("lfdpr-no-cell-scaling");
    const auto* lfdpr = dynamic_cast<const player::LfdprRenderer*>(paperDensity.get());
    ASSERT_NE(lfdpr, nullptr);
    EXPECT_EQ(lfdpr->options().cellScale, 1u);
    EXPECT_TRUE(lfdpr->options().pixelCentreCulling);
}

TEST_F(BenchTest, LfdprRowHasPointGenerationAndRatioLines)
{
    std::ostringstream progress;
    BenchOptions o = options({"mvr", "mvr-layered", "lfdpr"});
    o.frames = 2;
    const BenchReport report =
        player::runBenchmark(o, benchProfile(), cubeAndSphereScene(), "scene.lfdpack", "test GL", progress);
    const player::RendererResult* lfdpr = report.find("lfdpr");
    ASSERT_NE(lfdpr, nullptr);
    EXPECT_GT(lfdpr->stageMean("point_generation"), 0.0);
    ASSERT_TRUE(lfdpr->extraValue("points"));
    EXPECT_GT(*lfdpr->extraValue("points"), 100.0);
    EXPECT_GT(lfdpr->centreView.ssim, 0.5) << "lfdpr's views should resemble mvr's";
    const std::string table = player::benchTable(report);
    EXPECT_NE(table.find("lfdpr/mvr total-time ratio: " +
                         [&] {
                             char t[32];
                             std::snprintf(t, sizeof(t), "%.2fx", *report.speedUp("lfdpr", "mvr"));
                             return std::string(t);
                         }()),
              std::string::npos)
        << table;
    EXPECT_EQ(table.find("lfdpr/mvr-layered: n/a"), std::string::npos) << table;

    // Every stage lfd-play prints is in the bench report too: lfdpr's resolve has its own
    // column in the table and the CSV (it once went missing from both).
    EXPECT_GT(lfdpr->stageMean("resolve"), 0.0);
    EXPECT_NE(table.find("resolve ms"), std::string::npos) << table;
    EXPECT_EQ(table.find("stages inside total not shown above"), std::string::npos) << table;
    const std::string csv = player::benchCsv(report);
    const std::string header = csv.substr(0, csv.find('\n'));
    ASSERT_NE(header.find(",resolve_ms"), std::string::npos) << header;
    const size_t lfdprRow = csv.find("\nlfdpr,");
    ASSERT_NE(lfdprRow, std::string::npos) << csv;
    const std::string row = csv.substr(lfdprRow + 1, csv.find('\n', lfdprRow + 1) - lfdprRow - 1);
    EXPECT_NE(row.back(), ',') << "lfdpr's resolve_ms is empty: " << row;
}

TEST_F(BenchTest, WritesJsonCsvSvgAndImages)
{
    std::ostringstream progress;
    std::map<std::string, player::FrameImages> images;
    const DisplayProfile profile = benchProfile();
    const BenchReport report = player::runBenchmark(options({"mvr", "mvr-layered"}), profile, cubeAndSphereScene(),
                                                    "scene.lfdpack", "test GL", progress, &images);
    const fs::path dir = testOutputDir("bench_outputs") / "nested";
    const std::vector<fs::path> written = player::writeBenchOutputs(dir, report, images);
    // 2 x (EIA, centre view) + 1 diff (not for the reference) + json, csv, svg.
    EXPECT_EQ(written.size(), 8u);
    for (const fs::path& path : written)
        EXPECT_TRUE(fs::is_regular_file(path)) << path;
    EXPECT_FALSE(fs::exists(dir / "mvr_diff_eia.png"));
    EXPECT_EQ(metrics::readImage(dir / "mvr-layered_eia.png").width, profile.panelWidth);
    const metrics::Image centre = metrics::readImage(dir / "mvr_view_centre.png", 4);
    EXPECT_EQ(centre.width, profile.viewWidth);
    EXPECT_EQ(centre.pixels, images["mvr"].centre);

    const nlohmann::json j = nlohmann::json::parse(readBytes(dir / "bench.json"));
    EXPECT_EQ(j["gl"], "test GL");
    EXPECT_EQ(j["profile"]["views"], 4);
    EXPECT_EQ(j["options"]["frames"], 3);
    ASSERT_EQ(j["renderers"].size(), 2u);
    const nlohmann::json& mvr = j["renderers"][0];
    EXPECT_EQ(mvr["name"], "mvr");
    EXPECT_EQ(mvr["stages"]["total"]["ms"].size(), 3u);
    for (const char* key : {"mean", "median", "min", "max"})
        EXPECT_TRUE(mvr["stages"]["total"].contains(key)) << key;
    EXPECT_TRUE(mvr["quality"]["eia"]["psnr"].is_null()) << "identical: +inf is written as null";
    EXPECT_DOUBLE_EQ(mvr["speedup_vs_mvr"].get<double>(), 1.0);
    EXPECT_NEAR(j["renderers"][1]["quality"]["eia"]["rmse"].get<double>(), report.results[1].eia.rmse, 1e-12);
    EXPECT_TRUE(j["ratios"]["lfdpr_vs_mvr"].is_null());

    const std::string csv = readBytes(dir / "bench.csv");
    EXPECT_EQ(countOf(csv, "\n"), 3u); // header + one row per renderer
    EXPECT_EQ(csv.rfind("renderer,timed,frames,point_generation_ms", 0), 0u);
    EXPECT_NE(csv.find("\nmvr-layered,1,3,"), std::string::npos) << csv;

    const std::string svg = readBytes(dir / "speed_vs_error.svg");
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    EXPECT_EQ(countOf(svg, "<circle"), 2u) << "one point per timed renderer";
    EXPECT_NE(svg.find(">mvr-layered ("), std::string::npos);
    EXPECT_EQ(countOf(svg, "<text"), countOf(svg, "</text>"));
}

TEST_F(BenchTest, FailedWriteLeavesNothingBehind)
{
    std::ostringstream progress;
    std::map<std::string, player::FrameImages> images;
    const BenchReport report = player::runBenchmark(options({"mvr"}), benchProfile(), cubeAndSphereScene(),
                                                    "scene.lfdpack", "test GL", progress, &images);
    const fs::path dir = testOutputDir("bench_failed_write");
    fs::create_directories(dir / "bench.json"); // a directory where the last file goes
    EXPECT_THROW(player::writeBenchOutputs(dir, report, images), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "mvr_eia.png"));
    EXPECT_FALSE(fs::exists(dir / "bench.csv"));
    EXPECT_FALSE(fs::exists(dir / "speed_vs_error.svg"));
}

} // namespace
} // namespace lfd::test
