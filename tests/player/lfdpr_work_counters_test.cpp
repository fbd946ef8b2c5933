// lfdpr's work counters (LfdprOptions::countWork, docs/player/8k-panels.md "Work counters"):
// against a hand-computable scene (one quad on the zero-parallax plane: the same pixels in
// every view, counted here from the frame's own projection), a scene whose footprints
// miss every pixel centre (all point-views culled, nothing written), their invariants on
// an ordinary scene, and equality between runs of what the geometry decides. FrameSync checks that counting adds no
// GL call and no wait.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "renderer_lfdpr.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace lfd::test {
namespace {

using metrics::Image;
using Stats = std::map<std::string, double>;

class LfdprWorkCounters : public GlTest {};

player::LfdprOptions counting(bool pixelCentreCulling = true)
{
    player::LfdprOptions o;
    o.countWork = true;
    o.pixelCentreCulling = pixelCentreCulling;
    return o;
}

double stat(const Stats& stats, const std::string& key)
{
    const auto it = stats.find(key);
    if (it == stats.end()) {
        ADD_FAILURE() << "no " << key;
        return -1.0;
    }
    return it->second;
}

// Window position (GL: x right, y up, pixels) of scene point p in a view.
glm::dvec2 windowOf(const glm::mat4& clipFromScene, const glm::vec3& p, const DisplayProfile& profile)
{
    const glm::dvec4 c = glm::dmat4(clipFromScene) * glm::dvec4(p, 1.0);
    return {(c.x / c.w * 0.5 + 0.5) * profile.viewWidth, (c.y / c.w * 0.5 + 0.5) * profile.viewHeight};
}

// Pixel centres strictly inside the convex quad a, b, c, d (either winding).
int centresInside(const glm::dvec2 q[4], const DisplayProfile& profile)
{
    int n = 0;
    for (uint32_t y = 0; y < profile.viewHeight; ++y) {
        for (uint32_t x = 0; x < profile.viewWidth; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            int positive = 0, negative = 0;
            for (int k = 0; k < 4; ++k) {
                const glm::dvec2 e = q[(k + 1) % 4] - q[k], d = p - q[k];
                const double side = e.x * d.y - e.y * d.x;
                positive += side > 0.0;
                negative += side < 0.0;
            }
            n += positive == 4 || negative == 4;
        }
    }
    return n;
}

// Pixels of a view that differ from its corner pixel (the background there).
int shownPixels(const Image& view)
{
    int n = 0;
    for (uint32_t i = 0; i < view.width * view.height; ++i)
        for (uint32_t c = 0; c < 3; ++c)
            if (view.pixels[i * view.channels + c] != view.pixels[c]) {
                ++n;
                break;
            }
    return n;
}

// The quads scene with only the front quad in sight (the back one moved far outside every
// view): it lies on the zero-parallax plane, so it covers the same pixels in every view.
EmissiveQuads frontQuadOnly()
{
    EmissiveQuads q = emissiveQuadsScene(1.0f, -0.5f);
    q.scene.nodes[1].translation = glm::vec3(100.0f, 0.0f, 0.0f);
    return q;
}

TEST_F(LfdprWorkCounters, OneQuadAtZeroParallaxIsShadedOncePerCoveredPixelAndView)
{
    const EmissiveQuads q = frontQuadOnly();
    const uint32_t views = 6;
    const DisplayProfile profile = smallProfile(views, 96, 72);
    auto renderer = player::createLfdprRenderer(counting());
    const RenderedFrame f = renderFrame(*renderer, q.scene, profile);
    const Stats& s = f.stats;
    ASSERT_EQ(stat(s, "index_repairs"), 0.0) << "a repair shades pixels again";

    // By hand: the quad's corners (half size 0.1) projected with view 0's own matrix; every
    // view shows the same pixels (zero parallax).
    glm::dvec2 corners[4];
    const glm::vec2 offsets[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k)
        corners[k] = windowOf(f.setup.clipFromScene[0], q.frontCenter + glm::vec3(0.1f * offsets[k], 0.0f), profile);
    const int covered = centresInside(corners, profile);
    ASSERT_GT(covered, 20) << "the quad spans several pixels";
    for (uint32_t v = 0; v < views; ++v)
        EXPECT_EQ(shownPixels(f.views[v]), covered) << "view " << v;

    EXPECT_EQ(stat(s, "work_shadings"), double(views) * covered);
    // Every shown pixel was lowered at least once; neighbouring cells overlap, so a pixel
    // may be written (and lowered, by a nearer-or-equal record order) more than once.
    EXPECT_GE(stat(s, "work_words_lowered"), double(views) * covered);
    EXPECT_GE(stat(s, "work_atomics"), stat(s, "work_words_lowered"));
    EXPECT_GE(stat(s, "work_samples"), stat(s, "work_atomics"));
    EXPECT_EQ(stat(s, "work_point_views"), stat(s, "work_points") * views);
    EXPECT_EQ(stat(s, "work_point_views_culled") + stat(s, "work_point_view_setups"), stat(s, "work_point_views"));
    std::printf("[ work     ] quad: %d pixels x %u views; %.0f points, %.0f point-views, %.0f culled (%.0f by "
                "centres), %.0f samples, %.0f atomics, %.0f lowered, %.0f shadings\n",
                covered, views, stat(s, "work_points"), stat(s, "work_point_views"),
                stat(s, "work_point_views_culled"), stat(s, "work_point_views_culled_by_centres"),
                stat(s, "work_samples"), stat(s, "work_atomics"), stat(s, "work_words_lowered"),
                stat(s, "work_shadings"));
}

TEST_F(LfdprWorkCounters, FootprintsBetweenPixelCentresAreCulledBeforeSetup)
{
    // The front quad shrunk to a 1/1000 of its size and moved onto a pixel corner (on the
    // zero-parallax plane, the same corner in every view): its points' footprints hold no
    // pixel centre, so every point-view is culled and nothing is written. Point generation
    // keeps the points (pixel-centre culling off), so the splat sees them.
    EmissiveQuads q = frontQuadOnly();
    const uint32_t views = 6;
    const DisplayProfile profile = smallProfile(views, 96, 72);
    auto probe = player::createLfdprRenderer(counting(false));
    const RenderedFrame framing = renderFrame(*probe, q.scene, profile);
    // The plane z = 0 maps affinely to window coordinates (w is constant on it).
    const glm::mat4& m = framing.setup.clipFromScene[0];
    const glm::dvec2 o = windowOf(m, q.frontCenter, profile);
    const glm::dvec2 dx = windowOf(m, q.frontCenter + glm::vec3(1, 0, 0), profile) - o;
    const glm::dvec2 dy = windowOf(m, q.frontCenter + glm::vec3(0, 1, 0), profile) - o;
    const glm::dvec2 target = glm::round(o) - o; // the nearest pixel corner
    const double det = dx.x * dy.y - dx.y * dy.x;
    const glm::dvec2 move((target.x * dy.y - target.y * dy.x) / det, (dx.x * target.y - dx.y * target.x) / det);
    q.scene.nodes[0].translation = q.frontCenter + glm::vec3(float(move.x), float(move.y), 0.0f);
    q.scene.nodes[0].scale = glm::vec3(1e-3f);

    auto renderer = player::createLfdprRenderer(counting(false));
    const RenderedFrame f = renderFrame(*renderer, q.scene, profile);
    const Stats& s = f.stats;
    ASSERT_GT(stat(s, "work_points"), 0.0);
    EXPECT_EQ(stat(s, "work_point_views_culled"), stat(s, "work_point_views"));
    EXPECT_EQ(stat(s, "work_point_view_setups"), 0.0);
    EXPECT_EQ(stat(s, "work_samples"), 0.0);
    EXPECT_EQ(stat(s, "work_atomics"), 0.0);
    EXPECT_EQ(stat(s, "work_shadings"), 0.0);
    for (uint32_t v = 0; v < views; ++v)
        EXPECT_EQ(shownPixels(f.views[v]), 0) << "view " << v;
}

TEST_F(LfdprWorkCounters, InvariantsHoldAndRunsCountAlike)
{
    const Scene scene = cubeAndSphereScene();
    const uint32_t views = 8;
    const DisplayProfile profile = smallProfile(views, 96, 72);
    auto a = player::createLfdprRenderer(counting());
    const RenderedFrame first = renderFrame(*a, scene, profile, atTurntableAngle(0.6));
    auto b = player::createLfdprRenderer(counting());
    const RenderedFrame second = renderFrame(*b, scene, profile, atTurntableAngle(0.6));
    const Stats& s = first.stats;
    EXPECT_GT(stat(s, "work_point_views_culled"), 0.0);
    EXPECT_EQ(stat(s, "work_point_views_culled") + stat(s, "work_point_view_setups"), stat(s, "work_point_views"));
    EXPECT_LE(stat(s, "work_point_views_culled_by_centres"), stat(s, "work_point_views_culled"));
    EXPECT_LE(stat(s, "work_words_lowered"), stat(s, "work_atomics"));
    EXPECT_LE(stat(s, "work_atomics"), stat(s, "work_samples"));
    if (stat(s, "index_repairs") == 0.0) {
        int shown = 0;
        for (const Image& v : first.views)
            shown += shownPixels(v);
        EXPECT_EQ(stat(s, "work_shadings"), double(shown)) << "one shading per visible view pixel";
    }
    // What the geometry decides is the same in every run; the atomics issued and the words
    // lowered depend on the order the invocations ran in (a plain read sees a word before or
    // after a racing nearer write), and so do the 32-bit path's repairs and their shadings.
    for (const char* key : {"work_points", "work_point_views", "work_point_views_culled",
                            "work_point_views_culled_by_centres", "work_point_view_setups", "work_samples"}) {
        EXPECT_EQ(stat(s, key), stat(second.stats, key)) << key << " differs between two runs of one frame";
    }
    if (stat(s, "index_repairs") == 0.0 && stat(second.stats, "index_repairs") == 0.0) {
        EXPECT_EQ(stat(s, "work_shadings"), stat(second.stats, "work_shadings"));
    }

    // Off (the default): no GPU counters are reported.
    auto plain = player::createLfdprRenderer();
    const RenderedFrame off = renderFrame(*plain, scene, profile, atTurntableAngle(0.6));
    EXPECT_EQ(off.stats.count("work_samples"), 0u);
    EXPECT_EQ(off.stats.count("work_points"), 1u) << "the CPU-side counters stay";
    for (uint32_t v = 0; v < views; ++v)
        EXPECT_EQ(off.views[v].pixels, first.views[v].pixels) << "counting changes no pixel (view " << v << ")";
}

} // namespace
} // namespace lfd::test
