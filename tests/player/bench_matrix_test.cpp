// lfd-bench's matrix on a small in-memory scene: every renderer x --ss x --aa
// configuration runs and is named, the matrix files hold every configuration, the Pareto
// front is the non-dominated set, the chart is drawn, a stop request keeps what finished,
// and a missing chart tool is reported rather than failing.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "skip_or_fail.h"
#include "test_scenes.h"
#include "tool_run.h"

#include "bench_matrix.h"
#include "bench_runner.h"
#include "frame_stages.h"

#include "lfd/display_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

DisplayProfile matrixProfile() { return tenthPrototypeProfile("matrix-small", 4, 64, 48); }

player::BenchOptions matrixOptions()
{
    player::BenchOptions o;
    o.pack = "scene.lfdpack";
    o.renderers = {"mvr", "lfdpr"};
    o.reference = "mvr";
    o.aa = {player::Reconstruction::None, player::Reconstruction::View};
    o.ss = {player::Supersampling::None, player::Supersampling::Angular2x};
    o.frames = 1;
    o.lensPositions = 3;
    o.warmup = 0;
    o.quiet = true;
    return o;
}

class BenchMatrixTest : public GlTest {};

TEST_F(BenchMatrixTest, RunsEveryConfigurationAndWritesTheMatrix)
{
    std::ostringstream progress;
    player::BenchOptions o = matrixOptions();
    int calls = 0;
    o.onResult = [&](const player::BenchReport& partial) {
        ++calls;
        EXPECT_EQ(partial.results.size(), size_t(calls));
    };
    const player::BenchReport report =
        player::runBenchmark(o, matrixProfile(), cubeAndSphereScene(), "scene.lfdpack", "test GL", progress);
    const std::vector<std::string> names = {"mvr", "mvr+aa-view", "mvr+ss-2v", "mvr+aa-view+ss-2v",
                                            "lfdpr", "lfdpr+aa-view", "lfdpr+ss-2v", "lfdpr+aa-view+ss-2v"};
    ASSERT_EQ(report.results.size(), names.size()); // the reference (mvr) is a timed configuration
    EXPECT_EQ(calls, int(names.size()));
    for (size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(report.results[i].name, names[i]);
        EXPECT_TRUE(report.results[i].timed);
        EXPECT_GT(report.results[i].stageMean(std::string(player::stage::kTotal)), 0.0);
        EXPECT_EQ(report.results[i].stages.count(std::string(player::stage::kDownsample)) == 1,
                  report.results[i].ss == "2v")
            << names[i];
        EXPECT_TRUE(std::isfinite(report.results[i].lens.rmse));
        // The through-the-lens sweep: K positions, the worst at least the mean.
        const auto& sweep = report.results[i].lensSweep;
        ASSERT_EQ(sweep.positions.size(), size_t(o.lensPositions)) << names[i];
        EXPECT_GE(sweep.rmseWorst, sweep.rmseMean);
        EXPECT_LE(sweep.ssimWorst, sweep.ssimMean);
    }
    // The reference against itself is identical at every position; a reconstruction moves
    // the EIA, so mvr with the view filter differs somewhere in the sweep.
    EXPECT_EQ(report.results[0].lensSweep.rmseWorst, 0.0);
    EXPECT_GT(report.results[1].lensSweep.rmseWorst, 0.0);
    // mvr against itself: identical; the reconstruction changes the EIA, not the views.
    EXPECT_EQ(report.results[0].eia.rmse, 0.0);
    EXPECT_GT(report.results[1].eia.rmse, 0.0);
    EXPECT_EQ(report.results[1].centreView.rmse, 0.0);
    // lfdpr keeps its point count under 2v.
    EXPECT_EQ(report.results[4].extraValue("points"), report.results[6].extraValue("points"));
    // Ratios are against mvr with the same reconstruction and supersampling.
    EXPECT_EQ(report.mvrBaseline(report.results[7])->name, "mvr+aa-view+ss-2v");
    EXPECT_EQ(report.mvrBaseline(report.results[6])->name, "mvr+ss-2v");
    EXPECT_EQ(report.mvrBaseline(report.results[5])->name, "mvr+aa-view");

    const fs::path dir = testOutputDir("bench_matrix");
    player::writeMatrixTables(dir, {report});
    const std::string csv = readBytes(dir / "results.csv");
    size_t lines = 0;
    for (char c : csv)
        lines += c == '\n';
    EXPECT_EQ(lines, names.size() + 1);
    EXPECT_NE(csv.find("lfdpr+aa-view+ss-2v,lfdpr,view,2v,1,"), std::string::npos);
    const std::string table = readBytes(dir / "table.md");
    EXPECT_NE(table.find("| scene (tris) | views | method | AA | SS | point gen ms (points)"), std::string::npos);
    EXPECT_NE(table.find("## Pareto front"), std::string::npos);
    const nlohmann::json j = nlohmann::json::parse(readBytes(dir / "results.json"));
    EXPECT_EQ(j["runs"][0]["renderers"].size(), names.size());
    EXPECT_FALSE(j["interrupted"].get<bool>());

    // The front: every configuration on it is not dominated; every one off it is.
    const std::vector<bool> front = player::paretoFront(report);
    const auto t = [&](size_t i) { return report.results[i].stageMean(std::string(player::stage::kTotal)); };
    for (size_t i = 0; i < front.size(); ++i) {
        bool dominated = false;
        for (size_t k = 0; k < front.size(); ++k)
            dominated |= k != i && t(k) <= t(i) && report.results[k].eia.rmse <= report.results[i].eia.rmse &&
                         (t(k) < t(i) || report.results[k].eia.rmse < report.results[i].eia.rmse);
        EXPECT_EQ(front[i], !dominated) << report.results[i].name;
    }

    // The chart, drawn by matplotlib (scripts/setup.sh installs python3-matplotlib): a PNG
    // and an SVG with one labelled point per configuration.
    std::string why;
    if (!player::drawMatrixChart(dir, why))
        LFD_SKIP_OR_FAIL("chart.png not drawn: " << why);
    const std::string png = readBytes(dir / "chart.png");
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    const std::string svg = readBytes(dir / "chart.svg");
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    for (const char* label : {"Pareto front", "mvr", "lfdpr SS 2v"})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST_F(BenchMatrixTest, StopRequestKeepsWhatFinished)
{
    std::ostringstream progress;
    player::BenchOptions o = matrixOptions();
    o.renderers = {"mvr"};
    int finished = 0;
    o.onResult = [&](const player::BenchReport&) { ++finished; };
    o.shouldStop = [&] { return finished >= 2; };
    const player::BenchReport report =
        player::runBenchmark(o, matrixProfile(), cubeAndSphereScene(), "scene.lfdpack", "test GL", progress);
    EXPECT_TRUE(report.interrupted);
    ASSERT_EQ(report.results.size(), 2u);
    EXPECT_EQ(report.results[0].name, "mvr");
    EXPECT_EQ(report.results[1].name, "mvr+aa-view");
}

TEST(BenchMatrix, MissingChartToolIsReportedNotFatal)
{
    const fs::path dir = testOutputDir("bench_matrix_nochart");
    ::setenv("LFD_BENCH_CHART_SCRIPT", "/nonexistent/bench_chart.py", 1);
    std::string why;
    EXPECT_FALSE(player::drawMatrixChart(dir, why));
    ::unsetenv("LFD_BENCH_CHART_SCRIPT");
    EXPECT_NE(why.find("not found"), std::string::npos) << why;
}

} // namespace
} // namespace lfd::test
