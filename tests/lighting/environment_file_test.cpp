// .hdr environments: a written file read back, and every bad input answered by one line
// naming the file: missing, a directory, another format, too large, not 2:1, corrupt RLE
// data and truncation at every length (which hung stb_image 2.27 before the guard).
#include "environment_file.h"

#include <gtest/gtest.h>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace lfd::lighting {
namespace {

namespace fs = std::filesystem;

class EnvironmentFile : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("lfd_environment_file_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A w x h .hdr whose texel (x, y) holds (x + 1, y + 1, 0.5) / 8 (exact in RGBE).
    fs::path writeHdr(const std::string& name, int w, int h)
    {
        std::vector<float> pixels(size_t(w) * h * 3);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float* p = pixels.data() + (size_t(y) * w + x) * 3;
                p[0] = float(x + 1) / 8.0f;
                p[1] = float(y + 1) / 8.0f;
                p[2] = 0.5f / 8.0f;
            }
        const fs::path path = dir_ / name;
        EXPECT_TRUE(stbi_write_hdr(path.c_str(), w, h, 3, pixels.data()));
        return path;
    }
    fs::path writeBytes(const std::string& name, const std::vector<char>& bytes)
    {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        return path;
    }
    static std::vector<char> readBytes(const fs::path& path)
    {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    // The one-line error loadEnvironment gives (empty when it does not throw).
    static std::string loadError(const fs::path& path)
    {
        try {
            loadEnvironment(path);
        } catch (const EnvironmentError& e) {
            return e.what();
        }
        return {};
    }
    static void expectOneLineNaming(const std::string& error, const fs::path& path, const std::string& problem)
    {
        EXPECT_NE(error.find(path.string()), std::string::npos) << error;
        EXPECT_NE(error.find(problem), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }

    fs::path dir_;
};

TEST_F(EnvironmentFile, ReadsWhatStbWrote)
{
    // 32 wide: stb writes RLE scanlines (8 <= width < 32768).
    const Environment e = loadEnvironment(writeHdr("sky.hdr", 32, 16));
    ASSERT_EQ(e.width, 32u);
    ASSERT_EQ(e.height, 16u);
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 32; ++x) {
            const glm::vec3 t = e.texel(x, y);
            ASSERT_FLOAT_EQ(t.r, float(x + 1) / 8.0f) << x << "," << y; // row 0 = the file's first (top) row
            ASSERT_FLOAT_EQ(t.g, float(y + 1) / 8.0f);
            ASSERT_FLOAT_EQ(t.b, 0.5f / 8.0f);
        }
}

TEST_F(EnvironmentFile, ReadsFlatScanlines)
{
    const Environment e = loadEnvironment(writeHdr("small.hdr", 4, 2)); // narrower than 8: flat
    ASSERT_EQ(e.width, 4u);
    EXPECT_FLOAT_EQ(e.texel(3, 1).r, 0.5f);
}

TEST_F(EnvironmentFile, MissingDirectoryAndOtherFormats)
{
    expectOneLineNaming(loadError(dir_ / "none.hdr"), dir_ / "none.hdr", "no such file");
    expectOneLineNaming(loadError(dir_), dir_, "is a directory");
    const fs::path text = writeBytes("notes.hdr", {'h', 'e', 'l', 'l', 'o', '\n'});
    expectOneLineNaming(loadError(text), text, "not a Radiance .hdr file");
    const fs::path empty = writeBytes("empty.hdr", {});
    expectOneLineNaming(loadError(empty), empty, "not a Radiance .hdr file");
    // A PNG signature is not an .hdr, whatever the extension says.
    const fs::path png = writeBytes("fake.hdr", {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n', 0, 0, 0, 13});
    expectOneLineNaming(loadError(png), png, "not a Radiance .hdr file");
}

TEST_F(EnvironmentFile, NotTwoToOne)
{
    const fs::path square = writeHdr("square.hdr", 16, 16);
    expectOneLineNaming(loadError(square), square, "16x16 is not an equirectangular panorama");
}

TEST_F(EnvironmentFile, AbsurdSizeRefusedBeforeDecoding)
{
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 50000 +X 100000\n";
    const fs::path huge = writeBytes("huge.hdr", std::vector<char>(header.begin(), header.end()));
    expectOneLineNaming(loadError(huge), huge, "100000x50000 pixels, more than the");
}

TEST_F(EnvironmentFile, UnsupportedHeader)
{
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 4\n";
    const fs::path xyz = writeBytes("xyz.hdr", std::vector<char>(header.begin(), header.end()));
    const std::string error = loadError(xyz);
    EXPECT_NE(error.find(xyz.string()), std::string::npos) << error;
    EXPECT_FALSE(error.empty());
}

TEST_F(EnvironmentFile, CorruptRunLengthsAreRefused)
{
    std::vector<char> bytes = readBytes(writeHdr("good.hdr", 32, 16));
    // The first scanline starts after the header's blank line and resolution line; its
    // 4-byte RLE marker (2, 2, width) is followed by the first channel's first count byte.
    const std::string text(bytes.begin(), bytes.end());
    const size_t data = text.find("+X 32\n") + 6;
    ASSERT_EQ(bytes[data], 2);
    bytes[data + 4] = char(200); // a run of 72 > the 32 pixels left
    const fs::path bad = writeBytes("bad.hdr", bytes);
    expectOneLineNaming(loadError(bad), bad, "cannot read pixels");
}

TEST_F(EnvironmentFile, EveryTruncationIsAnErrorNotAHang)
{
    for (const auto& [name, w, h] : {std::tuple{"rle.hdr", 32, 16}, std::tuple{"flat.hdr", 4, 2}}) {
        const std::vector<char> bytes = readBytes(writeHdr(name, w, h));
        const std::string text(bytes.begin(), bytes.end());
        const size_t headerEnd = text.find("+X ") + 3;
        for (size_t length = 1; length < bytes.size(); ++length) {
            const fs::path cut = writeBytes("cut.hdr", std::vector<char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(length)));
            const std::string error = loadError(cut);
            ASSERT_FALSE(error.empty()) << name << " cut to " << length << " of " << bytes.size() << " bytes";
            EXPECT_EQ(error.find('\n'), std::string::npos) << error;
            if (length > headerEnd + 3) {
                EXPECT_NE(error.find("truncated"), std::string::npos) << length << ": " << error;
            }
        }
    }
}

} // namespace
} // namespace lfd::lighting
