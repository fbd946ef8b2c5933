// EIA construction: hand-worked subpixels of the prototype, the subpixel -> channel and
// screen-position rules, and the GPU pass against the CPU reference (bit-exact).
#include "eia_builder.h"

#include "display_test_profiles.h"
#include "gl_test_support.h"
#include "gpu_timer.h"
#include "image_metrics.h"
#include "row_order.h"
#include "simulated_viewer.h"
#include "shader_library.h"
#include "view_targets.h"

#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

using namespace lfd;
using namespace lfd::player;
using namespace lfd::metrics;

namespace {

// Every pixel of view v is (5v, 5v, 5v): an EIA subpixel's value names its view.
std::vector<std::vector<uint8_t>> codedViews(uint32_t count, uint32_t w, uint32_t h) {
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < count; ++v) {
        std::vector<uint8_t> image(size_t(w) * h * 4, uint8_t(5 * v));
        for (size_t i = 3; i < image.size(); i += 4)
            image[i] = 255;
        views.push_back(std::move(image));
    }
    return views;
}

std::vector<std::vector<uint8_t>> randomViews(uint32_t count, uint32_t w, uint32_t h,
                                              unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<std::vector<uint8_t>> views(count, std::vector<uint8_t>(size_t(w) * h * 4));
    for (auto& view : views)
        for (uint8_t& b : view)
            b = uint8_t(byte(rng));
    return views;
}

uint8_t subpixelValue(const std::vector<uint8_t>& eia, uint32_t panelWidth, uint32_t k,
                      uint32_t l, SubpixelOrder order) {
    const uint32_t i = k % 3;
    const uint32_t channel = order == SubpixelOrder::BGR ? 2 - i : i;
    return eia[(size_t(l) * panelWidth + k / 3) * 4 + channel];
}

// Uploads image-order RGBA8 views into the GL view array (GL row 0 = bottom).
void uploadViews(ViewTargets& targets, const std::vector<std::vector<uint8_t>>& views) {
    const uint32_t w = targets.width(), h = targets.height();
    for (uint32_t v = 0; v < targets.viewCount(); ++v) {
        const std::vector<uint8_t> flipped = lfd::gl::flipRows(views[v], size_t(w) * 4);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage3D(targets.colorArray(), 0, 0, 0, GLint(v), GLsizei(w), GLsizei(h), 1,
                            GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
    }
}

// GPU EIA of `views` for `profile`; returns the image and the "eia" stage time in ms.
std::vector<uint8_t> buildEiaGpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views, uint32_t w,
                                 uint32_t h, double* milliseconds = nullptr) {
    ViewTargets targets(profile.viewCount, w, h);
    uploadViews(targets, views);
    EiaBuilder builder(profile);
    GpuTimer timer;
    builder.build(targets, Reconstruction::None, timer);
    timer.finish();
    if (milliseconds)
        *milliseconds = timer.stages().at("eia").mean();
    return builder.read();
}

size_t countDifferences(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        n += a[i] != b[i];
    return n + (a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

} // namespace

TEST(Eia, ParseReconstruction) {
    EXPECT_EQ(parseReconstruction("none"), Reconstruction::None);
    EXPECT_THROW(parseReconstruction("bogus"), std::invalid_argument);
    EXPECT_THROW(parseReconstruction(""), std::invalid_argument);
}

TEST(Eia, ShaderModeConstantsMatchTheEnum) {
    EXPECT_EQ(gl::shaderDefineValue("eia_bindings.glsl", "EIA_MODE_NONE"),
              long(Reconstruction::None));
}

TEST(Eia, PrototypeHandWorkedSubpixels) {
    // Prototype (formats/display_profiles.md section 2): X = 3 * 3840 / 479.36 = 11520 / 479.36
    //   = 24.0320427236...  subpixels per lens; tan(-9.66 deg) = -0.1702146861...
    // phase = fract((k + 0.5 - 3 l tan a) / X), view = floor(48 * phase):
    //   (k, l) = (0, 0):      0.5 / X = 0.0208056;            * 48 = 0.99867 -> view 0
    //   (1, 0):               1.5 / X = 0.0624167;            * 48 = 2.99600 -> view 2
    //   (2, 0):               2.5 / X = 0.1040278;            * 48 = 4.99333 -> view 4
    //   (12, 0):             12.5 / X = 0.5201389;            * 48 = 24.9667 -> view 24
    //   (0, 1):   (0.5 + 0.5106441) / X = 0.0420540;          * 48 = 2.01859 -> view 2
    //   (100, 1000): (100.5 + 510.6441) / X = 25.430383 -> fract 0.430383; * 48 = 20.658 -> view 20
    //   (5000, 7):  (5000.5 + 3.574508) / X = 208.225100 -> 0.225100;     * 48 = 10.805 -> view 10
    //   (11519, 2159): (11519.5 + 1102.4905) / X = 525.214634 -> 0.214634; * 48 = 10.302 -> view 10
    struct Case {
        uint32_t k, l, view;
    };
    const Case cases[] = {{0, 0, 0},       {1, 0, 2},      {2, 0, 4},      {12, 0, 24},
                          {0, 1, 2},       {100, 1000, 20}, {5000, 7, 10}, {11519, 2159, 10}};
    const DisplayProfile profile = prototypeDisplayProfile();
    const auto eia = buildEiaCpu(profile, codedViews(48, 8, 6), 8, 6);
    ASSERT_EQ(eia.size(), size_t(3840) * 2160 * 4);
    for (const Case& c : cases) {
        EXPECT_EQ(subpixelView(profile, c.k, c.l), c.view) << "k=" << c.k << " l=" << c.l;
        EXPECT_EQ(subpixelValue(eia, 3840, c.k, c.l, SubpixelOrder::RGB), 5 * c.view)
            << "k=" << c.k << " l=" << c.l;
    }
    EXPECT_EQ(eia[3], 255); // opaque
}

TEST(Eia, PrototypeViewsShareThePanelEvenly) {
    // Every view gets ~1/48 of the 24.9M subpixels (the mapping is equidistributed).
    const DisplayProfile profile = prototypeDisplayProfile();
    const auto eia = buildEiaCpu(profile, codedViews(48, 4, 3), 4, 3);
    std::vector<size_t> histogram(48, 0);
    for (size_t i = 0; i < eia.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            ++histogram[eia[i + size_t(c)] / 5];
    const double expected = 3.0 * 3840 * 2160 / 48;
    for (uint32_t v = 0; v < 48; ++v)
        EXPECT_NEAR(double(histogram[v]) / expected, 1.0, 0.01) << "view " << v;
}

TEST(Eia, SubpixelTakesItsChannelAtItsScreenPosition) {
    // Views code R = view column, G = view row (image order), B = 10 * view index; each
    // subpixel only shows one channel, so R subpixels reveal the sampled column, G the
    // row and B the view, all checked against the van Berkel formula written out here.
    const DisplayProfile profile = displaytest::smallProfile();
    const uint32_t W = profile.panelWidth, H = profile.panelHeight;
    const uint32_t vw = profile.viewWidth, vh = profile.viewHeight, N = profile.viewCount;
    std::vector<std::vector<uint8_t>> views;
    for (uint32_t v = 0; v < N; ++v) {
        std::vector<uint8_t> image(size_t(vw) * vh * 4);
        for (uint32_t y = 0; y < vh; ++y)
            for (uint32_t x = 0; x < vw; ++x) {
                uint8_t* p = &image[(size_t(y) * vw + x) * 4];
                p[0] = uint8_t(x);
                p[1] = uint8_t(y);
                p[2] = uint8_t(10 * v);
                p[3] = 255;
            }
        views.push_back(std::move(image));
    }
    const auto eia = buildEiaCpu(profile, views, vw, vh);

    const double X = 3.0 * W * profile.lensWidthMm / profile.screenWidthMm; // 12.016
    const double tanA = std::tan(profile.lensTiltDeg * std::numbers::pi / 180.0);
    size_t checked[3] = {0, 0, 0};
    for (uint32_t l = 0; l < H; ++l)
        for (uint32_t k = 0; k < 3 * W; ++k) {
            const uint8_t value = subpixelValue(eia, W, k, l, SubpixelOrder::RGB);
            switch (k % 3) {
            case 0: // red: column of the view pixel under (k + 0.5) / 3W
                ASSERT_EQ(value, uint32_t(std::floor((k + 0.5) / (3.0 * W) * vw))) << k << "," << l;
                break;
            case 1: // green: row of the view pixel under (l + 0.5) / H
                ASSERT_EQ(value, uint32_t(std::floor((l + 0.5) / H * vh))) << k << "," << l;
                break;
            default: { // blue: the view
                const double p = (k + 0.5 - 3.0 * l * tanA) / X;
                const double n = (p - std::floor(p)) * N;
                if (std::abs(n - std::round(n)) < 1e-6)
                    continue; // on a view boundary: rounding decides, not the model
                ASSERT_EQ(value, 10 * uint32_t(std::floor(n))) << k << "," << l;
            }
            }
            ++checked[k % 3];
        }
    EXPECT_GT(checked[2], size_t(W) * H * 99 / 100);
}

TEST(Eia, BgrAndInvertedMappings) {
    const DisplayProfile rgb = displaytest::smallProfile("RGB");
    const DisplayProfile bgr = displaytest::smallProfile("BGR");
    const DisplayProfile inverted = displaytest::smallProfile("RGB", true);
    const uint32_t W = rgb.panelWidth, H = rgb.panelHeight, N = rgb.viewCount;
    const auto views = codedViews(N, 6, 3);
    const auto eiaBgr = buildEiaCpu(bgr, views, 6, 3);
    const auto eiaInv = buildEiaCpu(inverted, views, 6, 3);
    for (uint32_t l = 0; l < H; l += 7)
        for (uint32_t x = 0; x < W; ++x) {
            // BGR: the first physical subpixel (k = 3x) is blue, so channel 2 of EIA pixel x
            // carries the view of subpixel 3x and channel 0 that of subpixel 3x + 2.
            const uint8_t* p = &eiaBgr[(size_t(l) * W + x) * 4];
            ASSERT_EQ(p[2], 5 * subpixelView(rgb, 3 * x, l));
            ASSERT_EQ(p[1], 5 * subpixelView(rgb, 3 * x + 1, l));
            ASSERT_EQ(p[0], 5 * subpixelView(rgb, 3 * x + 2, l));
            // Inverted: view = floor((1 - phase) * N) (phase 0 stays 0).
            for (uint32_t i = 0; i < 3; ++i) {
                const double phase = subpixelPhase(rgb, 3 * x + i, l);
                const double n = phase == 0.0 ? 0.0 : (1.0 - phase) * N;
                if (std::abs(n - std::round(n)) < 1e-9)
                    continue;
                ASSERT_EQ(eiaInv[(size_t(l) * W + x) * 4 + i], 5 * uint32_t(std::floor(n)));
            }
        }
}

TEST(Eia, CpuRejectsMismatchedViews) {
    const DisplayProfile profile = displaytest::smallProfile();
    EXPECT_THROW(buildEiaCpu(profile, codedViews(7, 4, 4), 4, 4), std::invalid_argument);
    auto views = codedViews(8, 4, 4);
    EXPECT_THROW(buildEiaCpu(profile, views, 4, 5), std::invalid_argument);
    views[3].pop_back();
    EXPECT_THROW(buildEiaCpu(profile, views, 4, 4), std::invalid_argument);
}

// ---- GPU (headless GL 4.5; skipped without a context) --------------------------------

class EiaGpu : public lfd::test::GlTest {};

TEST_F(EiaGpu, MatchesCpuReferenceExactly) {
    // Random content: any wrong texel, channel or view shows up as a mismatch. The GPU
    // computes the same double-precision phase and integer texel as the CPU and does not
    // filter, so the tolerance is zero.
    for (const DisplayProfile& profile :
         {displaytest::smallProfile("RGB"), displaytest::smallProfile("BGR"), displaytest::smallProfile("RGB", true)}) {
        const auto views = randomViews(profile.viewCount, profile.viewWidth, profile.viewHeight, 3);
        const auto gpu = buildEiaGpu(profile, views, profile.viewWidth, profile.viewHeight);
        const auto cpu = buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight);
        EXPECT_EQ(countDifferences(gpu, cpu), 0u)
            << (profile.subpixelOrder == SubpixelOrder::BGR ? "BGR" : "RGB")
            << (profile.mapping.invert ? " inverted" : "");
    }
}

TEST_F(EiaGpu, LensOrderCoversEveryPixelOnceOnAnyWidth) {
    // The pass numbers its invocations in lens order (lfd::samePhasePixelStride): with a
    // panel width that is not a multiple of the stride the last run is partial; every
    // pixel must still be written exactly as the CPU reference writes it.
    DisplayProfile profile = displaytest::smallProfile();
    profile.panelWidth = 482;
    const uint32_t stride = samePhasePixelStride(profile, 16, 0.5);
    ASSERT_GT(stride, 1u);
    ASSERT_NE(profile.panelWidth % stride, 0u);
    const auto views = randomViews(profile.viewCount, profile.viewWidth, profile.viewHeight, 5);
    const auto gpu = buildEiaGpu(profile, views, profile.viewWidth, profile.viewHeight);
    EXPECT_EQ(countDifferences(gpu, buildEiaCpu(profile, views, profile.viewWidth, profile.viewHeight)), 0u);
}

TEST_F(EiaGpu, PrototypePanelMatchesCpuAndIsTimed) {
    // The real configuration: 48 views of 480x360 onto the 3840x2160 panel.
    const DisplayProfile profile = prototypeDisplayProfile();
    const auto views = randomViews(48, 480, 360, 11);
    double gpuMs = 0.0;
    const auto gpu = buildEiaGpu(profile, views, 480, 360, &gpuMs);
    const auto start = std::chrono::steady_clock::now();
    const auto cpu = buildEiaCpu(profile, views, 480, 360);
    const double cpuMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(countDifferences(gpu, cpu), 0u);
    std::printf("[ timing   ] EIA 3840x2160, 48 views of 480x360: GPU pass %.1f ms (%s), "
                "CPU reference %.1f ms\n",
                gpuMs, lfd::test::sharedGlContext()->describe().c_str(), cpuMs);
    RecordProperty("eia_gpu_ms", std::to_string(gpuMs));
}

TEST_F(EiaGpu, RejectsWrongViewCount) {
    const DisplayProfile profile = displaytest::smallProfile();
    ViewTargets targets(profile.viewCount - 1, profile.viewWidth, profile.viewHeight);
    EiaBuilder builder(profile);
    GpuTimer timer;
    EXPECT_THROW(builder.build(targets, Reconstruction::None, timer), std::invalid_argument);
}

TEST_F(EiaGpu, RoundTripThroughTheSimulatedViewer) {
    // The GPU EIA seen from each view centre gives back the views (see
    // simulated_viewer_test.cpp for why the tolerance is not zero).
    const DisplayProfile profile = displaytest::smallProfile();
    const auto views = displaytest::smoothViews(profile);
    const uint32_t w = profile.viewWidth, h = profile.viewHeight;
    const auto eia = buildEiaGpu(profile, views, w, h);
    for (uint32_t i = 0; i < profile.viewCount; ++i) {
        const Image seen{w, h, 4, simulateViewer(profile, eia, i + 0.5)};
        EXPECT_GT(psnr(seen, Image{w, h, 4, views[i]}), 40.0) << "view " << i;
    }
}
