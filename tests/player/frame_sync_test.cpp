// Frames that never wait for the GPU (docs/player/lfdpr.md "Frames that never wait"): in a
// steady-state frame no renderer reads a buffer back, maps one, finishes, waits on a fence or asks
// for a query result before it is available. The test swaps libepoxy's GL entry points for counting
// wrappers (gl::GlCallCounter) and counts the calls of frames 3-10, as lfd-play and lfd-bench
// render them (FramePipeline::renderFrame), for every renderer. It also pins the shape of an lfdpr
// frame: its dispatches and barriers do not grow with the view count.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "frame_pipeline.h"
#include "gl_call_counter.h"
#include "gpu_timer.h"
#include "renderer_registry.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <sstream>

namespace lfd::test {
namespace {

// The tenth-size prototype (a 384x216 panel, so the EIA stays cheap on llvmpipe).
DisplayProfile profileWith(uint32_t views)
{
    return withViews(parseDisplayProfile(tenthPrototypeProfileJson("tenth"), "tenth"), views, 48, 36);
}

std::string describe(const gl::GlCallCounts& c)
{
    std::ostringstream s;
    s << c.dispatches << " dispatches, " << c.draws << " draws, " << c.barriers << " barriers, " << c.syncs
      << " waits";
    for (const auto& [name, n] : c.syncCalls)
        s << " (" << name << " x" << n << ")";
    return s.str();
}

// Frames 0..10 of `renderer`; the calls of frames 3-10.
gl::GlCallCounts steadyFrameCalls(const std::string& name, const Scene& scene, uint32_t views,
                                  player::RendererOptions options = {})
{
    player::FramePipeline pipeline(profileWith(views), scene, 10.0);
    std::unique_ptr<player::Renderer> renderer = player::createRenderer(name, options);
    player::GpuTimer timer;
    for (int k = 0; k < 3; ++k)
        pipeline.renderFrame(*renderer, k / 60.0, timer);
    gl::GlCallCounter counter;
    for (int k = 3; k <= 10; ++k)
        pipeline.renderFrame(*renderer, k / 60.0, timer);
    gl::GlCallCounts calls = counter.counts();
    timer.finish();
    return calls;
}

class FrameSync : public GlTest {};

TEST_F(FrameSync, NoRendererWaitsForTheGpuInSteadyFrames)
{
    const Scene scene = cubeAndSphereScene();
    player::RendererOptions lfdpr32;
    lfdpr32.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    for (const char* name : {"mvr", "mvr-layered", "lfdpr", "lfdpr-paper", "gstd"}) {
        const gl::GlCallCounts calls = steadyFrameCalls(name, scene, 6, lfdpr32);
        EXPECT_EQ(calls.syncs, 0u) << name << ": " << describe(calls);
        EXPECT_GT(calls.dispatches + calls.draws, 0u) << name << ": the counter saw no work";
    }
}

// The view targets' depth array exists only for renderers that rasterise into it: an
// lfdpr frame holds the colours and its own view words, and its reported frame memory is
// the same before and after an mvr frame on the same pipeline allocated the depth array
// (at 72 views of 960x480 that array is 127 MiB; issue 38's memory target).
TEST_F(FrameSync, OnlyRasterRenderersHoldTheDepthArray)
{
    const Scene scene = cubeAndSphereScene();
    const DisplayProfile profile = profileWith(6);
    player::FramePipeline pipeline(profile, scene, 10.0);
    player::GpuTimer timer;
    std::unique_ptr<player::Renderer> lfdpr = player::createRenderer("lfdpr", {});
    std::unique_ptr<player::Renderer> mvr = player::createRenderer("mvr", {});
    const uint64_t colours = uint64_t(6) * 48 * 36 * 4;
    const uint64_t eia = uint64_t(profile.panelWidth) * profile.panelHeight * 4;

    pipeline.renderFrame(*lfdpr, 0.0, timer);
    lfdpr->settle();
    EXPECT_FALSE(pipeline.targets().hasDepth());
    EXPECT_EQ(pipeline.targets().bytes(), colours);
    const uint64_t lfdprBytes = pipeline.frameGpuBytes(*lfdpr);
    EXPECT_EQ(lfdprBytes, colours + eia + lfdpr->frameGpuBytes());
    const std::vector<uint8_t> lfdprView = pipeline.targets().readView(3);

    pipeline.renderFrame(*mvr, 0.0, timer);
    EXPECT_TRUE(pipeline.targets().hasDepth());
    EXPECT_EQ(pipeline.targets().bytes(), 2 * colours); // + D32F, 4 B per view pixel
    EXPECT_EQ(pipeline.frameGpuBytes(*mvr), 2 * colours + eia + mvr->frameGpuBytes());
    EXPECT_EQ(pipeline.frameGpuBytes(*lfdpr), lfdprBytes);

    // lfdpr never reads the depth array: the same frame after mvr's gives the same view.
    pipeline.renderFrame(*lfdpr, 0.0, timer);
    lfdpr->settle();
    EXPECT_TRUE(pipeline.targets().readView(3) == lfdprView);
}

TEST_F(FrameSync, RepairsOnTheThirtyTwoBitPathDoNotWait)
{
    // Every 3rd point stores its record where it lost the depth test, as a lost race
    // would: the repair runs every frame, from counts the GPU keeps.
    player::RendererOptions options;
    options.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    options.lfdpr.testIndexRaces = 3;
    const gl::GlCallCounts calls = steadyFrameCalls("lfdpr", cubeAndSphereScene(), 6, options);
    EXPECT_EQ(calls.syncs, 0u) << describe(calls);
}

TEST_F(FrameSync, LfdprWorkCountersAddNoCallsAndNoWaits)
{
    // The work counters (LfdprOptions::countWork) come back with the point count through the
    // same read-back: a frame that counts makes the same dispatches, barriers and (no) waits.
    const Scene scene = cubeAndSphereScene();
    player::RendererOptions off, on;
    off.lfdpr.atomics = on.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    on.lfdpr.countWork = true;
    const gl::GlCallCounts plain = steadyFrameCalls("lfdpr", scene, 6, off);
    const gl::GlCallCounts counted = steadyFrameCalls("lfdpr", scene, 6, on);
    EXPECT_EQ(plain.dispatches, counted.dispatches) << describe(plain) << " / " << describe(counted);
    EXPECT_EQ(plain.barriers, counted.barriers);
    EXPECT_EQ(plain.draws, counted.draws);
    EXPECT_EQ(counted.syncs, 0u) << describe(counted);
}

TEST_F(FrameSync, LfdprDispatchesAndBarriersDoNotGrowWithViews)
{
    const Scene scene = cubeAndSphereScene();
    player::RendererOptions options;
    options.lfdpr.atomics = player::LfdprOptions::Atomics::TwoPass32;
    for (const char* name : {"lfdpr", "lfdpr-paper"}) {
        const gl::GlCallCounts few = steadyFrameCalls(name, scene, 4, options);
        const gl::GlCallCounts many = steadyFrameCalls(name, scene, 16, options);
        EXPECT_EQ(few.dispatches, many.dispatches) << name << ": 4 views " << describe(few) << "; 16 views "
                                                   << describe(many);
        EXPECT_EQ(few.barriers, many.barriers) << name;
        EXPECT_EQ(few.draws, many.draws) << name;
        std::printf("[ calls    ] %s, 8 frames of 16 views: %s\n", name, describe(many).c_str());
    }
}

TEST_F(FrameSync, TheCounterSeesWaitsAndStopsCounting)
{
    uint64_t before = 0;
    {
        gl::GlCallCounter counter;
        glFinish();
        GLuint query = 0;
        glGenQueries(1, &query);
        glQueryCounter(query, GL_TIMESTAMP);
        GLint available = 0;
        glGetQueryObjectiv(query, GL_QUERY_RESULT_AVAILABLE, &available); // does not wait
        GLuint64 t = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &t); // waits
        glDeleteQueries(1, &query);
        const gl::GlCallCounts c = counter.counts();
        EXPECT_EQ(c.syncs, 2u) << describe(c);
        EXPECT_EQ(c.syncCalls.count("glFinish"), 1u);
        EXPECT_EQ(c.syncCalls.count("glGetQueryObjectui64v"), 1u);
        EXPECT_THROW(gl::GlCallCounter second, std::logic_error);
        before = c.syncs;
    }
    // Uninstalled: GL still works, and a new counter starts from zero.
    glFinish();
    gl::GlCallCounter counter;
    EXPECT_EQ(counter.counts().syncs, 0u);
    glFinish();
    EXPECT_EQ(counter.counts().syncs, 1u);
    EXPECT_EQ(before, 2u);
}

} // namespace
} // namespace lfd::test
