// LDR FLIP (Andersson et al. 2020): zero for identical images, hand-computed values for
// uniform pairs (where the CSF filters and feature detectors leave only the colour term),
// ordering by noise level, the contrast sensitivity filtering, symmetry and arguments.
#include "colour_spaces.h"
#include "metric_test_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::metrics {
namespace {

using namespace lfd::metrics::test;
using detail::Vec3;

// The direct FLIP's CSF filter: a (2r+1)^2 square kernel per YCxCz channel, each channel
// normalised to sum 1 (radius in `r`).
std::vector<Vec3> directCsfKernel(double ppd, int& r)
{
    const double pi = std::numbers::pi;
    const double a1[3] = {1.0, 1.0, 34.1}, b1[3] = {0.0047, 0.0053, 0.04};
    const double a2[3] = {0.0, 0.0, 13.5}, b2[3] = {1e-5, 1e-5, 0.025};
    r = int(std::ceil(3.0 * std::sqrt(0.04 / (2.0 * pi * pi)) * ppd));
    const int n = 2 * r + 1;
    std::vector<Vec3> csf(size_t(n * n));
    Vec3 sum{};
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const double d2 = double(dx * dx + dy * dy) / (ppd * ppd);
            for (size_t c = 0; c < 3; ++c) {
                const double v = a1[c] * std::sqrt(pi / b1[c]) * std::exp(-pi * pi * d2 / b1[c]) +
                                 a2[c] * std::sqrt(pi / b2[c]) * std::exp(-pi * pi * d2 / b2[c]);
                csf[size_t((dy + r) * n + dx + r)][c] = v;
                sum[c] += v;
            }
        }
    for (Vec3& v : csf)
        for (size_t c = 0; c < 3; ++c)
            v[c] /= sum[c];
    return csf;
}

// The direct FLIP's 2D edge and point detectors along x (radius in `r`), their positive
// and negative weights normalised to 1 and -1.
void directFeatureKernels(double ppd, int& r, std::vector<double>& edge, std::vector<double>& point)
{
    const double sigma = 0.5 * 0.082 * ppd;
    r = int(std::ceil(3.0 * sigma));
    const int n = 2 * r + 1;
    edge.assign(size_t(n * n), 0.0);
    point.assign(size_t(n * n), 0.0);
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const double g = std::exp(-(dx * dx + dy * dy) / (2.0 * sigma * sigma));
            edge[size_t((dy + r) * n + dx + r)] = -dx * g;
            point[size_t((dy + r) * n + dx + r)] = (dx * dx / (sigma * sigma) - 1.0) * g;
        }
    for (std::vector<double>* k : {&edge, &point}) {
        double pos = 0.0, neg = 0.0;
        for (double v : *k)
            (v > 0 ? pos : neg) += std::abs(v);
        for (double& v : *k)
            v /= v > 0 ? pos : neg;
    }
}

// FLIP evaluated directly as the paper describes it, in double precision with square 2D
// kernels (no separable decomposition): the CSF filters as sums of Gaussians over the
// (2r+1)^2 support normalised to sum 1, and the 2D edge and point detectors with their
// positive and negative weights normalised to 1 and -1. Only the colour transforms are
// shared with the library (they are checked by the uniform-image values below).
std::vector<double> directFlipMap(const RgbImage& reference, const RgbImage& test, double ppd)
{
    const int w = reference.width, h = reference.height;
    auto at = [&](int x, int y) { return size_t(std::clamp(y, 0, h - 1)) * size_t(w) + size_t(std::clamp(x, 0, w - 1)); };
    auto ycxcz = [&](const RgbImage& im) {
        std::vector<Vec3> out(im.pixelCount());
        for (size_t i = 0; i < out.size(); ++i) {
            Vec3 rgb;
            for (size_t c = 0; c < 3; ++c)
                rgb[c] = detail::srgbToLinear(std::clamp(double(im.rgb[i * 3 + c]), 0.0, 255.0) / 255.0);
            out[i] = detail::xyzToYcxcz(detail::linearRgbToXyz(rgb));
        }
        return out;
    };
    int rc = 0;
    const std::vector<Vec3> csf = directCsfKernel(ppd, rc);
    const int nc = 2 * rc + 1;
    int rf = 0;
    std::vector<double> edge, point;
    directFeatureKernels(ppd, rf, edge, point);
    const int nf = 2 * rf + 1;
    auto hunt = [](const Vec3& rgb) { return detail::huntAdjust(detail::xyzToLab(detail::linearRgbToXyz(rgb))); };
    const double cmax = std::pow(detail::hyab(hunt({0, 1, 0}), hunt({0, 0, 1})), 0.7);

    struct Pixel {
        Vec3 lab;
        double edge, point;
    };
    auto pipeline = [&](const RgbImage& im) {
        const std::vector<Vec3> ycc = ycxcz(im);
        std::vector<Pixel> out(ycc.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                Vec3 f{};
                for (int dy = -rc; dy <= rc; ++dy)
                    for (int dx = -rc; dx <= rc; ++dx)
                        for (size_t c = 0; c < 3; ++c)
                            f[c] += csf[size_t((dy + rc) * nc + dx + rc)][c] * ycc[at(x + dx, y + dy)][c];
                Vec3 rgb = detail::xyzToLinearRgb(detail::ycxczToXyz(f));
                for (double& v : rgb)
                    v = std::clamp(v, 0.0, 1.0);
                double ex = 0, ey = 0, px = 0, py = 0;
                for (int dy = -rf; dy <= rf; ++dy)
                    for (int dx = -rf; dx <= rf; ++dx) {
                        const double lum = (ycc[at(x + dx, y + dy)][0] + 16.0) / 116.0;
                        ex += edge[size_t((dy + rf) * nf + dx + rf)] * lum;
                        ey += edge[size_t((dx + rf) * nf + dy + rf)] * lum; // transposed
                        px += point[size_t((dy + rf) * nf + dx + rf)] * lum;
                        py += point[size_t((dx + rf) * nf + dy + rf)] * lum;
                    }
                out[size_t(y) * size_t(w) + size_t(x)] = {hunt(rgb), std::hypot(ex, ey), std::hypot(px, py)};
            }
        return out;
    };
    const std::vector<Pixel> r = pipeline(reference), t = pipeline(test);
    std::vector<double> error(r.size());
    for (size_t i = 0; i < r.size(); ++i) {
        const double e = std::pow(detail::hyab(r[i].lab, t[i].lab), 0.7);
        const double colour = e < 0.4 * cmax ? e * 0.95 / (0.4 * cmax)
                                             : 0.95 + (e - 0.4 * cmax) / (cmax - 0.4 * cmax) * 0.05;
        const double feature =
            std::sqrt(std::max(std::abs(r[i].edge - t[i].edge), std::abs(r[i].point - t[i].point)) / std::sqrt(2.0));
        error[i] = std::pow(colour, 1.0 - feature);
    }
    return error;
}

TEST(Flip, DefaultObserverIs67PixelsPerDegree)
{
    // 0.7 m * (3840 px / 0.7 m) * pi / 180 = 67.0206 pixels per degree.
    EXPECT_NEAR(defaultFlipPixelsPerDegree(), 67.02064327658, 1e-9);
    EXPECT_NEAR(pixelsPerDegree(1.0, 0.5, 1920.0), 1920.0 / 0.5 * std::numbers::pi / 180.0, 1e-12);
}

TEST(Flip, IdenticalImagesGiveZeroEverywhere)
{
    const RgbImage a = noisyImage(gradientImage(24, 20), 30.0, 1);
    const std::vector<float> map = flipErrorMap(a, a);
    ASSERT_EQ(map.size(), a.pixelCount());
    EXPECT_TRUE(std::all_of(map.begin(), map.end(), [](float e) { return e == 0.0f; }));
    EXPECT_EQ(flip(a, a), 0.0);
}

// Uniform images: the normalised CSF filters leave a constant image unchanged and the
// feature detectors (derivatives) give 0, so the feature difference is 0 and FLIP equals
// the colour error. Worked by hand from the paper's definitions with D65 sRGB:
//   Hunt-adjusted L*a*b* of linear green (0,1,0) = (87.735, -75.612, 72.977), of blue
//   (0,0,1) = (32.297, 25.575, -34.836); HyAB = 55.438 + 147.860 = 203.297;
//   cmax = 203.297^0.7 = 41.2755; knee pc * cmax = 16.5102.
// Black (L* 0) vs white (L* 100), a* = b* = 0: HyAB = 100, 100^0.7 = 25.1189 >= knee, so
//   error = 0.95 + (25.1189 - 16.5102) / (41.2755 - 16.5102) * 0.05 = 0.96738.
// sRGB grey 100 has L* = 42.3746: 42.3746^0.7 = 13.7966 < knee, error = 13.7966 * 0.95 /
//   16.5102 = 0.79240.
TEST(Flip, SeparableFiltersMatchTheDirectTwoDimensionalDefinition)
{
    // Colour noise plus sharp edges, so the colour and the feature terms both matter.
    const RgbImage reference = noisyImage(gradientImage(26, 19), 20.0, 41);
    RgbImage test = noisyImage(reference, 25.0, 42);
    const RgbImage squares = checkerboard(26, 19, 5, 0.0f, 255.0f);
    for (size_t i = 0; i < test.rgb.size(); i += 7)
        test.rgb[i] = squares.rgb[i];
    for (double ppd : {defaultFlipPixelsPerDegree(), 20.0}) {
        const std::vector<float> map = flipErrorMap(reference, test, ppd);
        const std::vector<double> direct = directFlipMap(reference, test, ppd);
        ASSERT_EQ(map.size(), direct.size());
        double worst = 0.0;
        for (size_t i = 0; i < map.size(); ++i)
            worst = std::max(worst, std::abs(double(map[i]) - direct[i]));
        EXPECT_LT(worst, 1e-5) << "ppd " << ppd; // float planes against double sums: ~5e-7
    }
}

TEST(Flip, BlackAgainstWhiteIsCloseToOne)
{
    const RgbImage black = greyImage(16, 16, 0.0f), white = greyImage(16, 16, 255.0f);
    EXPECT_NEAR(flip(black, white), 0.967381, 2e-4);
    const std::vector<float> map = flipErrorMap(black, white);
    for (float e : map)
        EXPECT_NEAR(e, 0.967381, 2e-4);
}

TEST(Flip, UniformGreyAgainstBlackFollowsTheColourMapping)
{
    EXPECT_NEAR(flip(greyImage(12, 12, 0.0f), greyImage(12, 12, 100.0f)), 0.792402, 2e-4);
}

TEST(Flip, IncreasesWithTheNoiseLevel)
{
    const RgbImage reference = gradientImage(48, 48);
    double previous = 0.0;
    for (double sigma : {2.0, 8.0, 32.0}) {
        const double f = flip(reference, noisyImage(reference, sigma, 21));
        EXPECT_GT(f, previous) << sigma;
        EXPECT_LT(f, 1.0) << sigma;
        previous = f;
    }
}

TEST(Flip, IsSymmetricAndStaysInZeroToOne)
{
    const RgbImage a = noisyImage(gradientImage(30, 22), 25.0, 2);
    const RgbImage b = checkerboard(30, 22, 3, 0.0f, 255.0f);
    EXPECT_NEAR(flip(a, b), flip(b, a), 1e-6);
    for (float e : flipErrorMap(a, b)) {
        EXPECT_GE(e, 0.0f);
        EXPECT_LE(e, 1.0f);
    }
}

TEST(Flip, FinePatternsAreLessVisibleThanCoarseOnes)
{
    // The contrast sensitivity filters blur a one-pixel checkerboard at 67 PPD (0.015
    // degrees per cell) almost to its mean, while 16-pixel cells stay visible: against a
    // uniform grey of the same mean the fine pattern scores much lower.
    const RgbImage grey = greyImage(64, 64, 128.0f);
    const RgbImage fine = checkerboard(64, 64, 1, 64.0f, 192.0f);
    const RgbImage coarse = checkerboard(64, 64, 16, 64.0f, 192.0f);
    const double fineError = flip(grey, fine);
    EXPECT_LT(fineError, 0.5 * flip(grey, coarse));
    // Seen from closer (10 PPD: a cell spans 0.1 degree) the same fine pattern is visible.
    EXPECT_GT(flip(grey, fine, 10.0), fineError);
}

TEST(Flip, RejectsMismatchedSizesAndBadPixelsPerDegree)
{
    const RgbImage a = greyImage(8, 8, 0.0f);
    EXPECT_THROW(flip(a, greyImage(8, 9, 0.0f)), std::invalid_argument);
    EXPECT_THROW(flip(a, a, 0.0), std::invalid_argument);
    EXPECT_THROW(flip(a, a, -5.0), std::invalid_argument);
    EXPECT_THROW(flip(a, a, std::nan("")), std::invalid_argument);
    EXPECT_THROW(flip(a, a, 1e6), std::invalid_argument);
}

} // namespace
} // namespace lfd::metrics
