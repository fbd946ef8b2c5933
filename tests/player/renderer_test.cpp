// Raster renderers (mvr, mvr-layered) on a headless GL 4.5 context: agreement between the
// two, golden images, and analytic checks of the view geometry and shading.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "image_metrics.h"
#include "renderer_registry.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace lfd::test {
namespace {

using metrics::Image;

class RendererTest : public GlTest {};

struct PixelStats {
    size_t count = 0;
    double cx = 0.0, cy = 0.0; // centroid in pixel-centre coordinates, image order
};

// Pixels whose RGB is within `tolerance` of `rgb`.
PixelStats findColour(const Image& image, const glm::u8vec3& rgb, int tolerance)
{
    PixelStats s;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
            if (std::abs(p[0] - rgb.r) <= tolerance && std::abs(p[1] - rgb.g) <= tolerance &&
                std::abs(p[2] - rgb.b) <= tolerance) {
                ++s.count;
                s.cx += x;
                s.cy += y;
            }
        }
    if (s.count) {
        s.cx /= double(s.count);
        s.cy /= double(s.count);
    }
    return s;
}

size_t nonBackgroundPixels(const Image& image)
{
    size_t n = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4)
        n += std::abs(image.pixels[i] - 13) > 2 || std::abs(image.pixels[i + 1] - 13) > 2 ||
             std::abs(image.pixels[i + 2] - 13) > 2;
    return n;
}

TEST_F(RendererTest, FactoryKnowsRasterRenderersAndRejectsUnknownNames)
{
    const std::vector<std::string> names = player::rendererNames();
    EXPECT_NE(std::find(names.begin(), names.end(), "mvr"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "mvr-layered"), names.end());
    try {
        player::createRenderer("nope");
        FAIL() << "unknown renderer accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("nope"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("mvr-layered"), std::string::npos);
    }
}

// mvr-layered must reproduce mvr: same vertex math (shared code, `invariant gl_Position`),
// same fragment shader, same per-pixel draw order. Tolerance: at most 1 per channel and
// > 99.9% identical pixels, to allow a driver that contracts the two programs' arithmetic
// differently (FMA); llvmpipe produces identical images.
TEST_F(RendererTest, LayeredMatchesPerViewPasses)
{
    if (!caps().layerFromVertexShader)
        LFD_SKIP_OR_FAIL("driver lacks GL_ARB_shader_viewport_layer_array");
    const Scene scene = cubeAndSphereScene();
    const DisplayProfile profile = smallProfile(6, 96, 72);
    const RenderedFrame a = renderFrame("mvr", scene, profile, {.time = 1.7, .turntablePeriod = 10.0});
    const RenderedFrame b = renderFrame("mvr-layered", scene, profile, {.time = 1.7, .turntablePeriod = 10.0});
    ASSERT_EQ(a.views.size(), b.views.size());
    for (size_t v = 0; v < a.views.size(); ++v) {
        EXPECT_GT(nonBackgroundPixels(a.views[v]), 96u * 72u / 10) << "view " << v << " is empty";
        EXPECT_LE(metrics::maxAbsDiff(a.views[v], b.views[v]), 1) << "view " << v;
        size_t same = 0;
        for (size_t i = 0; i < a.views[v].pixels.size(); i += 4)
            same += std::equal(&a.views[v].pixels[i], &a.views[v].pixels[i] + 4, &b.views[v].pixels[i]);
        EXPECT_GT(double(same) / double(96 * 72), 0.999) << "view " << v;
    }
}

// Golden images of a fixed scene (checker-textured cube: mipmapping matters; red sphere;
// default-material box). Tolerance: RMSE < 1.5 (0..255) and max difference <= 64 —
// llvmpipe is deterministic, but a driver update may move a few edge pixels or round
// texture filtering differently; a wrong camera, shading or texture breaks both limits.
// LFD_REGENERATE_GOLDEN=1 rewrites the references in tests/data/golden/.
TEST_F(RendererTest, MvrMatchesGoldenImages)
{
    const Scene scene = cubeAndSphereScene();
    const RenderedFrame r =
        renderFrame("mvr", scene, smallProfile(4, 160, 120), {.time = 1.25, .turntablePeriod = 10.0});
    const std::filesystem::path goldenDir = std::filesystem::path(LFD_TEST_DATA) / "golden";
    const bool regenerate = std::getenv("LFD_REGENERATE_GOLDEN") &&
                            std::string(std::getenv("LFD_REGENERATE_GOLDEN")) == "1";
    for (uint32_t view : {0u, 3u}) {
        const std::filesystem::path golden = goldenDir / ("mvr_view" + std::to_string(view) + ".png");
        if (regenerate) {
            std::filesystem::create_directories(goldenDir);
            metrics::writeImage(golden, r.views[view]);
            continue;
        }
        ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " missing; run with LFD_REGENERATE_GOLDEN=1";
        const Image expected = metrics::readImage(golden, 4);
        ASSERT_EQ(expected.width, r.views[view].width);
        ASSERT_EQ(expected.height, r.views[view].height);
        const double error = metrics::rmse(expected, r.views[view]);
        const int maxDiff = metrics::maxAbsDiff(expected, r.views[view]);
        if (error >= 1.5 || maxDiff > 64) {
            const std::filesystem::path dir = testOutputDir("MvrMatchesGoldenImages");
            metrics::writeImage(dir / ("actual_view" + std::to_string(view) + ".png"), r.views[view]);
            metrics::writeDiffImage(dir / ("diff_view" + std::to_string(view) + ".png"), expected, r.views[view]);
            ADD_FAILURE() << "view " << view << ": RMSE " << error << ", max diff " << maxDiff
                          << " against " << golden << "; actual and diff images in " << dir;
        }
    }
    // Views differ by parallax, but only slightly.
    EXPECT_GT(metrics::rmse(r.views[0], r.views[3]), 2.0);
    EXPECT_GT(metrics::ssim(r.views[0], r.views[3]), 0.5);
}

// Analytic geometry and shading. Two emissive-only quads (direct and ambient light add
// < 1e-5 for black metallic rough surfaces): `front` on the zero-parallax plane must land
// on the same pixels in every view; `back` (behind the screen) must sit where the view's
// clipFromScene puts it and move right as the camera moves right (framing.h: a point
// behind the screen follows the camera). Colours must be the sRGB encoding of the
// emissive factor (+-1 for rounding).
TEST_F(RendererTest, ZeroParallaxPlaneAndDepthParallaxMatchFraming)
{
    for (const char* name : {"mvr", "mvr-layered"}) {
        if (std::string(name) == "mvr-layered" && !caps().layerFromVertexShader)
            continue;
        SCOPED_TRACE(name);
        const EmissiveQuads q = emissiveQuadsScene(1.0f, -0.6f);
        const uint32_t w = 160, h = 120;
        const RenderedFrame r = renderFrame(name, q.scene, smallProfile(6, w, h));
        const glm::u8vec3 front(srgbByte(q.frontEmissive.r), srgbByte(q.frontEmissive.g),
                                srgbByte(q.frontEmissive.b));
        const glm::u8vec3 back(srgbByte(q.backEmissive.r), srgbByte(q.backEmissive.g),
                               srgbByte(q.backEmissive.b));
        PixelStats front0;
        double previousBackX = -1.0;
        for (size_t v = 0; v < r.views.size(); ++v) {
            const PixelStats f = findColour(r.views[v], front, 1);
            const PixelStats b = findColour(r.views[v], back, 1);
            ASSERT_GT(f.count, 20u) << "front quad colour not found in view " << v;
            ASSERT_GT(b.count, 20u) << "back quad colour not found in view " << v;
            if (v == 0)
                front0 = f;
            EXPECT_NEAR(f.cx, front0.cx, 0.02) << "zero-parallax quad moved in view " << v;
            EXPECT_NEAR(f.cy, front0.cy, 0.02);
            EXPECT_LT(f.cy, h / 2.0) << "quad above the centre must be in the upper half (image order)";

            // Predicted centre of the back quad from the view's own projection.
            const glm::vec4 clip = r.setup.clipFromScene[v] * glm::vec4(q.backCenter, 1.0f);
            const double px = (clip.x / clip.w * 0.5 + 0.5) * w - 0.5;
            const double py = (1.0 - (clip.y / clip.w * 0.5 + 0.5)) * h - 0.5;
            EXPECT_NEAR(b.cx, px, 0.5) << "view " << v;
            EXPECT_NEAR(b.cy, py, 0.5) << "view " << v;
            EXPECT_GT(b.cx, previousBackX) << "back quad must move right with the camera";
            previousBackX = b.cx;
        }
        // The zero-parallax quad is centred where displayFromScene puts it on the screen.
        const glm::vec4 clip = r.setup.clipFromScene[0] * glm::vec4(q.frontCenter, 1.0f);
        EXPECT_NEAR(front0.cx, (clip.x / clip.w * 0.5 + 0.5) * w - 0.5, 0.5);
        EXPECT_NEAR(front0.cy, (1.0 - (clip.y / clip.w * 0.5 + 0.5)) * h - 0.5, 0.5);
    }
}

// Meshes without normals, uvs or tangents, drawn with the default material (-1).
TEST_F(RendererTest, MissingStreamsAndDefaultMaterialRender)
{
    const Scene scene = positionsOnlyScene();
    const RenderedFrame a = renderFrame("mvr", scene, smallProfile(4, 64, 48), {.time = 0.5, .turntablePeriod = 10.0});
    for (const Image& view : a.views)
        EXPECT_GT(nonBackgroundPixels(view), 64u * 48u / 10);
    // Flat shading from derivatives: the visible faces are lit differently.
    const PixelStats centre = findColour(a.views[0], {13, 13, 13}, 2);
    EXPECT_LT(centre.count, 64u * 48u);
    if (caps().layerFromVertexShader) {
        const RenderedFrame b =
            renderFrame("mvr-layered", scene, smallProfile(4, 64, 48), {.time = 0.5, .turntablePeriod = 10.0});
        for (size_t v = 0; v < a.views.size(); ++v)
            EXPECT_LE(metrics::maxAbsDiff(a.views[v], b.views[v]), 1);
    }
}

TEST_F(RendererTest, ViewGenerationIsTimed)
{
    const RenderedFrame r =
        renderFrame("mvr", cubeAndSphereScene(), smallProfile(4, 64, 48), {.turntablePeriod = 10.0});
    ASSERT_EQ(r.stageMs.size(), 1u);
    ASSERT_TRUE(r.stageMs.count("view_generation"));
    EXPECT_TRUE(std::isfinite(r.stageMs.at("view_generation")));
    EXPECT_GT(r.stageMs.at("view_generation"), 0.0);
}

} // namespace
} // namespace lfd::test
