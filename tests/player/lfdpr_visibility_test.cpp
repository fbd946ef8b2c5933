// LFDPR's visibility pipeline (the default): camera-line coherence against hand-worked
// values, the compute point generator against the paper's geometry-shader generator (the
// same points per triangle), per-pixel shading against mvr (it shades like mvr, so the
// bounds are tight), no dropped points after an overflow, and every shader variant -
// including the 64-bit-atomics ones no CI driver can compile - through glslangValidator.
#include "gl_test_support.h"
#include "skip_or_fail.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "frame.h"
#include "gpu_scene.h"
#include "image_metrics.h"
#include "lfdpr_bindings_gpu.h"
#include "lfdpr_camera_line.h"
#include "renderer_lfdpr.h"
#include "renderer_registry.h"
#include "shader_library.h"

#include "lfd/framing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace lfd::test {
namespace {

using metrics::Image;
using player::LfdprOptions;

// ---- Camera-line coherence (CPU) -----------------------------------------------------

player::FrameSetup prototypeFrame(uint32_t views, double time)
{
    const DisplayProfile profile = smallProfile(views, 160, 120);
    SceneBounds bounds;
    bounds.min = glm::vec3(-1.0f);
    bounds.max = glm::vec3(1.0f);
    bounds.center = glm::vec3(0.0f);
    bounds.radius = std::sqrt(3.0f);
    return player::makeFrameSetup(profile, fitSceneToDisplay(profile, bounds), time, 10.0);
}

TEST(LfdprCameraLine, OffsetsAreTheEyeShiftsAndRowsMatchEveryView)
{
    const player::FrameSetup frame = prototypeFrame(48, 1.3);
    const player::LfdprCameraLine line = player::makeLfdprCameraLine(frame);
    ASSERT_EQ(line.viewOffsets.size(), 48u);
    // Hand-worked: view i's eye is at x = D tan(cone ((i + 0.5) / N - 0.5)), y = 0, z = D
    // (display mm), so its offset from view 0 is the difference of the two tangents.
    const double D = frame.profile.viewingDistanceMm, cone = frame.profile.viewConeDeg * 3.14159265358979 / 180.0;
    for (uint32_t i = 0; i < 48; ++i) {
        const double expected = D * (std::tan(cone * ((i + 0.5) / 48.0 - 0.5)) - std::tan(cone * (0.5 / 48.0 - 0.5)));
        EXPECT_NEAR(line.viewOffsets[i], expected, 1e-3 * D) << "view " << i;
        EXPECT_EQ(line.gpu.viewOffsets[i / 4][int(i % 4)], line.viewOffsets[i]);
    }
    // Every view's clip x of a scene point is row0 . p + offset * row0PerOffset . p, and
    // clip y and w are shared.
    for (const glm::vec3 p : {glm::vec3(0.3f, -0.2f, 0.7f), glm::vec3(-0.9f, 0.8f, -0.6f), glm::vec3(0.0f)}) {
        const glm::vec4 h(p, 1.0f);
        for (uint32_t i = 0; i < 48; ++i) {
            const glm::vec4 clip = frame.clipFromScene[i] * h;
            const float x = glm::dot(line.gpu.row0, h) + line.viewOffsets[i] * glm::dot(line.gpu.row0PerOffset, h);
            EXPECT_NEAR(x, clip.x, 1e-4f * (std::abs(clip.w) + 1.0f)) << "view " << i;
            EXPECT_NEAR(glm::dot(line.gpu.row1, h), clip.y, 1e-4f * (std::abs(clip.w) + 1.0f));
            EXPECT_NEAR(glm::dot(line.gpu.row3, h), clip.w, 1e-4f * (std::abs(clip.w) + 1.0f));
        }
    }
    // A point on the screen plane (display z = 0) has zero parallax: no x change per offset.
    const glm::dvec4 onScreen = glm::inverse(frame.displayFromScene) * glm::dvec4(12.0, -7.0, 0.0, 1.0);
    EXPECT_NEAR(glm::dot(line.gpu.row0PerOffset, glm::vec4(onScreen)), 0.0f, 1e-6f);
    // The depth range is the cameras' near and far planes as w.
    EXPECT_GT(line.gpu.wRange.x, 0.0f);
    EXPECT_GT(line.gpu.wRange.y, line.gpu.wRange.x);
    // Pixel-centre culling: without supersampling the sampling rows are the views' rows,
    // and the cone's ends are the eyes at cone positions 0 and 1 (hand-worked as above),
    // at least half a view interval beyond the first and last view.
    EXPECT_EQ(line.gpu.cullRow0, line.gpu.row0);
    EXPECT_EQ(line.gpu.cullRow0PerOffset, line.gpu.row0PerOffset);
    EXPECT_EQ(line.gpu.cullRow3, line.gpu.row3);
    const double tan0 = std::tan(cone * (0.5 / 48.0 - 0.5));
    EXPECT_NEAR(line.gpu.cullOffsets.x, D * (std::tan(-0.5 * cone) - tan0), 1e-3);
    EXPECT_NEAR(line.gpu.cullOffsets.y, D * (std::tan(0.5 * cone) - tan0), 1e-3);
    const float interval = line.viewOffsets[1] - line.viewOffsets[0];
    EXPECT_LE(line.gpu.cullOffsets.x, line.viewOffsets.front() - 0.5f * interval);
    EXPECT_GE(line.gpu.cullOffsets.y, line.viewOffsets.back() + 0.5f * interval);
}

TEST(LfdprCameraLine, RefusesCamerasOffTheLine)
{
    player::FrameSetup frame = prototypeFrame(8, 0.0);
    frame.cameras[3].eye.y += 5.0; // a camera off the line, its matrix unchanged
    EXPECT_THROW(player::makeLfdprCameraLine(frame), std::invalid_argument);
    frame = prototypeFrame(8, 0.0);
    frame.cameras[5].clipFromDisplay[0][0] *= 1.01; // a toed-in / mis-scaled frustum
    EXPECT_THROW(player::makeLfdprCameraLine(frame), std::invalid_argument);
}

// ---- Rendering (GL) ------------------------------------------------------------------

class LfdprVisibilityTest : public GlTest {};

// One frame through the shared harness at turntable angle `angle`, plus what an lfdpr
// renderer reports about it.
struct VisibilityFrame {
    std::vector<Image> views;
    player::LfdprFrameInfo info;
    std::vector<uint32_t> pointsPerTriangle;
};

VisibilityFrame render(player::Renderer& renderer, const Scene& scene, const DisplayProfile& profile, double angle = 0.0)
{
    VisibilityFrame out;
    out.views = renderFrame(renderer, scene, profile, atTurntableAngle(angle)).views;
    if (auto* lfdpr = dynamic_cast<player::LfdprRenderer*>(&renderer)) {
        out.info = lfdpr->lastFrame();
        out.pointsPerTriangle = lfdpr->pointsPerTriangle();
    }
    return out;
}

TEST_F(LfdprVisibilityTest, ComputePointGenerationSamplesLikeTheGeometryShader)
{
    // Same setup code (lfdpr_triangle_setup.glsl) and the same conservative rule, so every
    // triangle gets exactly the points the paper's geometry-shader path gives it.
    const DisplayProfile profile = smallProfile(6, 160, 120);
    for (const Scene& scene : {cubeAndSphereScene(), denseTestScene()}) {
        for (bool lfdSampling : {true, false}) {
            // note: the paper samples every triangle at one point per sampling spacing;
            // pixel-centre culling, the margin trim and cell scaling (beyond the paper) are
            // off here and have their own tests.
            auto visibility = player::createLfdprRenderer(
                {.lfdBiasedSampling = lfdSampling,
                 .pixelCentreCulling = false,
                 .trimSamplingMargin = false,
                 .cellScale = 1});
            auto paper = player::createLfdprRenderer(
                {.pipeline = LfdprOptions::Pipeline::Paper, .lfdBiasedSampling = lfdSampling});
            const VisibilityFrame a = render(*visibility, scene, profile, 0.4);
            const VisibilityFrame b = render(*paper, scene, profile, 0.4);
            ASSERT_GT(a.info.points, 1000u);
            EXPECT_EQ(a.info.points, b.info.points);
            ASSERT_EQ(a.pointsPerTriangle.size(), b.pointsPerTriangle.size());
            size_t differing = 0;
            for (size_t t = 0; t < a.pointsPerTriangle.size(); ++t)
                differing += a.pointsPerTriangle[t] != b.pointsPerTriangle[t];
            EXPECT_EQ(differing, 0u) << "triangles whose point counts differ";
            EXPECT_EQ(std::accumulate(a.pointsPerTriangle.begin(), a.pointsPerTriangle.end(), uint64_t(0)),
                      a.info.points);
        }
    }
}

TEST_F(LfdprVisibilityTest, PixelCentreCullingDropsOnlyPointsThatCanWinNoPixel)
{
    // A triangle that holds no view pixel centre in any view emits no points: none of its
    // points could win a pixel, because a splat writes only centres inside its own
    // triangle. So the views must be byte-identical with and without the culling, and on
    // a dense scene of small triangles (coarse views make them sub-pixel) there must be
    // fewer points. Broken culling (a wrong x range, the offsets of one view only) shows
    // as holes here; no culling at all fails the point count.
    for (const uint32_t width : {96u, 48u}) {
        const DisplayProfile profile = smallProfile(6, width, width * 3 / 4);
        auto culled = player::createLfdprRenderer();
        auto full = player::createLfdprRenderer({.pixelCentreCulling = false});
        for (const double angle : {0.0, 1.3}) {
            const VisibilityFrame a = render(*culled, denseTestScene(), profile, angle);
            const VisibilityFrame b = render(*full, denseTestScene(), profile, angle);
            ASSERT_GT(b.info.points, 1000u);
            EXPECT_LT(a.info.points, b.info.points) << width << " px wide views";
            EXPECT_LT(a.info.triangles, b.info.triangles);
            for (uint32_t v = 0; v < profile.viewCount; ++v)
                EXPECT_EQ(a.views[v].pixels, b.views[v].pixels) << "view " << v << ", " << width << " px";
            std::printf("pixel-centre culling, %u px views, angle %.1f: points %llu -> %llu, triangles %llu -> %llu\n",
                        width, angle, (unsigned long long)b.info.points, (unsigned long long)a.info.points,
                        (unsigned long long)b.info.triangles, (unsigned long long)a.info.triangles);
        }
    }
}

TEST_F(LfdprVisibilityTest, MarginTrimKeepsTheViewsAndCutsThePoints)
{
    // The sampling box's low margin row and column lie outside the triangle and only touch
    // it; without them a sub-pixel triangle keeps one point instead of three or four. So
    // the views must be byte-identical with and without the margin, with far fewer points on
    // the dense scene (sub-pixel triangles at these sizes). At 48 px a sub-pixel triangle
    // sits at the corner of its one remaining cell, which is many times its size; unclipped
    // to the triangle's box, that cell reached behind a camera in some views, its point was
    // dropped, and only a margin cell had covered the pixel (a hole here, found so).
    // Sampling the margin anyway fails the count. Both work shapes: the GPU one tests the
    // cell's pixel centres before the setup and caps a cell's pixels, with the same slack.
    for (const auto shape : {LfdprOptions::WorkShape::Cpu, LfdprOptions::WorkShape::Gpu}) {
        for (const uint32_t width : {160u, 48u}) {
            const DisplayProfile profile = smallProfile(6, width, width * 3 / 4);
            auto trimmed = player::createLfdprRenderer({.workShape = shape});
            auto margin = player::createLfdprRenderer({.trimSamplingMargin = false, .workShape = shape});
            for (const Scene& scene : {cubeAndSphereScene(), denseTestScene()}) {
                for (const double angle : {0.0, 1.3}) {
                    const VisibilityFrame a = render(*trimmed, scene, profile, angle);
                    const VisibilityFrame b = render(*margin, scene, profile, angle);
                    ASSERT_GT(a.info.points, 100u);
                    EXPECT_LT(a.info.points, b.info.points) << width << " px wide views";
                    for (uint32_t v = 0; v < profile.viewCount; ++v)
                        EXPECT_EQ(a.views[v].pixels, b.views[v].pixels) << "view " << v << ", " << width << " px";
                    std::printf("margin trim, %s work shape, %u px views, angle %.1f, %zu triangles: points %llu -> %llu\n",
                                shape == LfdprOptions::WorkShape::Gpu ? "GPU" : "CPU", width, angle,
                                scene.indices.size() / 3, (unsigned long long)b.info.points,
                                (unsigned long long)a.info.points);
                }
            }
        }
    }
}

TEST_F(LfdprVisibilityTest, CellScalingKeepsTheViewsAndCutsThePoints)
{
    // Cells of k x k sampling spacings: a pixel is shaded from its winning point's triangle
    // at its own centre, and a splat writes only centres inside that triangle, so the
    // views must be byte-identical for every k, with fewer points where triangles span
    // several cells (the cube's faces) - and never a hole, which too large a cell that the
    // splat did not fully cover would leave.
    const DisplayProfile profile = smallProfile(6, 160, 120);
    for (const Scene& scene : {cubeAndSphereScene(), denseTestScene()}) {
        auto paper = player::createLfdprRenderer({.cellScale = 1});
        const VisibilityFrame reference = render(*paper, scene, profile, 0.7);
        for (const uint32_t scale : {2u, 3u}) {
            auto scaled = player::createLfdprRenderer({.cellScale = scale});
            const VisibilityFrame f = render(*scaled, scene, profile, 0.7);
            EXPECT_LT(f.info.points, reference.info.points) << "cell scale " << scale;
            std::printf("cell scale %u: %llu -> %llu points\n", scale, (unsigned long long)reference.info.points,
                        (unsigned long long)f.info.points);
            for (uint32_t v = 0; v < profile.viewCount; ++v)
                EXPECT_EQ(f.views[v].pixels, reference.views[v].pixels) << "view " << v << ", cell scale " << scale;
        }
    }
}

TEST_F(LfdprVisibilityTest, ShadesLikeMvr)
{
    // Per-pixel shading with mvr's material function and textureGrad at the pixel's
    // footprint: differences are left only where a splat boundary picks a different
    // surface than the rasteriser at a silhouette (the coverage rule itself is the
    // rasteriser's: DecidesEdgePixelsAsTheRasteriser), and from exact versus
    // quad-difference texture gradients. Measured on llvmpipe: SSIM >=
    // 0.998, RMSE <= 1.5, holes 0. (The paper's per-splat shading: SSIM ~0.97, RMSE ~5.)
    const DisplayProfile profile = smallProfile(6, 160, 120);
    for (const Scene& scene : {cubeAndSphereScene(), denseTestScene()}) {
        auto lfdpr = player::createLfdprRenderer();
        auto mvr = player::createRenderer("mvr");
        const VisibilityFrame a = render(*lfdpr, scene, profile, 0.9);
        const VisibilityFrame b = render(*mvr, scene, profile, 0.9);
        CoverageStats coverage;
        for (uint32_t v = 0; v < profile.viewCount; ++v) {
            EXPECT_GT(metrics::ssim(a.views[v], b.views[v]), 0.99) << "view " << v;
            EXPECT_LT(metrics::rmse(a.views[v], b.views[v]), 3.0) << "view " << v;
            coverage += compareCoverage(b.views[v], a.views[v]);
        }
        EXPECT_GT(coverage.covered, size_t(1000));
        EXPECT_LT(coverage.holeRate(), 0.005);
        if (HasFailure()) {
            const std::filesystem::path dir = testOutputDir("lfdpr_visibility_shades_like_mvr");
            for (uint32_t v = 0; v < profile.viewCount; ++v) {
                metrics::writeImage(dir / ("view" + std::to_string(v) + "_lfdpr.png"), a.views[v]);
                metrics::writeImage(dir / ("view" + std::to_string(v) + "_mvr.png"), b.views[v]);
                metrics::writeDiffImage(dir / ("view" + std::to_string(v) + "_diff.png"), a.views[v], b.views[v]);
            }
            FAIL() << "images in " << dir;
        }
    }
}

// Pixels whose colour differs from the reference's by at least 48 in some channel: a
// different surface (or the background) won there, not a shading difference.
size_t surfaceChanges(const Image& test, const Image& reference)
{
    size_t changed = 0;
    for (size_t i = 0; i + 3 < test.pixels.size(); i += test.channels) {
        int most = 0;
        for (size_t c = 0; c < 3; ++c)
            most = std::max(most, std::abs(int(test.pixels[i + c]) - int(reference.pixels[i + c])));
        changed += most >= 48 ? 1 : 0;
    }
    return changed;
}

TEST_F(LfdprVisibilityTest, DecidesEdgePixelsAsTheRasteriser)
{
    // lfdpr snaps window positions to the rasteriser's sub-pixel grid and breaks ties with
    // its left / bottom-edge rule, so the pixel centres within a sub-pixel of an edge -
    // where float edge functions and the rasteriser's fixed point disagree - go to the same
    // triangle as mvr's, silhouettes included. Measured on llvmpipe over these 16 views of
    // the dense block and the cube-and-sphere: 0 changed pixels (without the snap and the
    // rule: 11).
    const DisplayProfile profile = smallProfile(8, 160, 120);
    size_t changed = 0, covered = 0;
    for (const Scene& scene : {cubeAndSphereScene(), denseTestScene()}) {
        auto lfdpr = player::createLfdprRenderer();
        auto mvr = player::createRenderer("mvr");
        const VisibilityFrame a = render(*lfdpr, scene, profile, 0.4);
        const VisibilityFrame b = render(*mvr, scene, profile, 0.4);
        for (uint32_t v = 0; v < profile.viewCount; ++v) {
            changed += surfaceChanges(a.views[v], b.views[v]);
            covered += compareCoverage(b.views[v], a.views[v]).covered;
        }
    }
    std::printf("pixels where another surface won: %zu of %zu covered\n", changed, covered);
    EXPECT_GT(covered, size_t(10000));
    EXPECT_LE(changed, size_t(2));
}

TEST_F(LfdprVisibilityTest, OverflowGrowsAndTheFrameIsRenderedAgain)
{
    // The renderer learns of an overflow from counts read back without waiting (frames
    // later); the harness, as lfd-play and lfd-bench before reading outputs, settles it and
    // renders a frame that overflowed again with the grown buffer.
    const Scene scene = cubeAndSphereScene();
    const DisplayProfile profile = smallProfile(4, 96, 72);
    auto roomy = player::createLfdprRenderer();
    auto tight = player::createLfdprRenderer({.initialPointCapacity = 64});
    const VisibilityFrame a = render(*roomy, scene, profile);
    const VisibilityFrame b = render(*tight, scene, profile);
    EXPECT_EQ(a.info.bufferGrowths, 0u);
    EXPECT_GE(b.info.bufferGrowths, 1u);
    EXPECT_FALSE(b.info.overflowed) << "the frame was redone with room for every point";
    EXPECT_EQ(b.info.points, a.info.points);
    EXPECT_GE(b.info.pointCapacity, b.info.points);
    for (uint32_t v = 0; v < profile.viewCount; ++v)
        EXPECT_EQ(metrics::maxAbsDiff(a.views[v], b.views[v]), 0) << "view " << v;

    EXPECT_EQ(b.info.overflowFrames, 1u) << "the first render lost points and is counted";

    // At its cap the buffer stops growing: the frame keeps what fits and says so (it
    // overflowed at 16 points, was rendered again at the cap of 64 and overflowed again:
    // both renders are counted).
    auto capped = player::createLfdprRenderer({.initialPointCapacity = 16, .maxPointCapacity = 64});
    const VisibilityFrame c = render(*capped, scene, profile);
    EXPECT_TRUE(c.info.overflowed);
    EXPECT_EQ(c.info.pointCapacity, 64u);
    EXPECT_EQ(c.info.pointsStored, 64u);
    EXPECT_EQ(c.info.overflowFrames, 2u);
}

TEST_F(LfdprVisibilityTest, PointBufferSizedAtLoadSoTheFirstFrameDoesNotOverflow)
{
    // The default capacity (0) is sized from a count-only run of point generation for the
    // scene's first frame: that frame keeps every point, and the buffer is not far above
    // what it needs (1.5 x the count; measured here on llvmpipe: ratio 1.50).
    const Scene scene = denseTestScene();
    const DisplayProfile profile = smallProfile(8, 160, 120);
    auto renderer = player::createLfdprRenderer();
    const VisibilityFrame a = render(*renderer, scene, profile, 0.4);
    EXPECT_EQ(a.info.overflowFrames, 0u);
    EXPECT_EQ(a.info.bufferGrowths, 0u);
    EXPECT_GT(a.info.points, 5000u) << "a moderately dense scene";
    EXPECT_EQ(a.info.points, a.info.pointsStored);
    EXPECT_EQ(a.info.sizedPoints, a.info.points) << "the count-only run counts as the frame does";
    EXPECT_GE(a.info.pointCapacity, a.info.points);
    EXPECT_LE(double(a.info.pointCapacity), 2.0 * double(a.info.points));
    std::printf("first frame: %llu points, capacity %u (%.2fx)\n", (unsigned long long)a.info.points,
                a.info.pointCapacity, double(a.info.pointCapacity) / double(a.info.points));
}

TEST_F(LfdprVisibilityTest, WorkCountersAreConsistent)
{
    // lfdpr's work counters (extraStats, so lfd-bench's bench.json and lfd-play --stats):
    // every stored point is splatted into every view, and the bytes cleared are the view
    // words (8 B), the RGBA8 views and the small per-frame words; mvr's are its RGBA8 and
    // D32F targets and its triangles x views.
    const Scene scene = cubeAndSphereScene();
    const uint32_t views = 6, width = 96, height = 72;
    const DisplayProfile profile = smallProfile(views, width, height);
    auto value = [](const player::Renderer& r, const std::string& key) {
        for (const auto& [name, v] : r.extraStats())
            if (name == key)
                return v;
        ADD_FAILURE() << "no " << key;
        return -1.0;
    };
    auto lfdpr = player::createLfdprRenderer();
    const VisibilityFrame a = render(*lfdpr, scene, profile);
    const double points = value(*lfdpr, "work_points");
    EXPECT_GT(points, 0.0);
    EXPECT_EQ(points, double(a.info.pointsStored));
    EXPECT_EQ(value(*lfdpr, "work_point_views"), points * views);
    const double viewBytes = double(views) * width * height * (8 + 4);
    const double cleared = value(*lfdpr, "work_bytes_cleared");
    EXPECT_GE(cleared, viewBytes);
    EXPECT_LE(cleared, viewBytes + double(value(*lfdpr, "shade_work_bytes")) + 4096.0);
    std::printf("lfdpr: %.0f points, %.0f point-views, %.0f bytes cleared (views: %.0f)\n", points,
                value(*lfdpr, "work_point_views"), cleared, viewBytes);

    auto mvr = player::createRenderer("mvr");
    render(*mvr, scene, profile);
    EXPECT_EQ(value(*mvr, "work_bytes_cleared"), double(views) * width * height * 8);
    EXPECT_GT(value(*mvr, "work_triangle_views"), 0.0);
    EXPECT_EQ(std::fmod(value(*mvr, "work_triangle_views"), double(views)), 0.0);
    std::printf("mvr: %.0f triangle-views\n", value(*mvr, "work_triangle_views"));
}

TEST_F(LfdprVisibilityTest, CompactPointsAndReportedMemory)
{
    auto renderer = player::createLfdprRenderer();
    const DisplayProfile profile = smallProfile(4, 96, 72);
    const VisibilityFrame f = render(*renderer, cubeAndSphereScene(), profile);
    EXPECT_EQ(f.info.bytesPerPoint, 8u);
    EXPECT_EQ(f.info.viewBufferBytes, 4u * 96u * 72u * 8u); // depth + index
    EXPECT_GT(f.info.triangleBufferBytes, 0u);
    EXPECT_LE(f.info.triangles, f.info.points) << "one record per emitting triangle";
    std::map<std::string, double> stats;
    for (const auto& [key, value] : renderer->extraStats())
        stats[key] = value;
    for (const char* key : {"points", "bytes_per_point", "point_buffer_bytes", "triangle_buffer_bytes",
                            "view_buffer_bytes", "shade_work_bytes", "frame_gpu_bytes", "point_buffer_growths",
                            "index_repairs", "tie_points", "shading_passes"})
        EXPECT_TRUE(stats.count(key)) << key;
    EXPECT_EQ(stats["frame_gpu_bytes"], stats["point_buffer_bytes"] + stats["triangle_buffer_bytes"] +
                                            stats["view_buffer_bytes"] + stats["shade_work_bytes"]);
    // The shading work: per group a dispatch, and a tile list over 8 x 8 tiles of every
    // view (12 x 9 tiles per view here) - a small fraction of the per-pixel buffers.
    EXPECT_GT(stats["shade_work_bytes"], 0.0);
    EXPECT_LT(stats["shade_work_bytes"], 0.5 * stats["view_buffer_bytes"] + 8192.0);
    EXPECT_GE(stats["shading_passes"], 1.0);
}

// The 32-bit path's index repair: a pixel whose stored index lost a race to a nearer
// point is flagged in the shading pass, the index pass runs, and the pixel is classified
// and shaded again - from the list of its tiles when the list holds them all, else by a
// whole-frame pass. Races are forced here (LfdprOptions::testIndexRaces: every n-th point
// also stores its index where it lost), and the views must come out byte-identical to an
// unforced frame on every path: a few repairs (the index pass runs only the points that
// reach a listed chunk: at most LFDPR_REPAIR_FILTER_MAX of them), more (every point, the
// list) and more than the list holds (one entry per tile chunk: 12 x 9 tiles of one 6-view
// chunk = 108 here).
TEST_F(LfdprVisibilityTest, IndexRepairRestoresTheImageFromTheListAndTheWholeFrame)
{
    const DisplayProfile profile = smallProfile(6, 96, 72);
    const Scene scene = denseTestScene();
    auto clean = player::createLfdprRenderer({.atomics = LfdprOptions::Atomics::TwoPass32});
    const VisibilityFrame reference = render(*clean, scene, profile, 0.6);
    ASSERT_EQ(reference.info.repairs, 0u) << "the unforced frame needs no repair here";
    const uint32_t filterMax = player::lfdpr_bindings::kRepairFilterMax;
    bool filtered = false, listed = false, wholeFrame = false;
    // How many forced races land where a point lost depends on the threads' timing (measured
    // over runs: every 1009th point 0-17 repairs, 61st 53-72, 41st 68-106, 31st 86-114, 3rd
    // 680-1116), so several rates cover the three paths between them.
    for (const uint32_t every : {1009u, 499u, 251u, 61u, 41u, 37u, 31u, 3u}) {
        auto racy = player::createLfdprRenderer({.atomics = LfdprOptions::Atomics::TwoPass32, .testIndexRaces = every});
        const VisibilityFrame a = render(*racy, scene, profile, 0.6);
        std::printf("every %u-th point racing: %llu repairs\n", every, (unsigned long long)a.info.repairs);
        filtered = filtered || (a.info.repairs > 0 && a.info.repairs <= filterMax);
        listed = listed || (a.info.repairs > filterMax && a.info.repairs <= 108);
        wholeFrame = wholeFrame || a.info.repairs > 108;
        for (uint32_t v = 0; v < profile.viewCount; ++v)
            EXPECT_EQ(a.views[v].pixels, reference.views[v].pixels) << "view " << v << ", every " << every;
    }
    EXPECT_TRUE(filtered) << "no case exercised the index pass's point filter";
    EXPECT_TRUE(listed) << "no case exercised the repair list with every point";
    EXPECT_TRUE(wholeFrame) << "no case exercised the whole-frame repair";
}

// Two copies of one tessellated plane, a red one drawn first and a green one drawn second,
// meet at the same depth key in every pixel they cover: a depth tie, as coincident surfaces
// (a decal on its wall, a duplicated mesh) give. mvr's depth test keeps the triangle drawn
// first. lfdpr's words keep the lower record where they order records (the 64-bit word; the
// direct splat's record pass, which runs on the 32-bit path too), and records are numbered
// by drawn triangle, so there it must too, however its invocations run. The red copy is
// alpha-masked (a cutoff of 0 that drops nothing), which puts it in a later point generation
// dispatch than the green one: its records were written second, so numbering them in the
// order they were written shows green here. The views path's single 32-bit pass queues the
// points that met a tie for the tie pass, which keeps the lower record, on the GPU work
// shape; llvmpipe's CPU work shape keeps the first point to arrive (docs/player/lfdpr.md,
// Depth ties). Each is run twice (which point reaches a word first changes between runs;
// before the tie pass, 3 subpixels of the third-party DamagedHelmet's EIA did).
TEST_F(LfdprVisibilityTest, DepthTiesGoToTheTriangleDrawnFirstAsInMvr)
{
    const DisplayProfile profile = smallProfile(6, 96, 72);
    Scene scene;
    for (const glm::vec3 emissive : {glm::vec3(0.9f, 0.05f, 0.05f), glm::vec3(0.05f, 0.9f, 0.05f)})
        scene.materials.push_back(emissiveOnlyMaterial(emissive));
    scene.materials[0].alphaMode = AlphaMode::Mask;
    scene.materials[0].alphaCutoff = 0.0f;
    const glm::quat tilt = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1.0f, 0.4f, 0.0f)));
    for (int32_t copy = 0; copy < 2; ++copy) {
        const int32_t mesh = addMesh(scene, addGrid(scene, 1.0f, 6, 1.0f), copy);
        addNode(scene, mesh, glm::vec3(0.0f), tilt, glm::vec3(1.0f));
    }
    finishScene(scene);
    scene.bounds.min = glm::vec3(-1.0f);
    scene.bounds.max = glm::vec3(1.0f);
    scene.bounds.center = glm::vec3(0.0f);
    scene.bounds.radius = std::sqrt(3.0f);
    // Red-lit and green-lit subpixels (values on the 8-bit scale; the other channel is dim).
    auto count = [](const Image& image, size_t& covered, size_t& green) {
        for (size_t i = 0; i + 2 < image.pixels.size(); i += image.channels) {
            covered += image.pixels[i] > 100;
            green += image.pixels[i + 1] > 100;
        }
    };

    RenderRequest request = atTurntableAngle(0.0);
    request.eia = true;
    const RenderedFrame mvr = renderFrame("mvr", scene, profile, request);
    size_t mvrCovered = 0, mvrGreen = 0;
    count(mvr.eia, mvrCovered, mvrGreen);
    ASSERT_EQ(mvrGreen, 0u) << "mvr keeps the copy drawn first";
    ASSERT_GT(mvrCovered, mvr.eia.pixels.size() / 4 / 20) << "the planes cover under a twentieth of the panel";

    // The direct splat: its 32-bit record pass keeps the lowest record at the nearest key.
    for (int run = 0; run < 2; ++run) {
        const RenderedFrame direct = renderFrame("lfdpr-direct", scene, profile, request);
        size_t covered = 0, green = 0;
        count(direct.eia, covered, green);
        std::printf("depth ties, lfdpr-direct, run %d: %zu red subpixels (mvr %zu), %zu green\n", run, covered,
                    mvrCovered, green);
        EXPECT_EQ(green, 0u) << "the copy drawn second won depth ties";
        EXPECT_LT(metrics::rmse(direct.eia, mvr.eia), 3.0);
    }
    // The views path: the 64-bit word where the driver has it, and the 32-bit pass with its
    // tie pass, on both work shapes.
    const VisibilityFrame expected = render(*player::createRenderer("mvr"), scene, profile);
    for (const auto atomics : {LfdprOptions::Atomics::Auto, LfdprOptions::Atomics::TwoPass32}) {
        if (atomics == LfdprOptions::Atomics::Auto && !player::lfdprUseInt64(atomics))
            continue; // Auto is the 32-bit pass here, run below
        for (const auto shape : {LfdprOptions::WorkShape::Cpu, LfdprOptions::WorkShape::Gpu}) {
            for (int run = 0; run < 2; ++run) {
                auto lfdpr = player::createLfdprRenderer({.workShape = shape, .atomics = atomics});
                const VisibilityFrame a = render(*lfdpr, scene, profile);
                std::printf("depth ties, views path, %s atomics, %s work shape, run %d: %llu points queued at "
                            "a tie\n",
                            a.info.int64Atomics ? "64-bit" : "32-bit",
                            shape == LfdprOptions::WorkShape::Cpu ? "CPU" : "GPU", run,
                            (unsigned long long)a.info.tiePoints);
                if (!a.info.int64Atomics && shape == LfdprOptions::WorkShape::Cpu) {
                    EXPECT_EQ(a.info.tiePoints, 0u) << "the CPU work shape has no tie pass";
                    continue; // the first point to arrive keeps a tied word
                }
                if (!a.info.int64Atomics) {
                    EXPECT_GT(a.info.tiePoints, 0u) << "the 32-bit pass queued no point for the tie pass";
                }
                for (uint32_t v = 0; v < profile.viewCount; ++v) {
                    size_t covered = 0, green = 0;
                    count(a.views[v], covered, green);
                    EXPECT_EQ(green, 0u) << "view " << v << (a.info.int64Atomics ? ", 64-bit" : ", 32-bit");
                    EXPECT_LT(metrics::rmse(a.views[v], expected.views[v]), 2.0) << "view " << v;
                }
            }
        }
    }
    // A tie queue too short for the planes' points: the points past it have their tile
    // chunks repaired instead, to the same image.
    auto shortQueue = player::createLfdprRenderer({.workShape = LfdprOptions::WorkShape::Gpu,
                                                   .atomics = LfdprOptions::Atomics::TwoPass32,
                                                   .testTieCapacity = 64});
    const VisibilityFrame a = render(*shortQueue, scene, profile);
    std::printf("depth ties, a queue of 64 points: %llu points met a tie, %llu repairs\n",
                (unsigned long long)a.info.tiePoints, (unsigned long long)a.info.repairs);
    EXPECT_GT(a.info.tiePoints, 64u) << "the queue did not overflow";
    EXPECT_GT(a.info.repairs, 0u) << "the points past the queue listed no chunk";
    for (uint32_t v = 0; v < profile.viewCount; ++v) {
        size_t covered = 0, green = 0;
        count(a.views[v], covered, green);
        EXPECT_EQ(green, 0u) << "view " << v << ", short tie queue";
    }
}

// Shading visits only the tiles that hold a pixel of each group: a scene of several
// textured and untextured materials must come out as mvr draws it, with one shading
// dispatch per group, and pixels of a material must not be shaded with another's
// textures (a tile holding two materials is listed for both, each shading its own).
TEST_F(LfdprVisibilityTest, ShadingGroupsShadeEachMaterialWithItsOwnTextures)
{
    const DisplayProfile profile = smallProfile(4, 96, 72);
    // Two textured materials side by side (the cube's checker and a second, green-white
    // checker on the sphere, with an emissive texture), plus untextured ones.
    Scene scene = cubeAndSphereScene();
    scene.textures.push_back(checkerTexture(64, 4, {30, 200, 60, 255}, {240, 240, 240, 255}, true));
    scene.materials[1].baseColorTexture = int32_t(scene.textures.size() - 1);
    scene.materials[1].emissiveTexture = int32_t(scene.textures.size() - 1);
    scene.materials[1].emissiveFactor = {0.2f, 0.2f, 0.2f};
    finishScene(scene);
    auto lfdpr = player::createLfdprRenderer();
    auto mvr = player::createRenderer("mvr");
    const VisibilityFrame a = render(*lfdpr, scene, profile);
    const VisibilityFrame b = render(*mvr, scene, profile);
    std::map<std::string, double> stats;
    for (const auto& [key, value] : lfdpr->extraStats())
        stats[key] = value;
    size_t textured = 0;
    for (const Material& m : scene.materials)
        textured += player::materialTextureFlags(m) != 0;
    EXPECT_EQ(textured, 2u);
    // The untextured group + one per textured material, per pass: on the 32-bit path the
    // repair pass dispatches every group too (with zero workgroups when nothing raced).
    const double passes = lfdpr->lastFrame().int64Atomics ? 1.0 : 2.0;
    EXPECT_EQ(stats["shading_passes"], double(textured + 1) * passes)
        << "untextured group + one per textured material, per pass";
    for (size_t v = 0; v < a.views.size(); ++v) {
        EXPECT_GT(metrics::ssim(a.views[v], b.views[v]), 0.99) << "view " << v;
        EXPECT_LT(metrics::rmse(a.views[v], b.views[v]), 3.0) << "view " << v;
    }
}

TEST_F(LfdprVisibilityTest, Int64AndSingle32BitPassGiveTheSameImage)
{
    if (!caps().int64Atomics)
        GTEST_SKIP() << "GL_NV_shader_atomic_int64 absent (" << caps().renderer
                     << "): only the 32-bit path runs here; glslangValidator checks the 64-bit shaders";
    const Scene scene = denseTestScene();
    const DisplayProfile profile = smallProfile(4, 160, 120);
    auto r64 = player::createLfdprRenderer({.atomics = LfdprOptions::Atomics::Int64});
    auto r32 = player::createLfdprRenderer({.atomics = LfdprOptions::Atomics::TwoPass32});
    const VisibilityFrame a = render(*r64, scene, profile);
    const VisibilityFrame b = render(*r32, scene, profile);
    for (uint32_t v = 0; v < profile.viewCount; ++v)
        EXPECT_EQ(metrics::maxAbsDiff(a.views[v], b.views[v]), 0) << "view " << v;
}

// Alpha-masked materials (glTF MASK): cells whose alpha is below the cutoff emit no
// point (point generation compiles that test in only for draws of masked materials): a
// checker whose every other square is transparent keeps about half the cube's points, the
// holes show, and they match mvr's where the cut-out squares are large enough to be
// resolved (both sample alpha differently at the squares' minified edges: mvr per pixel
// centre, lfdpr per sampling cell).
TEST_F(LfdprVisibilityTest, AlphaMaskedCellsEmitNoPointsAndShowTheirHoles)
{
    const DisplayProfile profile = smallProfile(4, 192, 144);
    Scene opaque = cubeAndSphereScene();
    opaque.textures[0] = checkerTexture(128, 32, {230, 200, 60, 255}, {40, 60, 160, 0}, true);
    finishScene(opaque);
    Scene masked = opaque;
    masked.materials[0].alphaMode = AlphaMode::Mask;
    masked.materials[0].alphaCutoff = 0.5f;

    // The paper's density for both (alpha-masked cells always keep it), so the point
    // counts compare.
    auto lfdpr = player::createLfdprRenderer({.cellScale = 1});
    auto mvr = player::createRenderer("mvr");
    const VisibilityFrame solid = render(*lfdpr, opaque, profile);
    const VisibilityFrame cut = render(*lfdpr, masked, profile);
    const VisibilityFrame reference = render(*mvr, masked, profile);
    ASSERT_EQ(cut.pointsPerTriangle.size(), solid.pointsPerTriangle.size());
    uint64_t cubeSolid = 0, cubeCut = 0, othersSolid = 0, othersCut = 0;
    const size_t cubeTriangles = 12; // the first draw: the checker cube
    for (size_t t = 0; t < cut.pointsPerTriangle.size(); ++t) {
        (t < cubeTriangles ? cubeSolid : othersSolid) += solid.pointsPerTriangle[t];
        (t < cubeTriangles ? cubeCut : othersCut) += cut.pointsPerTriangle[t];
    }
    EXPECT_NEAR(double(cubeCut) / double(cubeSolid), 0.5, 0.15) << "half the checker is transparent";
    EXPECT_EQ(othersCut, othersSolid) << "opaque materials keep every point";
    for (size_t v = 0; v < cut.views.size(); ++v) {
        EXPECT_GT(metrics::ssim(cut.views[v], reference.views[v]), 0.9) << "view " << v;
        EXPECT_LT(metrics::rmse(cut.views[v], reference.views[v]), 12.0) << "view " << v;
        EXPECT_GT(metrics::rmse(cut.views[v], solid.views[v]), 2.0) << "the holes must show, view " << v;
    }
    const std::filesystem::path dir = testOutputDir("alpha_mask");
    metrics::writeImage(dir / "lfdpr_masked.png", cut.views[0]);
    metrics::writeImage(dir / "mvr_masked.png", reference.views[0]);
}

TEST_F(LfdprVisibilityTest, BothWorkShapesRenderTheSameViews)
{
    // The GPU work shape (lfdpr_work_shape.glsl) cuts the same work into shorter
    // invocations: a splat per point and slice of views, cells of at most a few pixels
    // (more points where a coarse texture made splats large), more triangles sampled by a
    // workgroup, shading per slice of views. None of that may change a pixel. Scenes: the
    // cube and sphere, the dense block, a coarse 2 x 2 texture (large splats), an
    // alpha-masked material (its own dispatch class, cells keep their size), and more views
    // than one 64-view chunk holds.
    Scene coarse = cubeAndSphereScene();
    coarse.textures[0] = checkerTexture(2, 1, {230, 200, 60, 255}, {40, 60, 160, 255}, true);
    finishScene(coarse);
    Scene masked = cubeAndSphereScene();
    masked.textures[0] = checkerTexture(128, 32, {230, 200, 60, 255}, {40, 60, 160, 0}, true);
    masked.materials[0].alphaMode = AlphaMode::Mask;
    masked.materials[0].alphaCutoff = 0.5f;
    finishScene(masked);
    struct Case {
        const char* name;
        Scene scene;
        DisplayProfile profile;
    };
    const Case cases[] = {
        {"cube and sphere", cubeAndSphereScene(), smallProfile(6, 160, 120)},
        {"dense", denseTestScene(), smallProfile(6, 160, 120)},
        {"coarse texture", coarse, smallProfile(6, 160, 120)},
        {"alpha mask", masked, smallProfile(4, 192, 144)},
        {"70 views", cubeAndSphereScene(), smallProfile(70, 48, 36)},
    };
    using Shape = LfdprOptions::WorkShape;
    for (const Case& c : cases) {
        auto cpu = player::createLfdprRenderer({.workShape = Shape::Cpu, .atomics = LfdprOptions::Atomics::TwoPass32});
        auto gpu = player::createLfdprRenderer({.workShape = Shape::Gpu, .atomics = LfdprOptions::Atomics::TwoPass32});
        const VisibilityFrame a = render(*cpu, c.scene, c.profile, 0.6);
        // The GPU shape clears its view words and colours in a shader
        // (lfdpr_visibility_clear.comp): a frame from another angle first, so a word or
        // colour the clear missed would show in the compared frame.
        render(*gpu, c.scene, c.profile, 0.0);
        const VisibilityFrame b = render(*gpu, c.scene, c.profile, 0.6);
        ASSERT_GT(a.info.points, 0u) << c.name;
        EXPECT_GE(b.info.points, a.info.points) << c.name << ": a cell never grows";
        EXPECT_GE(b.info.trianglesLarge, a.info.trianglesLarge) << c.name;
        for (uint32_t v = 0; v < c.profile.viewCount; ++v)
            EXPECT_EQ(a.views[v].pixels, b.views[v].pixels) << c.name << ", view " << v;
        std::printf("[ shapes   ] %s: points %llu (cpu) / %llu (gpu), triangles sampled by a workgroup %llu / %llu\n",
                    c.name, (unsigned long long)a.info.points, (unsigned long long)b.info.points,
                    (unsigned long long)a.info.trianglesLarge, (unsigned long long)b.info.trianglesLarge);
        if (std::string(c.name) == "coarse texture") {
            EXPECT_GT(b.info.points, a.info.points) << "large splats are cut into cells of a few pixels";
        }
        if (std::string(c.name) == "cube and sphere") {
            EXPECT_GT(b.info.trianglesLarge, a.info.trianglesLarge) << "boxes over 64 cells go to a workgroup";
        }
    }
}

// ---- Every shader variant through glslangValidator (no GL context needed) -------------

struct ShaderVariant {
    const char* file;
    const char* stage;
    std::vector<std::string> defines;
};
// Every stage file with the define sets the player compiles it with.
const std::vector<ShaderVariant> kShaderVariants = {
    {"mvr.vert", "vert", {}},
    {"mvr_layered.vert", "vert", {}},
    {"mvr.frag", "frag", {}},
    {"eia_construct.comp", "comp", {"EIA_MODE 0"}},
    {"eia_construct.comp", "comp", {"EIA_MODE 1"}},
    {"eia_construct.comp", "comp", {"EIA_MODE 2"}},
    {"eia_construct.comp", "comp", {"EIA_MODE 3"}},
    {"eia_prefilter.comp", "comp", {}},
    {"eia_prefilter.comp", "comp", {"EIA_PREFILTER_LAYERED 1"}},
    {"gstd_reconstruct.comp", "comp", {}},
    {"gstd_panel_phases.comp", "comp", {}},
    {"gstd_panel_accumulate.comp", "comp", {}},
    {"gstd_panel_resolve.comp", "comp", {}},
    {"view_downsample.comp", "comp", {}},
    {"text_overlay.vert", "vert", {}},
    {"text_overlay.frag", "frag", {}},
    {"pose_vertices.comp", "comp", {}},
    {"pose_triangles.comp", "comp", {}},
    {"lfdpr_paper_points.vert", "vert", {}},
    {"lfdpr_paper_points.geom", "geom", {}},
    {"lfdpr_paper_points.frag", "frag", {}},
    {"lfdpr_paper_dispatch.comp", "comp", {}},
    {"lfdpr_paper_splat.comp", "comp", {}},
    {"lfdpr_paper_splat.comp", "comp", {"LFDPR_INT64 1"}},
    {"lfdpr_paper_resolve.comp", "comp", {}},
    {"lfdpr_paper_resolve.comp", "comp", {"LFDPR_INT64 1"}},
    {"lfdpr_visibility_points.comp", "comp", {}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_LARGE_PASS 1"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_ALPHA_TEST 1"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_ALPHA_TEST 1", "LFDPR_LARGE_PASS 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_INT64 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_INDEX_PASS 1"}},
    {"lfdpr_visibility_shade.comp", "comp", {}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_INT64 1"}},
    // Shading programs are compiled per shading group's textures: none, and a subset.
    {"lfdpr_visibility_shade.comp", "comp", {"LFD_TEXTURE_MASK 0x0u"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_INT64 1", "LFD_TEXTURE_MASK 0x3u"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFD_TEXTURE_MASK 0x0u", "LFD_STREAMS 0x1u"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFD_TEXTURE_MASK 0x1u", "LFD_STREAMS 0x9u"}},
    // --aniso above 1 with the shader's taps (llvmpipe's default).
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_ANISO_TAPS 1", "LFD_TEXTURE_MASK 0x1Fu"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_PIXEL_CENTRE_CULLING 1"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_PIXEL_CENTRE_CULLING 1", "LFDPR_CELL_SCALE 2"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_PIXEL_CENTRE_CULLING 1", "LFDPR_LARGE_PASS 1"}},
    {"lfdpr_visibility_shade_list.comp", "comp", {}},
    {"lfdpr_visibility_shade_list.comp", "comp", {"LFDPR_REPAIR_LIST 1"}},
    {"lfdpr_visibility_repair_dispatch.comp", "comp", {}},
    // The GPU work shape (lfdpr_work_shape.glsl) as a GPU runs it: with 64-bit atomics.
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_PIXEL_CENTRE_CULLING 1", "LFDPR_CELL_SCALE 2"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_PIXEL_CENTRE_CULLING 1", "LFDPR_LARGE_PASS 1"}},
    {"lfdpr_visibility_points.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_ALPHA_TEST 1", "LFDPR_LARGE_PASS 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_WORK_GPU 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INDEX_PASS 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INDEX_PASS 1", "LFDPR_TIE_PASS 1"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INT64 1", "LFD_TEXTURE_MASK 0x3u"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_WORK_GPU 1", "LFD_TEXTURE_MASK 0x0u"}},
    // Every texture as a GPU shades it (the texture unit filters anisotropically).
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INT64 1", "LFD_TEXTURE_MASK 0x1Fu"}},
    {"lfdpr_visibility_shade_list.comp", "comp", {"LFDPR_WORK_GPU 1"}},
    {"lfdpr_visibility_repair_dispatch.comp", "comp", {"LFDPR_WORK_GPU 1"}},
    {"lfdpr_visibility_clear.comp", "comp", {"LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    {"lfdpr_visibility_clear.comp", "comp", {"LFDPR_WORK_GPU 1"}},
    // The work counters (lfdpr_work_counters.glsl, --lfdpr-work-counters) on every path.
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_COUNT_WORK 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_COUNT_WORK 1", "LFDPR_INDEX_PASS 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_COUNT_WORK 1", "LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_COUNT_WORK 1", "LFD_TEXTURE_MASK 0x1u"}},
    {"lfdpr_visibility_shade.comp", "comp", {"LFDPR_COUNT_WORK 1", "LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    // The direct subpixel splat (lfdpr-direct): both atomics paths and its record pass, its
    // shading per texture set, the pack, on both work shapes and with the counters.
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_DIRECT 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_DIRECT 1", "LFDPR_INDEX_PASS 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_DIRECT 1", "LFDPR_INT64 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_DIRECT 1", "LFDPR_COUNT_WORK 1"}},
    {"lfdpr_visibility_splat.comp", "comp", {"LFDPR_DIRECT 1", "LFDPR_WORK_GPU 1", "LFDPR_INT64 1", "LFDPR_COUNT_WORK 1"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFD_TEXTURE_MASK 0x0u"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFDPR_INT64 1", "LFD_TEXTURE_MASK 0x1Fu"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFDPR_ANISO_TAPS 1", "LFD_TEXTURE_MASK 0x1Fu", "LFD_STREAMS 0x9u"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFDPR_COUNT_WORK 1", "LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFDPR_DIRECT_EXACT 1", "LFD_TEXTURE_MASK 0x1Fu"}},
    {"lfdpr_direct_shade.comp", "comp", {"LFDPR_DIRECT_EXACT 1", "LFDPR_WORK_GPU 1", "LFDPR_INT64 1"}},
    {"lfdpr_direct_pack.comp", "comp", {}},
};
TEST(ShaderVariants, EveryVariantCompilesWithGlslang)
{
    const char* validator = "glslangValidator";
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        LFD_SKIP_OR_FAIL("glslangValidator (Debian glslang-tools, installed by scripts/setup.sh) is missing");
    const std::filesystem::path dir = testOutputDir("shader_variants");
    size_t checked = 0;
    for (const ShaderVariant& v : kShaderVariants) {
        const gl::PreprocessedShader source = gl::preprocessShader(v.file, v.defines);
        std::string name = v.file;
        for (std::string d : v.defines) {
            std::replace(d.begin(), d.end(), ' ', '=');
            name += "." + d;
        }
        const std::filesystem::path path = dir / (name + "." + v.stage);
        std::ofstream(path) << source.text;
        const std::filesystem::path log = dir / (name + ".log");
        const std::string command = std::string(validator) + " -S " + v.stage + " \"" + path.string() + "\" > \"" +
                                    log.string() + "\" 2>&1";
        const int rc = std::system(command.c_str());
        std::ifstream in(log);
        const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(rc, 0) << v.file << " " << (v.defines.empty() ? "" : v.defines[0]) << ":\n" << output;
        ++checked;
    }
    EXPECT_EQ(checked, kShaderVariants.size());
    // Every embedded stage file appears above at least once.
    for (const std::string& file : gl::shaderNames()) {
        if (file.ends_with(".glsl"))
            continue;
        bool listed = false;
        for (const ShaderVariant& v : kShaderVariants)
            listed = listed || file == v.file;
        EXPECT_TRUE(listed) << file << " has no glslang check";
    }
}

} // namespace
} // namespace lfd::test
