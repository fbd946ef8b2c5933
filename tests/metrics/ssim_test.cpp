// SSIM (Wang et al. 2004): hand-worked uniform cases, identity, symmetry, ordering by
// distortion, masks, and the separable implementation against a direct evaluation of
// eq. 13 with the 11x11 Gaussian window.
#include "metric_test_images.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lfd::metrics {
namespace {

using namespace lfd::metrics::test;

constexpr double kC1 = 6.5025;  // (0.01 * 255)^2
constexpr double kC2 = 58.5225; // (0.03 * 255)^2

// Direct evaluation: for every 11x11 window inside the image, the Gaussian-weighted (sigma
// 1.5, weights summing to 1) means, variances and covariance of the luma, then eq. 13.
double directSsim(const RgbImage& a, const RgbImage& b)
{
    auto luma = [](const RgbImage& im, int x, int y) {
        const float* p = &im.rgb[(size_t(y) * size_t(im.width) + size_t(x)) * 3];
        return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    };
    double weights[11][11], total = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i)
            total += weights[j][i] = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2 * 1.5 * 1.5));
    double sum = 0.0;
    int count = 0;
    for (int y0 = 0; y0 + 11 <= a.height; ++y0)
        for (int x0 = 0; x0 + 11 <= a.width; ++x0) {
            double mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) {
                    const double w = weights[j][i] / total;
                    const double x = luma(a, x0 + i, y0 + j), y = luma(b, x0 + i, y0 + j);
                    mx += w * x;
                    my += w * y;
                    xx += w * x * x;
                    yy += w * y * y;
                    xy += w * x * y;
                }
            const double vx = xx - mx * mx, vy = yy - my * my, cxy = xy - mx * my;
            sum += (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
            ++count;
        }
    return sum / count;
}

TEST(Ssim, IdenticalImagesGiveOne)
{
    const RgbImage a = noisyImage(gradientImage(32, 24), 20.0, 3);
    EXPECT_DOUBLE_EQ(ssim(a, a), 1.0);
    EXPECT_DOUBLE_EQ(ssim(greyImage(12, 12, 0.0f), greyImage(12, 12, 0.0f)), 1.0);
}

TEST(Ssim, UniformPairReducesToTheLuminanceTerm)
{
    // Two uniform grey images, luma x = 100 and y = 110 everywhere (for grey R = G = B the
    // luma weights 0.299 + 0.587 + 0.114 sum to 1). In every window mu_x = 100, mu_y = 110
    // and sigma_x = sigma_y = sigma_xy = 0, so the contrast-structure factor is
    // (2 * 0 + C2) / (0 + 0 + C2) = 1 and
    //   SSIM = (2 * 100 * 110 + C1) / (100^2 + 110^2 + C1)
    //        = 22006.5025 / 22106.5025 = 0.99547644409...
    // with C1 = (0.01 * 255)^2 = 6.5025.
    EXPECT_NEAR(ssim(greyImage(16, 16, 100.0f), greyImage(16, 16, 110.0f)), 0.9954764440915, 1e-9);
    // Black against white-ish: x = 50, y = 200: (20000 + C1) / (42500 + C1) = 0.47066922...
    EXPECT_NEAR(ssim(greyImage(16, 16, 50.0f), greyImage(16, 16, 200.0f)), 0.4706692229030, 1e-9);
    // Images smaller than the window (5x5) use a smaller window; the uniform case is the same.
    EXPECT_NEAR(ssim(greyImage(5, 5, 100.0f), greyImage(5, 5, 110.0f)), 0.9954764440915, 1e-9);
}

TEST(Ssim, IsSymmetricAndBelowOneForDifferentImages)
{
    const RgbImage a = noisyImage(gradientImage(40, 30), 10.0, 5);
    const RgbImage b = noisyImage(gradientImage(40, 30), 10.0, 6);
    const double ab = ssim(a, b), ba = ssim(b, a);
    EXPECT_NEAR(ab, ba, 1e-12);
    EXPECT_LT(ab, 1.0);
    EXPECT_GT(ab, -1.0);
}

TEST(Ssim, MatchesADirectEvaluationOfTheWindowedIndex)
{
    const RgbImage a = noisyImage(gradientImage(23, 17), 30.0, 8);
    const RgbImage b = noisyImage(a, 15.0, 9);
    EXPECT_NEAR(ssim(a, b), directSsim(a, b), 1e-10);
}

TEST(Ssim, BandsOfWindowRowsMatchTheDirectEvaluation)
{
    // 150 rows: 140 window rows, three bands of 64 (common/parallel.h), each filtering the
    // rows above its first window again; a mask that keeps only the rows around the seams.
    const RgbImage a = noisyImage(gradientImage(31, 150), 30.0, 10);
    const RgbImage b = noisyImage(a, 15.0, 11);
    EXPECT_NEAR(ssim(a, b), directSsim(a, b), 1e-10);
    std::vector<uint8_t> mask(size_t(31) * 150, 0);
    for (int y : {68, 69, 70, 132, 133, 134})
        for (int x = 0; x < 31; ++x)
            mask[size_t(y) * 31 + size_t(x)] = 1;
    const double masked = ssim(a, b, mask);
    EXPECT_GT(masked, -1.0);
    EXPECT_LT(masked, 1.0);
}

TEST(Ssim, DecreasesWithTheNoiseLevel)
{
    const RgbImage reference = gradientImage(48, 48);
    double previous = 1.0;
    for (double sigma : {2.0, 8.0, 32.0}) {
        const double s = ssim(reference, noisyImage(reference, sigma, 4));
        EXPECT_LT(s, previous) << sigma;
        previous = s;
    }
}

TEST(Ssim, MaskCountsOnlyWindowsCentredOnMaskedPixels)
{
    // 40x20: the left half equal, the right half noisy. A mask over columns 5..12 only
    // selects windows (radius 5) that lie wholly in the equal half: SSIM exactly 1 there.
    const RgbImage reference = gradientImage(40, 20);
    RgbImage test = reference;
    const RgbImage noisy = noisyImage(reference, 20.0, 12);
    for (int y = 0; y < 20; ++y)
        for (int x = 20; x < 40; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * 40 + size_t(x)) * 3 + size_t(c);
                test.rgb[i] = noisy.rgb[i];
            }
    std::vector<uint8_t> mask(40 * 20, 0);
    for (int y = 0; y < 20; ++y)
        for (int x = 5; x <= 12; ++x)
            mask[size_t(y) * 40 + size_t(x)] = 1;
    EXPECT_DOUBLE_EQ(ssim(reference, test, mask), 1.0);
    EXPECT_LT(ssim(reference, test), 0.9);
    // A mask of every pixel is the whole-image SSIM.
    EXPECT_NEAR(ssim(reference, test, std::vector<uint8_t>(40 * 20, 1)), ssim(reference, test), 1e-12);
    // Masked pixels only in the 5-pixel border: no window is centred on them.
    std::vector<uint8_t> border(40 * 20, 0);
    border[0] = 1;
    EXPECT_THROW(ssim(reference, test, border), std::invalid_argument);
    EXPECT_THROW(ssim(reference, test, std::vector<uint8_t>(3, 1)), std::invalid_argument);
}

TEST(Ssim, RejectsMismatchedSizes)
{
    EXPECT_THROW(ssim(greyImage(12, 12, 0.0f), greyImage(12, 13, 0.0f)), std::invalid_argument);
}

} // namespace
} // namespace lfd::metrics
