// LDR FLIP (Andersson et al. 2020): zero for identical images, hand-computed values for
// uniform pairs (where the CSF filters and feature detectors leave only the colour term),
// ordering by noise level, the contrast sensitivity filtering, symmetry and arguments.
#include "metric_test_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::metrics {
namespace {

using namespace lfd::metrics::test;

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
