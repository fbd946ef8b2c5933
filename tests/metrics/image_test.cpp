// PNG output (atomic writes, round trips) and the image metrics (CPU only).
#include "image_file.h"
#include "image_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lfd::metrics;

namespace {

class ImageFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("lfd_image_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    size_t entriesInDir() const {
        return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }

    fs::path dir_;
};

Image gradient(uint32_t w, uint32_t h, uint32_t channels) {
    Image image{w, h, channels, std::vector<uint8_t>(size_t(w) * h * channels)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (uint32_t c = 0; c < channels; ++c)
                image.pixels[(size_t(y) * w + x) * channels + c] =
                    uint8_t((x * 7 + y * 13 + c * 60) % 256);
    return image;
}

TEST_F(ImageFileTest, RoundTripRgba8AndRgb8) {
    for (uint32_t channels : {4u, 3u}) {
        const Image original = gradient(37, 19, channels); // odd sizes: no row padding games
        const fs::path path = dir_ / ("img" + std::to_string(channels) + ".png");
        writeImage(path, original);
        const Image back = readImage(path);
        EXPECT_EQ(back.width, original.width);
        EXPECT_EQ(back.height, original.height);
        EXPECT_EQ(back.channels, channels);
        EXPECT_EQ(back.pixels, original.pixels) << channels << " channels";
    }
    // Only the two images: no temporary files left behind.
    EXPECT_EQ(entriesInDir(), 2u);
}

TEST_F(ImageFileTest, ReadConvertsChannels) {
    const Image rgb = gradient(5, 4, 3);
    writeImage(dir_ / "rgb.png", rgb);
    const Image rgba = readImage(dir_ / "rgb.png", 4);
    ASSERT_EQ(rgba.channels, 4u);
    for (size_t i = 0; i < 20; ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(rgba.pixels[i * 4 + c], rgb.pixels[i * 3 + c]);
        EXPECT_EQ(rgba.pixels[i * 4 + 3], 255); // missing alpha = opaque
    }
}

TEST_F(ImageFileTest, OverwriteReplacesAtomically) {
    const fs::path path = dir_ / "view.png";
    writeImage(path, gradient(8, 8, 4));
    Image second = gradient(8, 8, 4);
    second.pixels[0] = 99;
    writeImage(path, second);
    EXPECT_EQ(readImage(path).pixels, second.pixels);
    EXPECT_EQ(entriesInDir(), 1u);
}

TEST_F(ImageFileTest, FailedWriteThrowsOneLineAndLeavesNothing) {
    const Image image = gradient(4, 4, 4);
    const fs::path missing = dir_ / "no_such_dir" / "out.png";
    try {
        writeImage(missing, image);
        FAIL() << "writing into a missing directory must throw";
    } catch (const ImageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(missing.parent_path()));
    EXPECT_EQ(entriesInDir(), 0u);

    // A format OpenImageIO cannot write: also an error naming the file, nothing left.
    EXPECT_THROW(writeImage(dir_ / "out.notaformat", image), ImageError);
    // Bad arguments are rejected before anything is created.
    EXPECT_THROW(writeImage(dir_ / "five.png", image.pixels.data(), 2, 2, 5), ImageError);
    Image wrongSize = image;
    wrongSize.pixels.pop_back();
    EXPECT_THROW(writeImage(dir_ / "short.png", wrongSize), ImageError);
    EXPECT_EQ(entriesInDir(), 0u);
}

// The formats the tools check their output names against before rendering: exactly what
// writeImage encodes, by extension in any case.
TEST_F(ImageFileTest, ImageFormatProblemMatchesWhatWriteImageWrites) {
    const Image image = gradient(4, 4, 3);
    for (const char* name : {"a.png", "b.PNG", "c.jpg", "d.JPEG", "e.bmp", "f.Tga"}) {
        EXPECT_EQ(imageFormatProblem(name), "") << name;
        EXPECT_NO_THROW(writeImage(dir_ / name, image)) << name;
    }
    EXPECT_EQ(imageFormatProblem("g.exr"), "cannot write this image format '.exr' (write .png, .jpg, .bmp or .tga)");
    EXPECT_EQ(imageFormatProblem("dir.png/h"), "has no image extension (write .png, .jpg, .bmp or .tga)");
    for (const char* name : {"g.exr", "h", "i.webp", "j.png.gz"}) {
        EXPECT_NE(imageFormatProblem(name), "") << name;
        try {
            writeImage(dir_ / name, image);
            FAIL() << name << " was written";
        } catch (const ImageError& e) {
            EXPECT_NE(std::string(e.what()).find(imageFormatProblem(name)), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(entriesInDir(), 6u);
}

TEST_F(ImageFileTest, ReadMissingFileThrowsNamingIt) {
    const fs::path path = dir_ / "absent.png";
    try {
        readImage(path);
        FAIL() << "reading a missing file must throw";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

TEST(ImageMetrics, RmseAndMaxDiffHandComputed) {
    // 2x1 RGBA: the first pixel differs by (3, 4, 0) in colour and by 200 in alpha (alpha
    // is ignored). Sum of squares 9 + 16 = 25 over 2 pixels x 3 channels:
    // RMSE = sqrt(25 / 6) = 2.0412414523...
    const Image a{2, 1, 4, {0, 0, 0, 255, 10, 20, 30, 255}};
    const Image b{2, 1, 4, {3, 4, 0, 55, 10, 20, 30, 255}};
    EXPECT_NEAR(rmse(a, b), std::sqrt(25.0 / 6.0), 1e-12);
    EXPECT_EQ(maxAbsDiff(a, b), 4);
    // PSNR = 20 log10(255 / RMSE) = 41.8909...
    EXPECT_NEAR(psnr(a, b), 20.0 * std::log10(255.0 / std::sqrt(25.0 / 6.0)), 1e-9);
    EXPECT_EQ(rmse(a, a), 0.0);
    EXPECT_TRUE(std::isinf(psnr(a, a)));

    // RGB vs RGBA of the same colours compare equal.
    const Image rgb{2, 1, 3, {0, 0, 0, 10, 20, 30}};
    EXPECT_EQ(rmse(a, rgb), 0.0);

    const Image other{1, 2, 4, std::vector<uint8_t>(8, 0)};
    EXPECT_THROW(rmse(a, other), std::invalid_argument);
    EXPECT_THROW(ssim(a, other), std::invalid_argument);
}

TEST(ImageMetrics, SsimIdenticalIsOneAndNoiseLowersIt) {
    const Image clean = gradient(64, 48, 3);
    EXPECT_NEAR(ssim(clean, clean), 1.0, 1e-12);

    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 20.0);
    Image noisy = clean;
    for (uint8_t& p : noisy.pixels)
        p = uint8_t(std::clamp(std::lround(p + noise(rng)), 0L, 255L));
    const double s = ssim(clean, noisy);
    EXPECT_LT(s, 0.95);
    EXPECT_GT(s, 0.0);
    EXPECT_NEAR(s, ssim(noisy, clean), 1e-12); // symmetric

    // Less noise, higher SSIM.
    Image slightlyNoisy = clean;
    std::normal_distribution<double> small(0.0, 3.0);
    for (uint8_t& p : slightlyNoisy.pixels)
        p = uint8_t(std::clamp(std::lround(p + small(rng)), 0L, 255L));
    EXPECT_GT(ssim(clean, slightlyNoisy), s);

    // Images smaller than the 11x11 window still work (the window shrinks).
    const Image tiny = gradient(5, 4, 3);
    EXPECT_NEAR(ssim(tiny, tiny), 1.0, 1e-12);
}

TEST(ImageMetrics, SsimOfConstantShiftMatchesFormula) {
    // Two constant images (luma 100 and 110): variances and covariance are 0, so SSIM =
    // (2 * 100 * 110 + C1) / (100^2 + 110^2 + C1) with C1 = (0.01 * 255)^2 = 6.5025.
    const Image a{16, 16, 1, std::vector<uint8_t>(256, 100)};
    const Image b{16, 16, 1, std::vector<uint8_t>(256, 110)};
    const double C1 = 6.5025;
    EXPECT_NEAR(ssim(a, b), (2.0 * 100 * 110 + C1) / (100.0 * 100 + 110.0 * 110 + C1), 1e-9);
}

TEST_F(ImageFileTest, DiffImageIsScaledAbsoluteDifference) {
    const Image a{2, 1, 4, {10, 20, 30, 255, 0, 0, 0, 255}};
    const Image b{2, 1, 4, {13, 10, 30, 0, 100, 0, 0, 255}};
    const fs::path path = dir_ / "diff.png";
    writeDiffImage(path, a, b, 8.0f);
    const Image diff = readImage(path);
    ASSERT_EQ(diff.channels, 3u);
    EXPECT_EQ(diff.pixels, (std::vector<uint8_t>{24, 80, 0, 255, 0, 0}));
}

} // namespace
