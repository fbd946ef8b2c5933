// PlayerSession: the one place lfd-play (headless and the window) builds renderers. The
// window's R key used to rebuild lfdpr with default options, silently dropping --atomics,
// --lfdpr-pipeline and the --no-* flags; it now goes through the registry with the
// session's options, and these tests would fail if any path bypassed them again.
#include "gl_test_support.h"
#include "test_scenes.h"

#include "player_session.h"
#include "renderer_lfdpr.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace lfd::test {
namespace {

class PlayerSessionTest : public GlTest {};

DisplayProfile sessionProfile()
{
    return withViews(prototypeDisplayProfile(), 4, 32, 24);
}

const player::LfdprRenderer& asLfdpr(player::Renderer& renderer)
{
    const auto* lfdpr = dynamic_cast<const player::LfdprRenderer*>(&renderer);
    if (!lfdpr)
        throw std::runtime_error(renderer.name() + " is not an lfdpr renderer");
    return *lfdpr;
}

TEST_F(PlayerSessionTest, RKeyCycleRebuildsLfdprWithTheUsersOptions)
{
    player::PlayOptions options;
    options.renderer = "lfdpr";
    options.rendererOptions.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    options.rendererOptions.lfdpr.pipeline = player::LfdprOptions::Pipeline::Paper;
    options.rendererOptions.lfdpr.lfdBiasedSampling = false;
    options.rendererOptions.lfdpr.multiviewMipmapping = false;
    player::PlayerSession session(options, sessionProfile(), cubeAndSphereScene(), "scene");

    // The window's cycle: every other interactive renderer, then lfdpr again.
    const std::vector<std::string> cycle = player::windowRendererCycle(options.renderer);
    ASSERT_FALSE(cycle.empty());
    EXPECT_EQ(cycle.back(), "lfdpr");
    EXPECT_EQ(std::count(cycle.begin(), cycle.end(), "gstd"), 0) << "gstd is too slow to cycle into";
    for (const std::string& name : cycle) {
        session.switchRenderer(name);
        EXPECT_EQ(session.rendererName(), name);
        session.renderFrame(0.0);
    }
    const player::LfdprOptions& after = asLfdpr(session.renderer()).options();
    EXPECT_EQ(after.atomics, player::LfdprOptions::Atomics::TwoPass32);
    EXPECT_EQ(after.pipeline, player::LfdprOptions::Pipeline::Paper);
    EXPECT_FALSE(after.lfdBiasedSampling);
    EXPECT_FALSE(after.multiviewMipmapping);
    EXPECT_TRUE(after.textureSplatting);
}

TEST_F(PlayerSessionTest, VariantsStartFromTheUsersOptionsAndChangeOneThing)
{
    player::PlayOptions options;
    options.renderer = "lfdpr-no-texture-splatting";
    options.rendererOptions.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    options.rendererOptions.lfdpr.lfdBiasedSampling = false;
    player::PlayerSession session(options, sessionProfile(), cubeAndSphereScene(), "scene");
    const player::LfdprOptions& o = asLfdpr(session.renderer()).options();
    EXPECT_FALSE(o.textureSplatting);
    EXPECT_FALSE(o.lfdBiasedSampling);
    EXPECT_EQ(o.atomics, player::LfdprOptions::Atomics::TwoPass32);

    // A variant stays in the window's cycle, so R comes back to it.
    const std::vector<std::string> cycle = player::windowRendererCycle(options.renderer);
    EXPECT_EQ(cycle.back(), "lfdpr-no-texture-splatting");
}

TEST_F(PlayerSessionTest, FailedSwitchKeepsTheCurrentRenderer)
{
    player::PlayOptions options;
    options.renderer = "mvr";
    player::PlayerSession session(options, sessionProfile(), cubeAndSphereScene(), "scene");
    EXPECT_THROW(session.switchRenderer("warp-drive"), std::invalid_argument);
    EXPECT_EQ(session.rendererName(), "mvr");
    EXPECT_EQ(session.renderer().name(), "mvr");
}

} // namespace
} // namespace lfd::test

namespace lfd::test {
namespace {

// The responsive preview alternates with full frames in one session: preview frames use
// their own fewer, smaller views and EIA, each renderer follows the size changes, and the
// full-quality frame after a preview is exactly the full frame before it.
TEST_F(PlayerSessionTest, PreviewFramesReturnToTheSameFullQualityFrame)
{
    for (const std::string renderer : {"mvr", "mvr-layered", "lfdpr"}) {
        SCOPED_TRACE(renderer);
        if (renderer == "mvr-layered" && !caps().layerFromVertexShader)
            continue;
        player::PlayOptions options;
        options.renderer = renderer;
        options.turntablePeriod = 0.0;
        const DisplayProfile profile = withViews(prototypeDisplayProfile(), 8, 64, 48);
        player::PlayerSession session(options, profile, cubeAndSphereScene(), "scene");
        session.renderFrame(0.0);
        const std::vector<uint8_t> full = session.eia().read();
        session.renderFrame(0.0, player::FrameQuality::Preview);
        EXPECT_EQ(session.profile().viewCount, 4u);
        EXPECT_EQ(session.targets().width(), 32u);
        const std::vector<uint8_t> preview = session.eia().read();
        EXPECT_EQ(preview.size(), full.size()) << "the preview fills the whole panel";
        EXPECT_FALSE(preview == full);
        session.renderFrame(0.0);
        EXPECT_EQ(session.profile().viewCount, 8u);
        EXPECT_TRUE(session.eia().read() == full);
        session.timer().finish();
        session.previewTimer().finish();
        EXPECT_EQ(session.timer().stages().at("total").ms.size(), 2u);
        EXPECT_EQ(session.previewTimer().stages().at("total").ms.size(), 1u);
    }
}

} // namespace
} // namespace lfd::test
