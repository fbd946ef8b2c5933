// Determinism of headless renders (issue "proof of robustness"): the same frame rendered
// by two separate lfd-play processes is the same bytes, view for view and in the EIA, for
// every renderer and lfdpr depth path. llvmpipe runs fragments and compute invocations on
// several threads in an order that changes from run to run, so this holds only where the
// method makes every result independent of order: mvr by the depth test (equal depths keep
// the first primitive in draw order), the lfdpr visibility pipeline by its 32-bit tie rule
// (equal depths keep the lowest triangle record); gstd's seeded samples have their own test
// (GstdTest.TwoRunsAreBitIdentical). The paper
// pipeline's 32-bit path writes the colour of any splat whose depth equals the minimum,
// which is order-dependent where two splats of different colour tie; it is held to a
// stated tolerance instead (below).
#include "gl_test_support.h"
#include "test_scenes.h"

#include "image_metrics.h"
#include "lfd/pack.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sys/wait.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

struct Config {
    const char* name;
    const char* flags;
    bool exact; // else: RMSE <= kPaperTieRmse per view
};

// Paper pipeline, 32-bit: a tie between splats of one surface (neighbouring points of the
// same triangle plane) swaps two nearly equal colours; measured 0 on this scene, bounded
// well below anything visible.
constexpr double kPaperTieRmse = 0.5;

class RenderDeterminism : public GlTest {};

TEST_F(RenderDeterminism, TwoProcessesRenderTheSameBytes)
{
    const fs::path dir = testOutputDir("render_determinism");
    const fs::path pack = dir / "scene.lfdpack";
    writePack(pack, cubeAndSphereScene());
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    ASSERT_TRUE(fs::exists(play));
    const Config configs[] = {
        {"mvr", "--renderer mvr", true},
        {"mvr-layered", "--renderer mvr-layered", true},
        {"lfdpr", "--renderer lfdpr --atomics 32", true},
        {"lfdpr-paper", "--renderer lfdpr-paper --atomics 32", false},
    };
    const uint32_t views = 6;
    for (const Config& c : configs) {
        std::vector<fs::path> runs;
        for (int run = 0; run < 2; ++run) {
            const fs::path out = dir / (std::string(c.name) + "_" + std::to_string(run));
            fs::create_directories(out);
            // --frame 1 of 2: the second frame, after the first has filled every buffer once.
            const std::string command = "'" + play.string() + "' --headless '" + pack.string() + "' " + c.flags +
                                        " --views " + std::to_string(views) +
                                        " --view-size 96x72 --frames 2 --frame 1 --views-out '" +
                                        (out / "views").string() + "' --out '" + (out / "eia.png").string() +
                                        "' > /dev/null 2> '" + (out / "err.txt").string() + "'";
            const int raw = std::system(command.c_str());
            ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << c.name << ": " << command;
            runs.push_back(out);
        }
        const metrics::Image eia0 = metrics::readImage(runs[0] / "eia.png", 4);
        const metrics::Image eia1 = metrics::readImage(runs[1] / "eia.png", 4);
        for (uint32_t v = 0; v < views; ++v) {
            char name[32];
            std::snprintf(name, sizeof(name), "views/view_%03u.png", v);
            const metrics::Image a = metrics::readImage(runs[0] / name, 4);
            const metrics::Image b = metrics::readImage(runs[1] / name, 4);
            ASSERT_EQ(a.width, 96u);
            if (c.exact)
                EXPECT_TRUE(a.pixels == b.pixels) << c.name << " view " << v << ": RMSE " << metrics::rmse(a, b);
            else
                EXPECT_LE(metrics::rmse(a, b), kPaperTieRmse) << c.name << " view " << v;
            // Not trivially equal: the view shows the scene, not the background only.
            EXPECT_GT(metrics::rmse(a, metrics::Image{a.width, a.height, 4,
                                                    std::vector<uint8_t>(a.pixels.size(), 0)}),
                      10.0)
                << c.name << " view " << v;
        }
        if (c.exact)
            EXPECT_TRUE(eia0.pixels == eia1.pixels) << c.name << " EIA: RMSE " << metrics::rmse(eia0, eia1);
        else
            EXPECT_LE(metrics::rmse(eia0, eia1), kPaperTieRmse) << c.name << " EIA";
    }
}

} // namespace
} // namespace lfd::test
