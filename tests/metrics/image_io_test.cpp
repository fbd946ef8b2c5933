// Reading images into RgbImage (8-bit exactly, 16-bit scaled, grey and alpha handled) and
// one-line errors naming the file.
#include "metric_test_images.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lfd::metrics {
namespace {

class ImageIo : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("lfd_metrics_io_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    template <typename T>
    fs::path write(const std::string& name, const std::vector<T>& pixels, int w, int h, int channels,
                   OIIO::TypeDesc type)
    {
        const fs::path path = dir_ / name;
        auto out = OIIO::ImageOutput::create(path.string());
        OIIO::ImageSpec spec(w, h, channels, type);
        spec.attribute("oiio:UnassociatedAlpha", 1); // store the colour values as given
        EXPECT_TRUE(out && out->open(path.string(), spec));
        EXPECT_TRUE(out->write_image(type, pixels.data()));
        out->close();
        return path;
    }

    fs::path dir_;
};

TEST_F(ImageIo, RgbPngRoundTripsExactly)
{
    const std::vector<uint8_t> rgb = {0, 1, 2, 253, 254, 255};
    writeRgb8Image(dir_ / "a.png", rgb, 2, 1);
    const RgbImage image = readRgbImage(dir_ / "a.png");
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 1);
    EXPECT_EQ(image.rgb, (std::vector<float>{0, 1, 2, 253, 254, 255}));
}

TEST_F(ImageIo, GreyIsReplicatedAndAlphaDropped)
{
    const fs::path grey = write("grey.png", std::vector<uint8_t>{7, 200}, 2, 1, 1, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(readRgbImage(grey).rgb, (std::vector<float>{7, 7, 7, 200, 200, 200}));
    const fs::path rgba = write("rgba.png", std::vector<uint8_t>{10, 20, 30, 0}, 1, 1, 4, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(readRgbImage(rgba).rgb, (std::vector<float>{10, 20, 30}));
}

TEST_F(ImageIo, SixteenBitIsScaledToTheEightBitRange)
{
    const fs::path path = write("deep.png", std::vector<uint16_t>{0, 65535, 32768}, 1, 1, 3,
                                OIIO::TypeDesc::UINT16);
    const RgbImage image = readRgbImage(path);
    EXPECT_NEAR(image.rgb[0], 0.0f, 1e-4);
    EXPECT_NEAR(image.rgb[1], 255.0f, 1e-3);
    EXPECT_NEAR(image.rgb[2], 255.0f * 32768.0f / 65535.0f, 1e-3);
}

TEST_F(ImageIo, ErrorsAreOneLineNamingTheFile)
{
    auto expectError = [](const fs::path& path, const std::string& problem) {
        try {
            readRgbImage(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const ImageError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(path.string()), std::string::npos) << what;
            EXPECT_NE(what.find(problem), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    };
    expectError(dir_ / "absent.png", "no such file");
    std::ofstream(dir_ / "text.png") << "not an image\n";
    expectError(dir_ / "text.png", "cannot read image");
    expectError(dir_, "is a directory");
}

TEST_F(ImageIo, HdrIsReadAsFloatAndATruncatedOneIsAnErrorNotAHang)
{
    // 16 wide: written with RLE scanlines, the layout stb_image 2.27 hangs on when cut short.
    std::vector<float> pixels(16 * 2 * 3);
    for (size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = float(i % 5) * 0.25f;
    const fs::path path = write("sky.hdr", pixels, 16, 2, 3, OIIO::TypeDesc::FLOAT);
    const RgbImage image = readRgbImage(path);
    ASSERT_EQ(image.width, 16);
    EXPECT_NEAR(image.rgb[7], 255.0f * 0.5f, 1e-3); // value 2 * 0.25, 1.0 = 255
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    ASSERT_GT(bytes.size(), 40u);
    for (const size_t cut : {bytes.size() - 1, bytes.size() - 20, bytes.size() - 40}) {
        std::ofstream(dir_ / "cut.hdr", std::ios::binary).write(bytes.data(), std::streamsize(cut));
        for (const bool eightBit : {false, true}) {
            try {
                if (eightBit)
                    readImage(dir_ / "cut.hdr");
                else
                    readRgbImage(dir_ / "cut.hdr");
                ADD_FAILURE() << "no error for a file cut to " << cut << " bytes";
            } catch (const ImageError& e) {
                EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
            }
        }
    }
}

} // namespace
} // namespace lfd::metrics
