// RMSE and PSNR: exact values for constant offsets, the noise level for Gaussian noise,
// masks, and argument checks.
#include "metric_test_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lfd::metrics {
namespace {

using namespace lfd::metrics::test;

TEST(Rmse, IdenticalImagesGiveZeroAndInfinitePsnr)
{
    const RgbImage a = gradientImage(17, 9);
    EXPECT_EQ(rmse(a, a), 0.0);
    EXPECT_EQ(psnr(a, a), std::numeric_limits<double>::infinity());
    EXPECT_EQ(psnrFromRmse(0.0), std::numeric_limits<double>::infinity());
}

TEST(Rmse, ConstantOffsetGivesTheOffset)
{
    // Every R, G, B value differs by d, so the mean squared error is d^2 and rmse = d;
    // PSNR = 20 log10(255 / d): d = 5 gives 20 log10(51) = 34.151403...
    const RgbImage reference = gradientImage(16, 12);
    for (float d : {1.0f, 5.0f, 17.5f}) {
        EXPECT_NEAR(rmse(reference, offsetImage(reference, d)), d, 1e-5) << d;
        EXPECT_NEAR(rmse(reference, offsetImage(reference, -d)), d, 1e-5) << d;
        EXPECT_NEAR(psnr(reference, offsetImage(reference, d)), 20.0 * std::log10(255.0 / d), 1e-5);
    }
    EXPECT_NEAR(psnr(greyImage(4, 4, 100.0f), greyImage(4, 4, 105.0f)), 34.151403521958, 1e-9);
}

TEST(Rmse, OneChannelOffsetCountsOverAllThreeChannels)
{
    // Only R differs, by 6: mean squared error 36 / 3 = 12, rmse sqrt(12) = 3.4641...
    EXPECT_NEAR(rmse(constantImage(3, 5, 10, 20, 30), constantImage(3, 5, 16, 20, 30)),
                std::sqrt(12.0), 1e-12);
}

TEST(Rmse, GaussianNoiseGivesItsStandardDeviation)
{
    const RgbImage reference = greyImage(256, 256, 128.0f); // 196608 noisy values
    for (double sigma : {2.0, 10.0, 25.0}) {
        // float values: rmse estimates sigma with a relative standard error of
        // 1 / sqrt(2 N) = 0.16 %; 1 % is over six standard errors.
        EXPECT_NEAR(rmse(reference, noisyImage(reference, sigma, 7)), sigma, 0.01 * sigma) << sigma;
    }
    // Rounded to 8 bits the noise gains the rounding variance 1/12: sqrt(sigma^2 + 1/12).
    const double rounded = rmse(reference, noisyImage(reference, 3.0, 11, true));
    EXPECT_NEAR(rounded, std::sqrt(9.0 + 1.0 / 12.0), 0.03);
}

TEST(Rmse, MaskSelectsThePixelsCounted)
{
    const RgbImage reference = greyImage(4, 2, 50.0f);
    RgbImage test = reference;
    std::vector<uint8_t> mask(8, 0);
    // Pixels 0 and 1 are masked and differ by 3 in every channel; pixel 7 differs by 100
    // but is not masked.
    for (size_t i : {0u, 1u}) {
        mask[i] = 1;
        for (size_t c = 0; c < 3; ++c)
            test.rgb[i * 3 + c] = 53.0f;
    }
    for (size_t c = 0; c < 3; ++c)
        test.rgb[7 * 3 + c] = 150.0f;
    EXPECT_NEAR(rmse(reference, test, mask), 3.0, 1e-12);
    // Whole image: (2 * 3 * 9 + 3 * 10000) / 24 = 1252.25, rmse 35.387...
    EXPECT_NEAR(rmse(reference, test), std::sqrt(1252.25), 1e-9);
    mask.assign(8, 255);
    EXPECT_NEAR(rmse(reference, test, mask), rmse(reference, test), 1e-12);
}

TEST(Rmse, RejectsMismatchedSizesAndMasks)
{
    const RgbImage a = greyImage(4, 4, 0.0f);
    EXPECT_THROW(rmse(a, greyImage(4, 5, 0.0f)), std::invalid_argument);
    EXPECT_THROW(rmse(a, greyImage(5, 4, 0.0f)), std::invalid_argument);
    EXPECT_THROW(rmse(a, a, std::vector<uint8_t>(15, 1)), std::invalid_argument);
    EXPECT_THROW(rmse(a, a, std::vector<uint8_t>(16, 0)), std::invalid_argument); // selects nothing
    EXPECT_THROW(rmse(RgbImage{}, RgbImage{}), std::invalid_argument);
}

TEST(RgbImage, ConvertsEightBitAndFloatPixels)
{
    const uint8_t greyAlpha[] = {10, 255, 20, 0};
    const RgbImage g = rgbFromPixels8(greyAlpha, 2, 1, 2);
    EXPECT_EQ(g.rgb, (std::vector<float>{10, 10, 10, 20, 20, 20}));
    const uint8_t rgba[] = {1, 2, 3, 4, 5, 6, 7, 8};
    EXPECT_EQ(rgbFromPixels8(rgba, 1, 2, 4).rgb, (std::vector<float>{1, 2, 3, 5, 6, 7}));
    const float linear[] = {0.0f, 0.5f, 1.0f};
    EXPECT_EQ(rgbFromPixelsFloat(linear, 1, 1, 3).rgb, (std::vector<float>{0.0f, 127.5f, 255.0f}));
    EXPECT_THROW(rgbFromPixels8(rgba, 1, 1, 5), std::invalid_argument);
    EXPECT_THROW(rgbFromPixels8(rgba, 0, 1, 3), std::invalid_argument);
    EXPECT_THROW(rgbFromPixels8(nullptr, 1, 1, 3), std::invalid_argument);
}

} // namespace
} // namespace lfd::metrics
