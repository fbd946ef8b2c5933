// Reconstruction (--aa) and supersampling (--ss), paper section 4: the seeded Gaussian
// samples, a single bright view pixel spreading as the spatial Gaussian predicts, the view
// filter mixing neighbouring views only, GPU against the CPU reference (stated tolerance),
// reproducibility, the supersampled cameras, the pipeline's downsample against a CPU mean
// of the supersampled views, and lfdpr's point cloud not growing under 2x angular
// supersampling.
#include "display_test_profiles.h"
#include "gl_test_support.h"
#include "test_scenes.h"

#include "eia_builder.h"
#include "frame_pipeline.h"
#include "frame_stages.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "image_metrics.h"
#include "renderer_registry.h"
#include "shader_library.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lfd::test {
namespace {

using player::Reconstruction;
using player::ReconstructionFilter;
using player::Supersampling;

double linearOf(uint8_t v)
{
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Every view black but view pixel (px, py) (image order) white in the views listed (all
// when `only` < 0).
std::vector<std::vector<uint8_t>> brightPixelViews(const DisplayProfile& p, uint32_t px, uint32_t py, int only = -1)
{
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < p.viewCount; ++v) {
        std::vector<uint8_t> image(size_t(p.viewWidth) * p.viewHeight * 4, 0);
        for (size_t i = 3; i < image.size(); i += 4)
            image[i] = 255;
        if (only < 0 || int(v) == only)
            for (int c = 0; c < 3; ++c)
                image[(size_t(py) * p.viewWidth + px) * 4 + size_t(c)] = 255;
        views.push_back(std::move(image));
    }
    return views;
}

std::vector<std::vector<uint8_t>> randomViews(const DisplayProfile& p, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<std::vector<uint8_t>> views(p.viewCount, std::vector<uint8_t>(size_t(p.viewWidth) * p.viewHeight * 4));
    for (auto& view : views)
        for (uint8_t& b : view)
            b = uint8_t(byte(rng));
    return views;
}

// Moments of the light an EIA shows, per subpixel at its screen position in view pixels.
struct Spread {
    double energy = 0.0;       // sum of linear values / subpixels per view pixel
    double cx = 0.0, cy = 0.0; // centroid, view pixels
    double vx = 0.0, vy = 0.0; // variance, view pixels^2
    double reach = 0.0;        // largest distance of a lit subpixel from (cx, cy)
};

Spread spreadOf(const DisplayProfile& p, const std::vector<uint8_t>& eia)
{
    const uint32_t W = p.panelWidth, H = p.panelHeight;
    double sum = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
    struct Lit {
        double x, y;
    };
    std::vector<Lit> lit;
    for (uint32_t l = 0; l < H; ++l)
        for (uint32_t k = 0; k < 3 * W; ++k) {
            const double value = linearOf(eia[(size_t(l) * W + k / 3) * 4 + k % 3]);
            if (value <= 0.0)
                continue;
            const double x = (k + 0.5) / (3.0 * W) * p.viewWidth, y = (l + 0.5) / H * p.viewHeight;
            sum += value;
            sx += value * x;
            sy += value * y;
            sxx += value * x * x;
            syy += value * y * y;
            lit.push_back({x, y});
        }
    Spread s;
    const double perPixel = 3.0 * W / p.viewWidth * H / p.viewHeight;
    s.energy = sum / perPixel;
    s.cx = sx / sum;
    s.cy = sy / sum;
    s.vx = sxx / sum - s.cx * s.cx;
    s.vy = syy / sum - s.cy * s.cy;
    for (const Lit& q : lit)
        s.reach = std::max(s.reach, std::hypot(q.x - s.cx, q.y - s.cy));
    return s;
}

TEST(Reconstruction, NamesParseAndRoundTrip)
{
    for (const std::string& name : player::reconstructionNames())
        EXPECT_EQ(player::reconstructionName(player::parseReconstruction(name)), name);
    EXPECT_EQ(player::parseReconstruction("view-spatial"), Reconstruction::ViewSpatial);
    EXPECT_THROW(player::parseReconstruction("gaussian"), std::invalid_argument);
    for (const std::string& name : player::supersamplingNames())
        EXPECT_EQ(player::supersamplingName(player::parseSupersampling(name)), name);
    EXPECT_EQ(player::parseSupersampling("2v"), Supersampling::Angular2x);
    EXPECT_THROW(player::parseSupersampling("4x"), std::invalid_argument);
}

TEST(Reconstruction, SamplesAreSeededGaussiansInsideTheSupport)
{
    // Reproducible and seed-dependent; only the mode's dimensions are offset, within 3 sigma.
    for (Reconstruction mode : {Reconstruction::Spatial, Reconstruction::View, Reconstruction::ViewSpatial}) {
        const auto a = player::reconstructionSamples(mode, 7), b = player::reconstructionSamples(mode, 7);
        const auto c = player::reconstructionSamples(mode, 8);
        ASSERT_EQ(a.size(), ReconstructionFilter::kSamples);
        EXPECT_EQ(a, b);
        EXPECT_NE(a, c);
        const bool spatial = mode != Reconstruction::View, view = mode != Reconstruction::Spatial;
        for (const glm::vec3& o : a) {
            EXPECT_EQ(o.x != 0.0f, spatial);
            EXPECT_EQ(o.z != 0.0f, view);
            EXPECT_LE(std::hypot(o.x, o.y), 1.125f + 1e-6f);
            EXPECT_LE(std::abs(o.z), 1.0f + 1e-6f);
        }
    }
    // Over many seeds the offsets have the Gaussians' spread: sigma = 2.25 / 6 view pixels,
    // 2 / 6 view intervals. A 3-sigma truncation lowers the variance: in 1D by the factor
    // 1 - 6 phi(3) / (1 - 2 Phi(-3)) = 0.9733; on a disc of radius 3 sigma (r^2 / sigma^2 is
    // chi-square with 2 degrees of freedom) by (1 - 5.5 e^-4.5) / (1 - e^-4.5) = 0.9494 per
    // axis. Tolerance 2% of sigma: the statistics of 4000 x 8 samples are within 1%.
    double xx = 0.0, zz = 0.0;
    const int seeds = 4000;
    for (int s = 0; s < seeds; ++s)
        for (const glm::vec3& o : player::reconstructionSamples(Reconstruction::ViewSpatial, uint64_t(s))) {
            xx += double(o.x) * o.x;
            zz += double(o.z) * o.z;
        }
    const double n = double(seeds) * ReconstructionFilter::kSamples;
    EXPECT_NEAR(std::sqrt(xx / n), 0.375 * std::sqrt(0.9494), 0.375 * 0.02);
    EXPECT_NEAR(std::sqrt(zz / n), (1.0 / 3.0) * std::sqrt(0.9733), (1.0 / 3.0) * 0.02);
}

TEST(Reconstruction, SpatialFilterSpreadsASinglePixelAsTheGaussianPredicts)
{
    // One white view pixel (all views): without a filter the EIA shows it as a box of one
    // view pixel (variance 1/12 per axis). The spatial filter is the mean of 8 bilinear
    // fetches at the sample offsets o_s: in x a tent of variance 1/6 around each of
    // -o_s.x, so the variance is 1/6 + the offsets' own variance (about sigma^2 =
    // 0.375^2), the centroid moves by -mean(o_s), the light stays within 1 + 1.125 view
    // pixels, and its total is kept (one view pixel). Tolerances: the panel samples a view
    // pixel at 12 x 6 subpixel positions, so discrete moments differ by a few percent.
    const DisplayProfile p = player::displaytest::smallProfile();
    const uint32_t px = 60, py = 22;
    const auto views = brightPixelViews(p, px, py);

    const Spread none = spreadOf(p, player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight));
    EXPECT_NEAR(none.energy, 1.0, 0.02);
    EXPECT_NEAR(none.vx, 1.0 / 12.0, 0.01);
    EXPECT_NEAR(none.vy, 1.0 / 12.0, 0.01);

    const auto samples = player::reconstructionSamples(Reconstruction::Spatial);
    double mx = 0.0, my = 0.0, mxx = 0.0, myy = 0.0;
    for (const glm::vec3& o : samples) {
        mx += o.x / 8.0;
        my += o.y / 8.0;
        mxx += double(o.x) * o.x / 8.0;
        myy += double(o.y) * o.y / 8.0;
    }
    const Spread spatial =
        spreadOf(p, player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight, Reconstruction::Spatial));
    EXPECT_NEAR(spatial.energy, 1.0, 0.05);
    EXPECT_NEAR(spatial.cx, px + 0.5 - mx, 0.05);
    EXPECT_NEAR(spatial.cy, py + 0.5 - my, 0.1);
    EXPECT_NEAR(spatial.vx, 1.0 / 6.0 + (mxx - mx * mx), 0.1 * (1.0 / 6.0 + mxx));
    EXPECT_NEAR(spatial.vy, 1.0 / 6.0 + (myy - my * my), 0.1 * (1.0 / 6.0 + myy));
    EXPECT_GT(spatial.vx, 2.0 * none.vx); // it spreads
    EXPECT_LE(spatial.reach, 1.0 + 1.125 + 0.3);
    std::printf("[ spread   ] one view pixel: none var %.3f x %.3f; spatial var %.3f x %.3f (predicted %.3f x "
                "%.3f), energy %.3f\n",
                none.vx, none.vy, spatial.vx, spatial.vy, 1.0 / 6.0 + mxx - mx * mx, 1.0 / 6.0 + myy - my * my,
                spatial.energy);
}

TEST(Reconstruction, ViewFilterMixesNeighbouringViewsOnly)
{
    // Only view 12 is lit. Nearest view: exactly the subpixels with floor(phase N) = 12.
    // View filter: light also reaches subpixels whose view coordinate c = phase N is within
    // the samples' reach of view 12's interval (c + dv in [12, 13)), never further, and the
    // total stays about the same (the samples are symmetric on average).
    const DisplayProfile p = player::displaytest::smallProfile();
    std::vector<std::vector<uint8_t>> white;
    for (uint32_t v = 0; v < p.viewCount; ++v) {
        std::vector<uint8_t> image(size_t(p.viewWidth) * p.viewHeight * 4, v == 12 ? 255 : 0);
        for (size_t i = 3; i < image.size(); i += 4)
            image[i] = 255;
        white.push_back(std::move(image));
    }
    const auto samples = player::reconstructionSamples(Reconstruction::View);
    float lo = 0.0f, hi = 0.0f;
    for (const glm::vec3& o : samples) {
        lo = std::min(lo, o.z);
        hi = std::max(hi, o.z);
    }
    const auto nearest = player::buildEiaCpu(p, white, p.viewWidth, p.viewHeight);
    const auto filtered = player::buildEiaCpu(p, white, p.viewWidth, p.viewHeight, Reconstruction::View);
    double litNearest = 0.0, litFiltered = 0.0;
    size_t neighbours = 0;
    for (uint32_t l = 0; l < p.panelHeight; ++l)
        for (uint32_t k = 0; k < 3 * p.panelWidth; ++k) {
            const size_t at = (size_t(l) * p.panelWidth + k / 3) * 4 + k % 3;
            const double c = subpixelPhase(p, k, l) * p.viewCount;
            litNearest += linearOf(nearest[at]);
            litFiltered += linearOf(filtered[at]);
            if (filtered[at] > 0) {
                ASSERT_GE(c + hi, 12.0 - 1e-9) << k << "," << l;
                ASSERT_LT(c + lo, 13.0 + 1e-9) << k << "," << l;
                neighbours += std::floor(c) != 12.0;
            }
        }
    EXPECT_GT(neighbours, size_t(100)); // light reaches views 11 and 13
    EXPECT_NEAR(litFiltered / litNearest, 1.0, 0.15);
    // The spatial mode does not mix views: view 12 alone, as nearest.
    const auto spatial = player::buildEiaCpu(p, white, p.viewWidth, p.viewHeight, Reconstruction::Spatial);
    EXPECT_EQ(spatial, nearest);
}

TEST(Reconstruction, CpuReferenceIsReproducibleAndSeeded)
{
    const DisplayProfile p = player::displaytest::smallProfile();
    const auto views = randomViews(p, 5);
    const auto a = player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight, Reconstruction::ViewSpatial, 3);
    const auto b = player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight, Reconstruction::ViewSpatial, 3);
    const auto c = player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight, Reconstruction::ViewSpatial, 4);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(Supersampling, AngularCamerasAreRandomInsideEachHalfInterval)
{
    const DisplayProfile p = player::displaytest::smallProfile();
    Scene scene = cubeAndSphereScene();
    const Framing framing = fitSceneToDisplay(p, scene.bounds);
    const player::FrameSetup frame = player::makeFrameSetup(p, framing, 0.25, 10.0);
    const player::FrameSetup ss = player::supersampledFrame(frame, Supersampling::Angular2x);
    ASSERT_EQ(ss.cameras.size(), 2u * p.viewCount);
    EXPECT_EQ(ss.profile.viewCount, 2u * p.viewCount);
    ASSERT_TRUE(ss.pointSampling);
    EXPECT_EQ(ss.samplingFrame().cameras.size(), p.viewCount);
    // Camera j = 2i + s sits in [(i + s/2) / N, (i + (s+1)/2) / N): between the eyes at
    // those cone positions (eye x grows monotonically with the position).
    const double N = p.viewCount;
    for (uint32_t j = 0; j < ss.cameras.size(); ++j) {
        const double from = (j / 2 + (j % 2) / 2.0) / N, to = from + 0.5 / N;
        EXPECT_GE(ss.cameras[j].eye.x, makeViewCameraAt(p, framing, from).eye.x) << j;
        EXPECT_LT(ss.cameras[j].eye.x, makeViewCameraAt(p, framing, to).eye.x) << j;
    }
    // Reproducible per frame, different between frames.
    const player::FrameSetup again = player::supersampledFrame(frame, Supersampling::Angular2x);
    const player::FrameSetup later =
        player::supersampledFrame(player::makeFrameSetup(p, framing, 0.5, 10.0), Supersampling::Angular2x);
    EXPECT_EQ(ss.cameras[5].eye.x, again.cameras[5].eye.x);
    EXPECT_NE(ss.cameras[5].eye.x - frame.cameras[2].eye.x, later.cameras[5].eye.x - frame.cameras[2].eye.x);
    // makeViewCameraAt agrees with makeViewCamera at the interval centres.
    EXPECT_EQ(makeViewCameraAt(p, framing, 2.5 / N).clipFromDisplay, makeViewCamera(p, framing, 2, p.viewCount).clipFromDisplay);
    // Spatial: the same cameras at twice the size.
    const player::FrameSetup s2 = player::supersampledFrame(frame, Supersampling::Spatial2x);
    EXPECT_EQ(s2.profile.viewWidth, 2 * p.viewWidth);
    EXPECT_EQ(s2.cameras.size(), frame.cameras.size());
    EXPECT_FALSE(s2.pointSampling);
}

// ---- GPU --------------------------------------------------------------------------------

class ReconstructionGpu : public GlTest {};

void uploadViews(player::ViewTargets& targets, const std::vector<std::vector<uint8_t>>& views)
{
    const uint32_t w = targets.width(), h = targets.height();
    std::vector<uint8_t> flipped(size_t(w) * h * 4);
    for (uint32_t v = 0; v < targets.viewCount(); ++v) {
        for (uint32_t y = 0; y < h; ++y)
            std::copy_n(&views[v][size_t(h - 1 - y) * w * 4], size_t(w) * 4, &flipped[size_t(y) * w * 4]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage3D(targets.colorArray(), 0, 0, 0, GLint(v), GLsizei(w), GLsizei(h), 1, GL_RGBA,
                            GL_UNSIGNED_BYTE, flipped.data());
    }
}

TEST_F(ReconstructionGpu, ShaderConstantsMatchTheEnum)
{
    EXPECT_EQ(gl::shaderDefineValue("eia_bindings.glsl", "EIA_MODE_SPATIAL"), long(Reconstruction::Spatial));
    EXPECT_EQ(gl::shaderDefineValue("eia_bindings.glsl", "EIA_MODE_VIEW"), long(Reconstruction::View));
    EXPECT_EQ(gl::shaderDefineValue("eia_bindings.glsl", "EIA_MODE_VIEW_SPATIAL"), long(Reconstruction::ViewSpatial));
    EXPECT_EQ(gl::shaderDefineValue("eia_bindings.glsl", "EIA_SAMPLES"), long(ReconstructionFilter::kSamples));
}

TEST_F(ReconstructionGpu, EveryModeMatchesTheCpuReference)
{
    // Tolerance: one 8-bit level on at most 1% of the subpixels. The GPU pass and the CPU
    // reference use the same samples, the same decoding table and the same float
    // operations, but the driver may fuse a multiply-add and its pow() may differ in the
    // last bit, which moves a value sitting on a rounding boundary by one level.
    for (const DisplayProfile& p : {player::displaytest::smallProfile("RGB"), player::displaytest::smallProfile("BGR", true)})
        for (Reconstruction mode : {Reconstruction::Spatial, Reconstruction::View, Reconstruction::ViewSpatial}) {
            const auto views = randomViews(p, 9);
            player::ViewTargets targets(p.viewCount, p.viewWidth, p.viewHeight);
            uploadViews(targets, views);
            player::EiaBuilder builder(p);
            player::GpuTimer timer;
            builder.build(targets, mode, timer);
            const auto gpu = builder.read();
            builder.build(targets, mode, timer);
            timer.finish();
            EXPECT_EQ(builder.read(), gpu) << "not reproducible";
            const auto cpu = player::buildEiaCpu(p, views, p.viewWidth, p.viewHeight, mode);
            ASSERT_EQ(gpu.size(), cpu.size());
            size_t off = 0;
            int worst = 0;
            for (size_t i = 0; i < gpu.size(); ++i) {
                const int d = std::abs(int(gpu[i]) - int(cpu[i]));
                off += d != 0;
                worst = std::max(worst, d);
            }
            EXPECT_LE(worst, 1) << player::reconstructionName(mode);
            EXPECT_LE(double(off) / double(gpu.size()), 0.01) << player::reconstructionName(mode);
        }
}

// 4 views of 64x48 on a 384x216 panel: a frame takes milliseconds on llvmpipe.
DisplayProfile tinyProfile()
{
    return parseDisplayProfile(R"({
        "format": "lfd-display-profile/1", "name": "ss-small",
        "panel_width": 384, "panel_height": 216,
        "screen_width_mm": 34.54, "screen_height_mm": 19.43,
        "subpixel_order": "RGB", "lens_width_mm": 0.72, "lens_tilt_deg": -9.66,
        "view_count": 4, "view_width": 64, "view_height": 48,
        "view_cone_deg": 40.0, "viewing_distance_mm": 300.0
    })",
                               "ss-small.json");
}

TEST_F(ReconstructionGpu, DownsampleIsTheLinearMeanOfTheSupersampledViews)
{
    // The pipeline's views under 2s / 2v against the CPU mean (linear light) of the
    // supersampled views rendered directly by the same renderer for the same frame.
    // Tolerance: one level (the shader decodes with pow(), the test exactly).
    const DisplayProfile p = tinyProfile();
    const Scene scene = cubeAndSphereScene();
    for (Supersampling ss : {Supersampling::Spatial2x, Supersampling::Angular2x}) {
        player::FramePipeline pipeline(p, scene, 10.0);
        pipeline.setSupersampling(ss);
        auto renderer = player::createRenderer("mvr");
        player::GpuTimer timer;
        pipeline.renderFrame(*renderer, 0.5, timer);
        timer.finish();
        EXPECT_TRUE(timer.stages().count(std::string(player::stage::kDownsample)));
        const player::FrameOutputs out = pipeline.read(0);

        const player::FrameSetup frame = player::supersampledFrame(pipeline.lastFrame(), ss);
        player::ViewTargets big(frame.profile.viewCount, frame.profile.viewWidth, frame.profile.viewHeight);
        player::GpuTimer t2;
        renderer->render(pipeline.scene(), frame, big, t2);
        t2.finish();
        int worst = 0;
        for (uint32_t v = 0; v < p.viewCount; ++v) {
            std::vector<std::vector<uint8_t>> sources;
            if (ss == Supersampling::Spatial2x)
                sources.push_back(big.readView(v));
            else
                sources = {big.readView(2 * v), big.readView(2 * v + 1)};
            const uint32_t bw = big.width();
            for (uint32_t y = 0; y < p.viewHeight; ++y)
                for (uint32_t x = 0; x < p.viewWidth; ++x)
                    for (int c = 0; c < 3; ++c) {
                        double sum = 0.0;
                        int n = 0;
                        for (const auto& src : sources)
                            for (uint32_t j = 0; j < (ss == Supersampling::Spatial2x ? 2u : 1u); ++j)
                                for (uint32_t i = 0; i < (ss == Supersampling::Spatial2x ? 2u : 1u); ++i) {
                                    const uint32_t sx = ss == Supersampling::Spatial2x ? 2 * x + i : x;
                                    const uint32_t sy = ss == Supersampling::Spatial2x ? 2 * y + j : y;
                                    sum += linearOf(src[(size_t(sy) * bw + sx) * 4 + size_t(c)]);
                                    ++n;
                                }
                        const double l = sum / n;
                        const double e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
                        const int expected = int(std::lround(e * 255.0));
                        worst = std::max(worst, std::abs(expected - int(out.views[v][(size_t(y) * p.viewWidth + x) * 4 + size_t(c)])));
                    }
        }
        EXPECT_LE(worst, 1) << player::supersamplingName(ss);
    }
}

TEST_F(ReconstructionGpu, AngularSupersamplingKeepsLfdprsPointCloud)
{
    // Paper section 5: angular supersampling projects the same points into more views and
    // does not grow the point cloud; spatial supersampling needs about 2-4x the points.
    const DisplayProfile p = tinyProfile();
    const Scene scene = cubeAndSphereScene();
    for (const char* name : {"lfdpr", "lfdpr-paper"}) {
        std::map<Supersampling, double> points;
        for (Supersampling ss : {Supersampling::None, Supersampling::Angular2x, Supersampling::Spatial2x}) {
            player::FramePipeline pipeline(p, scene, 10.0);
            pipeline.setSupersampling(ss);
            auto renderer = player::createRenderer(name);
            player::GpuTimer timer;
            pipeline.renderCompleteFrame(*renderer, 0.5, timer); // settled: its counts are back
            timer.finish();
            for (const auto& [key, value] : renderer->extraStats())
                if (key == "points")
                    points[ss] = value;
        }
        ASSERT_GT(points[Supersampling::None], 0.0) << name;
        EXPECT_EQ(points[Supersampling::Angular2x], points[Supersampling::None]) << name;
        EXPECT_GT(points[Supersampling::Spatial2x], 1.5 * points[Supersampling::None]) << name;
        std::printf("[ points   ] %s: 1x %.0f, 2v %.0f, 2s %.0f\n", name, points[Supersampling::None],
                    points[Supersampling::Angular2x], points[Supersampling::Spatial2x]);
    }
}

} // namespace
} // namespace lfd::test
