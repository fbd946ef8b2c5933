// The direct subpixel splat (renderer lfdpr-direct, docs/player/direct-splat.md) against its
// oracle: its panel image must equal the two-stage lfdpr EIA at --aa none byte for byte
// (the same points, coverage and winners, each view pixel fanned out to the subpixels that
// show it), on small panels whose views have fewer, about as many and more pixels than the
// panel has subpixels, with RGB and BGR stripes, normal and inverted view order and both
// lens slopes. A fan-out that missed a subpixel leaves one wrong channel (the background),
// one that added a subpixel writes a channel from the wrong view: both are counted.
#include "display_test_profiles.h"
#include "gl_test_support.h"
#include "lfdpr_direct_fanout.h"
#include "render_test_util.h"
#include "renderer_registry.h"
#include "test_scenes.h"

#include "lfd/display_profile.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lfd::test {
namespace {

// The prototype scaled down by 8 x 8 ("prototype/8"): a 480 x 270
// panel of 0.1 mm pixels under 59.92 lenses (prototype: 479.36 for 3840 pixels) at the
// prototype's tilt, or the opposite slope (as Looking Glass Portrait-class panels).
DisplayProfile eighthPrototype(uint32_t views, uint32_t width, uint32_t height, double tiltDeg = -9.66)
{
    const std::string json = R"({
        "format": "lfd-display-profile/1",
        "name": "prototype-eighth",
        "panel_width": 480, "panel_height": 270,
        "screen_width_mm": 48.0, "screen_height_mm": 27.0,
        "subpixel_order": "RGB",
        "lens_count": 59.92, "lens_tilt_deg": )" + std::to_string(tiltDeg) + R"(,
        "view_count": 48, "view_width": 60, "view_height": 45,
        "view_cone_deg": 40.0, "viewing_distance_mm": 300.0
    })";
    return withViews(parseDisplayProfile(json, "prototype-eighth.json"), views, width, height);
}

struct ProfileCase {
    const char* name;
    DisplayProfile profile;
};

std::vector<ProfileCase> oracleProfiles()
{
    return {
        {"prototype/8, 48 x 60x45 (V/S 1/3)", eighthPrototype(48, 60, 45)},
        {"tenth prototype, 16 x 48x36 (V/S 1/9)", tenthPrototypeProfile("tenth", 16, 48, 36)},
        {"prototype/8, 48 x 120x90 (V/S 4/3)", eighthPrototype(48, 120, 90)},
        {"BGR, inverted, 24 x 120x45 (V/S 1/3)", player::displaytest::smallProfile("BGR", true)},
        {"other slope sign, 48 x 60x45", eighthPrototype(48, 60, 45, 9.66)},
    };
}

// ---- The inverse map (CPU) ------------------------------------------------------------

TEST(LfdprDirectFanout, ListsEverySubpixelOnceUnderTheViewWordItShows)
{
    for (const ProfileCase& c : oracleProfiles()) {
        const DisplayProfile& p = c.profile;
        const player::LfdprDirectFanout map = player::buildLfdprDirectFanout(p);
        const size_t columns = 3 * size_t(p.panelWidth), subpixels = columns * p.panelHeight;
        ASSERT_EQ(map.offsets.size(), size_t(p.viewCount) * p.viewWidth * p.viewHeight + 1) << c.name;
        ASSERT_EQ(map.subpixels.size(), subpixels) << c.name;
        ASSERT_EQ(map.offsets.back(), subpixels) << c.name;
        std::vector<uint8_t> seen(subpixels, 0);
        size_t wrongWord = 0, repeated = 0, emptyWords = 0;
        for (size_t w = 0; w + 1 < map.offsets.size(); ++w) {
            emptyWords += map.offsets[w] == map.offsets[w + 1] ? 1 : 0;
            for (uint32_t i = map.offsets[w]; i < map.offsets[w + 1]; ++i) {
                const uint32_t s = map.subpixels[i];
                repeated += seen[s]++ ? 1 : 0;
                const uint32_t k = uint32_t(s % columns), l = uint32_t(s / columns);
                wrongWord += player::lfdprDirectViewWord(p, k, l) != w ? 1 : 0;
            }
        }
        EXPECT_EQ(wrongWord, 0u) << c.name;
        EXPECT_EQ(repeated, 0u) << c.name;
        std::printf("[ fan-out  ] %s: %zu subpixels, %zu view pixels, %zu of them feed no subpixel\n", c.name,
                    subpixels, map.offsets.size() - 1, emptyWords);
    }
}

// ---- The oracle: direct-nearest == views + EIA --aa none (GL) ---------------------------

class LfdprDirectTest : public GlTest {};

struct Mismatch {
    size_t bytes = 0;      // differing bytes (alpha included)
    size_t background = 0; // subpixels where exactly one image shows the background level
};

Mismatch compareEia(const metrics::Image& twoStage, const metrics::Image& direct)
{
    Mismatch m;
    constexpr uint8_t kBackgroundLevel = 13; // player::kBackground 0.05, as stored
    for (size_t i = 0; i < twoStage.pixels.size() && i < direct.pixels.size(); ++i) {
        if (twoStage.pixels[i] == direct.pixels[i])
            continue;
        ++m.bytes;
        const bool a = twoStage.pixels[i] == kBackgroundLevel, b = direct.pixels[i] == kBackgroundLevel;
        m.background += (i % 4 != 3 && a != b) ? 1 : 0;
    }
    return m;
}

// Every timed stage of a frame (renderFrame's timer has no "total").
double gpuMs(const RenderedFrame& frame)
{
    double sum = 0.0;
    for (const auto& [stage, ms] : frame.stageMs)
        sum += ms;
    return sum;
}

TEST_F(LfdprDirectTest, NearestEqualsTheTwoStageEiaByteForByte)
{
    struct SceneCase {
        const char* name;
        Scene scene;
    };
    const SceneCase scenes[] = {{"cube and sphere (textured)", cubeAndSphereScene()},
                                {"dense block", denseTestScene()}};
    for (const ProfileCase& p : oracleProfiles()) {
        for (const SceneCase& s : scenes) {
            RenderRequest request = atTurntableAngle(0.6);
            request.eia = true;
            const RenderedFrame twoStage = renderFrame("lfdpr", s.scene, p.profile, request);
            // A frame from another angle first, so a word or plane the clears missed would
            // show in the compared frame.
            const std::unique_ptr<player::Renderer> direct = player::createRenderer("lfdpr-direct");
            renderFrame(*direct, s.scene, p.profile, atTurntableAngle(0.0));
            const RenderedFrame panel = renderFrame(*direct, s.scene, p.profile, request);
            ASSERT_EQ(panel.eia.pixels.size(), twoStage.eia.pixels.size()) << p.name << ", " << s.name;
            EXPECT_EQ(blankReason(twoStage.eia), "") << p.name << ", " << s.name;
            const Mismatch m = compareEia(twoStage.eia, panel.eia);
            std::printf("[ direct   ] %s, %s: %zu mismatching bytes of %zu (%zu subpixels background in one "
                        "image only); GPU ms %.1f two-stage, %.1f direct\n",
                        p.name, s.name, m.bytes, twoStage.eia.pixels.size(), m.background, gpuMs(twoStage),
                        gpuMs(panel));
            EXPECT_EQ(m.bytes, 0u) << p.name << ", " << s.name;
        }
    }
}

// The exact-ray hybrid keeps the nearest mode's visibility (the same words) and only
// shades each winner along the subpixel's own ray: the same subpixels are covered, and the
// colours move, but only by what a fraction of a view interval and of a view pixel moves.
TEST_F(LfdprDirectTest, ExactRayShadesTheNearestWinnersAlongTheirOwnRays)
{
    const DisplayProfile profile = eighthPrototype(48, 60, 45);
    RenderRequest request = atTurntableAngle(0.6);
    request.eia = true;
    const Scene scene = cubeAndSphereScene();
    const RenderedFrame nearest = renderFrame("lfdpr-direct", scene, profile, request);
    const RenderedFrame exact = renderFrame("lfdpr-direct-exact", scene, profile, request);
    ASSERT_EQ(exact.eia.pixels.size(), nearest.eia.pixels.size());
    EXPECT_EQ(blankReason(exact.eia), "");
    const Mismatch m = compareEia(nearest.eia, exact.eia);
    const size_t subpixels = nearest.eia.pixels.size() / 4 * 3;
    const double rmse = metrics::rmse(nearest.eia, exact.eia);
    std::printf("[ exact    ] %zu of %zu bytes differ from nearest (RMSE %.2f levels), %zu subpixels background in "
                "one image only\n",
                m.bytes, nearest.eia.pixels.size(), rmse, m.background);
    EXPECT_GT(m.bytes, subpixels / 100) << "shaded along other rays than the view pixel centres";
    EXPECT_LT(rmse, 10.0);
    // A covered subpixel whose exact-ray colour happens to be the background level is rare.
    EXPECT_LT(m.background, subpixels / 1000);
}

} // namespace
} // namespace lfd::test
