// Texture stage: decoding and channel conversion, size reduction, the mip chain filter
// (hand-worked values), errors, and peak memory of the bake (measured in a forked child).
#include "bake_log.h"
#include "imported_scene.h"
#include "texture_bake.h"
#include "mip_chain.h"

#include <OpenImageIO/imageio.h>
#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>

namespace fs = std::filesystem;
using lfd::Texture;
using lfd::bake::BakeError;
using lfd::bake::TextureBakeOptions;
using lfd::bake::TextureSource;

namespace {

using Texel = std::array<int, 4>;

fs::path tempDir()
{
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("lfd_texture_test_" + std::to_string(getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

// Writes an image with OIIO (pixels interleaved, row-major, `format` per channel).
void writeImage(const fs::path& path, int width, int height, int channels, OIIO::TypeDesc format,
                const void* pixels)
{
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, channels, format);
    spec.attribute("oiio:UnassociatedAlpha", 1); // store the bytes given, no un-premultiply
    spec.attribute("png:compressionLevel", 1);     // speed over size
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(format, pixels)) << out->geterror();
    ASSERT_TRUE(out->close());
}

void writeRgba8(const fs::path& path, int width, int height, const std::vector<uint8_t>& rgba)
{
    writeImage(path, width, height, 4, OIIO::TypeDesc::UINT8, rgba.data());
}

std::vector<uint8_t> readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TextureSource fileSource(const fs::path& path, bool srgb)
{
    TextureSource source;
    source.name = path.filename().string();
    source.file = path;
    source.srgb = srgb;
    return source;
}

TextureSource embeddedSource(std::vector<uint8_t> bytes, const std::string& mime, bool srgb)
{
    TextureSource source;
    source.name = "embedded_image";
    source.encoded = std::move(bytes);
    source.mimeType = mime;
    source.srgb = srgb;
    return source;
}

Texel texel(const Texture& texture, size_t level, uint32_t x, uint32_t y)
{
    const lfd::MipLevel& l = texture.mips.at(level);
    const uint8_t* p = texture.texels.data() + l.offset + (size_t(y) * l.width + x) * 4;
    return {p[0], p[1], p[2], p[3]};
}

void expectChain(const Texture& texture, uint32_t width, uint32_t height)
{
    ASSERT_EQ(texture.width, width);
    ASSERT_EQ(texture.height, height);
    const size_t expectedLevels = size_t(std::floor(std::log2(double(std::max(width, height))))) + 1;
    ASSERT_EQ(texture.mips.size(), expectedLevels);
    uint64_t offset = 0;
    for (size_t l = 0; l < texture.mips.size(); ++l) {
        EXPECT_EQ(texture.mips[l].width, std::max(1u, width >> l)) << "level " << l;
        EXPECT_EQ(texture.mips[l].height, std::max(1u, height >> l)) << "level " << l;
        EXPECT_EQ(texture.mips[l].offset, offset) << "level " << l;
        EXPECT_EQ(texture.mips[l].size, uint64_t(texture.mips[l].width) * texture.mips[l].height * 4);
        offset += texture.mips[l].size;
    }
    EXPECT_EQ(texture.texels.size(), offset);
    EXPECT_EQ(texture.mips.back().width, 1u);
    EXPECT_EQ(texture.mips.back().height, 1u);
}

void expectOneLineNaming(const std::string& message, const std::string& label)
{
    EXPECT_EQ(message.rfind(label + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

template <typename F>
std::string bakeErrorOf(F&& f)
{
    try {
        f();
    } catch (const BakeError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected BakeError";
    return {};
}

std::vector<uint8_t> noise(size_t n, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::vector<uint8_t> v(n);
    for (uint8_t& b : v)
        b = uint8_t(rng() & 0xff);
    return v;
}

// Smooth RGB pattern (compresses well), generated and written one scanline at a time so
// that the generator never holds the image.
void writeSmoothPng(const fs::path& path, int size)
{
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(size, size, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("png:compressionLevel", 1);
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    std::vector<uint8_t> row(size_t(size) * 3);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            row[size_t(x) * 3 + 0] = uint8_t((x * 255) / (size - 1));
            row[size_t(x) * 3 + 1] = uint8_t((y * 255) / (size - 1));
            row[size_t(x) * 3 + 2] = uint8_t(((x + y) >> 6) & 0xff);
        }
        ASSERT_TRUE(out->write_scanline(y, 0, OIIO::TypeDesc::UINT8, row.data())) << out->geterror();
    }
    ASSERT_TRUE(out->close());
}

// ---- peak memory, measured in a forked child so the parent's history does not count ----

double statusMiB(const char* key)
{
    std::ifstream in("/proc/self/status");
    std::string line;
    const size_t keyLength = std::strlen(key);
    while (std::getline(in, line))
        if (line.compare(0, keyLength, key) == 0)
            return std::strtod(line.c_str() + keyLength + 1, nullptr) / 1024.0; // kB
    return -1.0;
}

struct ChildReport {
    bool ok = false;
    double baselineMiB = 0.0; // VmRSS before the bake
    double peakMiB = 0.0;     // VmHWM after it
    double seconds = 0.0;    // wall clock
    double cpuSeconds = 0.0; // user + system, all threads
    uint32_t width = 0, height = 0, levels = 0;
    char error[256] = {};
};

ChildReport bakeInChild(const TextureSource& source, const TextureBakeOptions& options)
{
    int fds[2];
    if (pipe(fds) != 0) {
        ADD_FAILURE() << "pipe failed";
        return {};
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        ChildReport report;
        report.baselineMiB = statusMiB("VmRSS:");
        try {
            const auto t0 = std::chrono::steady_clock::now();
            Texture texture = lfd::bake::bakeTexture(source, options);
            report.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            rusage usage{};
            getrusage(RUSAGE_SELF, &usage);
            report.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                                1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
            report.width = texture.width;
            report.height = texture.height;
            report.levels = uint32_t(texture.mips.size());
            report.ok = true;
        } catch (const std::exception& e) {
            std::strncpy(report.error, e.what(), sizeof(report.error) - 1);
        }
        report.peakMiB = statusMiB("VmHWM:");
        const ssize_t written = write(fds[1], &report, sizeof(report));
        _exit(written == ssize_t(sizeof(report)) ? 0 : 1);
    }
    close(fds[1]);
    ChildReport report;
    size_t got = 0;
    while (got < sizeof(report)) {
        const ssize_t n = read(fds[0], reinterpret_cast<char*>(&report) + got, sizeof(report) - got);
        if (n <= 0)
            break;
        got += size_t(n);
    }
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_EQ(got, sizeof(report)) << "child died (status " << status << ")";
    return report;
}

} // namespace

// ---- layout and filter -----------------------------------------------------------

TEST(TextureBake, ChainLayoutLevelsAndOffsets)
{
    const auto odd = lfd::bake::mip::chainLayout(5, 3);
    ASSERT_EQ(odd.size(), 3u);
    EXPECT_EQ(odd[0].width, 5u);
    EXPECT_EQ(odd[0].height, 3u);
    EXPECT_EQ(odd[1].width, 2u);
    EXPECT_EQ(odd[1].height, 1u);
    EXPECT_EQ(odd[2].width, 1u);
    EXPECT_EQ(odd[2].height, 1u);
    EXPECT_EQ(odd[1].offset, 60u);
    EXPECT_EQ(odd[2].offset, 68u);
    EXPECT_EQ(lfd::bake::mip::chainBytes(odd), 72u);

    for (auto [w, h] : {std::pair{1u, 1u}, {2u, 1u}, {1u, 7u}, {16u, 4u}, {4096u, 1024u},
                        {1000u, 3u}, {16384u, 16384u}}) {
        const auto levels = lfd::bake::mip::chainLayout(w, h);
        EXPECT_EQ(levels.size(), size_t(std::floor(std::log2(double(std::max(w, h))))) + 1)
            << w << "x" << h;
        EXPECT_EQ(levels.back().width, 1u);
        EXPECT_EQ(levels.back().height, 1u);
    }
}

TEST(TextureBake, SrgbCodecIsExact)
{
    using namespace lfd::bake::mip;
    for (int b = 0; b < 256; ++b) {
        // Round trip of every byte, and agreement with the formula evaluated in double.
        EXPECT_EQ(linearToSrgb8(srgb8ToLinear(uint8_t(b))), b);
        const double c = b / 255.0;
        const double lin = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        EXPECT_NEAR(srgb8ToLinear(uint8_t(b)), lin, 1e-7);
    }
    // Hand-computed: OETF(0.5) = 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 187.52 -> 188.
    EXPECT_EQ(linearToSrgb8(0.5f), 188);
    EXPECT_EQ(linearToSrgb8(0.0f), 0);
    EXPECT_EQ(linearToSrgb8(1.0f), 255);
    EXPECT_EQ(linearToSrgb8(-1.0f), 0);
    EXPECT_EQ(linearToSrgb8(2.0f), 255);
    EXPECT_EQ(linearToSrgb8(std::nanf("")), 0);
    // Dense check against round(255 * OETF(x)) away from exact rounding ties.
    for (int i = 0; i <= 100000; ++i) {
        const double x = i / 100000.0;
        const double e = 255.0 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055);
        if (std::abs(e - std::floor(e) - 0.5) < 1e-3)
            continue;
        ASSERT_EQ(linearToSrgb8(float(x)), int(std::lround(e))) << x;
    }
}

TEST(TextureBake, DataTexture2x2IsRoundedByteAverage)
{
    // Texels (R, G, B, A); level 1 = per-channel mean rounded half up:
    //   R 0,1,1,1 -> 0.75 -> 1   G 10,20,30,41 -> 25.25 -> 25
    //   B 0,0,1,1 -> 0.5 -> 1    A 255,254,0,3 -> 128
    const std::vector<uint8_t> rgba = {0, 10, 0, 255, 1, 20, 0, 254, 1, 30, 1, 0, 1, 41, 1, 3};
    const fs::path path = tempDir() / "data2x2.png";
    writeRgba8(path, 2, 2, rgba);
    const Texture t = lfd::bake::bakeTexture(fileSource(path, false), {});
    expectChain(t, 2, 2);
    EXPECT_FALSE(t.srgb);
    EXPECT_EQ(t.name, "data2x2.png");
    EXPECT_TRUE(std::equal(rgba.begin(), rgba.end(), t.texels.begin())); // level 0 as stored
    EXPECT_EQ(texel(t, 1, 0, 0), (Texel{1, 25, 1, 128}));
}

TEST(TextureBake, SrgbCheckerAveragesInLinearLight)
{
    // Black/white checker, alpha 255/0: linear mean 0.5 -> sRGB 188 (a byte-space mean
    // would give 128); alpha is averaged linearly: 127.5 -> 128.
    const std::vector<uint8_t> rgba = {0, 0, 0, 255, 255, 255, 255, 0,
                                       255, 255, 255, 255, 0, 0, 0, 0};
    const fs::path path = tempDir() / "checker.png";
    writeRgba8(path, 2, 2, rgba);
    const Texture colour = lfd::bake::bakeTexture(fileSource(path, true), {});
    expectChain(colour, 2, 2);
    EXPECT_TRUE(colour.srgb);
    EXPECT_EQ(texel(colour, 1, 0, 0), (Texel{188, 188, 188, 128}));
    // The same bytes as data average in byte space.
    const Texture data = lfd::bake::bakeTexture(fileSource(path, false), {});
    EXPECT_EQ(texel(data, 1, 0, 0), (Texel{128, 128, 128, 128}));
}

TEST(TextureBake, OddSizesUsePolyphaseBox)
{
    // 5x3 data texture: R = 10 x, G = 100 y, B noise, A = 255.
    // Width 5 -> 2 weights (2,2,1)/5 and (1,2,2)/5: R = 8, 32; height 3 -> 1 weights 1/3
    // each: G = (0 + 100 + 200) / 3 = 100. Level 2 (2x1 -> 1x1): R = (8 + 32) / 2 = 20,
    // the mean of the input, as a box filter must give.
    std::vector<uint8_t> rgba(5 * 3 * 4);
    const std::vector<uint8_t> n = noise(15, 7);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            uint8_t* p = &rgba[size_t(y * 5 + x) * 4];
            p[0] = uint8_t(10 * x);
            p[1] = uint8_t(100 * y);
            p[2] = n[size_t(y * 5 + x)];
            p[3] = 255;
        }
    const fs::path path = tempDir() / "odd5x3.png";
    writeRgba8(path, 5, 3, rgba);
    for (bool srgb : {false, true}) {
        const Texture t = lfd::bake::bakeTexture(fileSource(path, srgb), {});
        expectChain(t, 5, 3);
        ASSERT_EQ(t.mips[1].width, 2u);
        ASSERT_EQ(t.mips[1].height, 1u);
        // Every level stays within the input's range per channel.
        const auto [bMin, bMax] = std::minmax_element(n.begin(), n.end());
        for (size_t l = 1; l < t.mips.size(); ++l)
            for (uint32_t y = 0; y < t.mips[l].height; ++y)
                for (uint32_t x = 0; x < t.mips[l].width; ++x) {
                    const Texel v = texel(t, l, x, y);
                    EXPECT_GE(v[0], 0);
                    EXPECT_LE(v[0], 40);
                    EXPECT_GE(v[1], 0);
                    EXPECT_LE(v[1], 200);
                    EXPECT_GE(v[2], *bMin);
                    EXPECT_LE(v[2], *bMax);
                    EXPECT_EQ(v[3], 255);
                }
        if (!srgb) {
            EXPECT_EQ(texel(t, 1, 0, 0)[0], 8);
            EXPECT_EQ(texel(t, 1, 1, 0)[0], 32);
            EXPECT_EQ(texel(t, 1, 0, 0)[1], 100);
            EXPECT_EQ(texel(t, 1, 1, 0)[1], 100);
            EXPECT_EQ(texel(t, 2, 0, 0)[0], 20);
        }
    }
}

TEST(TextureBake, NonSquareChainKeepsConstantColour)
{
    // 16x4 -> 8x2 -> 4x1 -> 2x1 -> 1x1; a constant texture stays exactly constant in
    // both filter spaces (the sRGB decode/encode round trip is exact).
    const fs::path path = tempDir() / "const16x4.png";
    std::vector<uint8_t> rgba(16 * 4 * 4);
    for (size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i] = 77;
        rgba[i + 1] = 1;
        rgba[i + 2] = 254;
        rgba[i + 3] = 99;
    }
    writeRgba8(path, 16, 4, rgba);
    for (bool srgb : {false, true}) {
        const Texture t = lfd::bake::bakeTexture(fileSource(path, srgb), {});
        expectChain(t, 16, 4);
        ASSERT_EQ(t.mips.size(), 5u);
        for (size_t i = 0; i < t.texels.size(); i += 4)
            ASSERT_EQ((Texel{t.texels[i], t.texels[i + 1], t.texels[i + 2], t.texels[i + 3]}),
                      (Texel{77, 1, 254, 99}))
                << "byte " << i;
    }
}

TEST(TextureBake, DownsamplerStartedMidImageMatchesFullRun)
{
    // A stage fed from input row 2k on must produce output rows k.. exactly as a stage
    // fed the whole image (this is how the chain splits a level between threads).
    for (uint32_t height : {1u, 2u, 7u, 8u, 9u}) {
        const uint32_t width = 3;
        std::vector<std::vector<float>> rows(height);
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t i = 0; i < width * 4; ++i)
                rows[y].push_back(float((y * 31 + i * 7) % 256));
        lfd::bake::mip::RowDownsampler full(width, height);
        std::vector<std::vector<float>> expected(full.outHeight());
        for (uint32_t y = 0; y < full.inputRowsEnd(full.outHeight()); ++y)
            if (const float* out = full.push(rows[y].data()))
                expected.at(full.lastOutputRow()).assign(out, out + full.outWidth() * 4);
        for (const auto& row : expected)
            ASSERT_EQ(row.size(), full.outWidth() * 4) << "height " << height;
        for (uint32_t k = 0; 2 * k < height; ++k) {
            lfd::bake::mip::RowDownsampler part(width, height, 2 * k);
            uint32_t next = k;
            for (uint32_t y = 2 * k; y < part.inputRowsEnd(part.outHeight()); ++y)
                if (const float* out = part.push(rows[y].data())) {
                    ASSERT_EQ(part.lastOutputRow(), next) << "height " << height << " k " << k;
                    EXPECT_EQ(std::vector<float>(out, out + part.outWidth() * 4), expected[next]);
                    ++next;
                }
            EXPECT_EQ(next, std::max(k, part.outHeight())) << "height " << height << " k " << k;
        }
    }
}

TEST(TextureBake, ThreadedChainMatchesSerial)
{
    // Bands of rows on several threads must give the serial result (odd heights share an
    // input row across the band seam).
    for (auto [w, h] : {std::pair{1001u, 777u}, {640u, 481u}, {3u, 1200u}}) {
        for (bool srgb : {false, true}) {
            const auto levels = lfd::bake::mip::chainLayout(w, h);
            std::vector<uint8_t> serial = noise(lfd::bake::mip::chainBytes(levels), w + h);
            std::vector<uint8_t> threaded = serial;
            lfd::bake::mip::buildChain(serial.data(), levels, srgb, 1);
            lfd::bake::mip::buildChain(threaded.data(), levels, srgb, 5);
            EXPECT_EQ(serial, threaded) << w << "x" << h << " srgb " << srgb;
        }
    }
}

// ---- decoding --------------------------------------------------------------------

TEST(TextureBake, OneChannelBecomesGrey)
{
    const std::vector<uint8_t> grey = {0, 50, 128, 255};
    const fs::path path = tempDir() / "grey1.png";
    writeImage(path, 2, 2, 1, OIIO::TypeDesc::UINT8, grey.data());
    for (bool srgb : {false, true}) {
        const Texture t = lfd::bake::bakeTexture(fileSource(path, srgb), {});
        for (uint32_t i = 0; i < 4; ++i)
            EXPECT_EQ(texel(t, 0, i % 2, i / 2), (Texel{grey[i], grey[i], grey[i], 255}));
    }
}

TEST(TextureBake, TwoChannelsBecomeGreyAlpha)
{
    const std::vector<uint8_t> ga = {10, 200, 20, 0, 30, 255, 40, 1};
    const fs::path path = tempDir() / "greyalpha.png";
    writeImage(path, 2, 2, 2, OIIO::TypeDesc::UINT8, ga.data());
    const Texture t = lfd::bake::bakeTexture(fileSource(path, false), {});
    for (uint32_t i = 0; i < 4; ++i)
        EXPECT_EQ(texel(t, 0, i % 2, i / 2), (Texel{ga[2 * i], ga[2 * i], ga[2 * i], ga[2 * i + 1]}));
}

TEST(TextureBake, ThreeChannelsGetOpaqueAlpha)
{
    const std::vector<uint8_t> rgb = {1, 2, 3, 40, 50, 60, 70, 80, 90, 250, 251, 252};
    const fs::path path = tempDir() / "rgb.png";
    writeImage(path, 2, 2, 3, OIIO::TypeDesc::UINT8, rgb.data());
    const Texture t = lfd::bake::bakeTexture(fileSource(path, true), {});
    for (uint32_t i = 0; i < 4; ++i)
        EXPECT_EQ(texel(t, 0, i % 2, i / 2), (Texel{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], 255}));
}

TEST(TextureBake, StraightAlphaIsKept)
{
    // OIIO would premultiply PNG alpha unless told not to: colour under partial alpha
    // must come back unchanged.
    const std::vector<uint8_t> rgba = {200, 100, 50, 128, 255, 255, 255, 1,
                                       10, 20, 30, 0, 90, 180, 240, 77};
    const fs::path path = tempDir() / "straight.png";
    writeRgba8(path, 2, 2, rgba);
    const Texture t = lfd::bake::bakeTexture(fileSource(path, true), {});
    EXPECT_TRUE(std::equal(rgba.begin(), rgba.end(), t.texels.begin()));
}

TEST(TextureBake, SixteenBitIsRoundedToEightBit)
{
    // v16 / 65535 * 255 rounded: 0 -> 0, 1000 -> 3.89 -> 4, 32896 -> 128, 65535 -> 255,
    // 33153 -> 129.0 (33153 = 129 * 257), 32767 -> 127.498 -> 127.
    const std::vector<uint16_t> rgba = {0, 1000, 32896, 65535, 33153, 32767, 65535, 0,
                                        257, 514, 771, 1028, 65535, 65535, 65535, 65535};
    const fs::path path = tempDir() / "rgba16.png";
    writeImage(path, 2, 2, 4, OIIO::TypeDesc::UINT16, rgba.data());
    const Texture t = lfd::bake::bakeTexture(fileSource(path, false), {});
    EXPECT_EQ(texel(t, 0, 0, 0), (Texel{0, 4, 128, 255}));
    EXPECT_EQ(texel(t, 0, 1, 0), (Texel{129, 127, 255, 0}));
    EXPECT_EQ(texel(t, 0, 0, 1), (Texel{1, 2, 3, 4}));
    EXPECT_EQ(texel(t, 0, 1, 1), (Texel{255, 255, 255, 255}));

    const std::vector<uint16_t> grey = {0, 1000, 32896, 65535};
    const fs::path greyPath = tempDir() / "grey16.png";
    writeImage(greyPath, 2, 2, 1, OIIO::TypeDesc::UINT16, grey.data());
    const Texture g = lfd::bake::bakeTexture(fileSource(greyPath, false), {});
    EXPECT_EQ(texel(g, 0, 1, 0), (Texel{4, 4, 4, 255}));
    EXPECT_EQ(texel(g, 0, 0, 1), (Texel{128, 128, 128, 255}));
}

TEST(TextureBake, EmbeddedBytesMatchFile)
{
    const std::vector<uint8_t> rgba = noise(37 * 23 * 4, 3);
    const fs::path png = tempDir() / "noise.png";
    writeRgba8(png, 37, 23, rgba);
    std::vector<uint8_t> rgb;
    for (size_t i = 0; i < rgba.size(); ++i)
        if (i % 4 != 3)
            rgb.push_back(rgba[i]);
    const fs::path jpg = tempDir() / "noise.jpg";
    writeImage(jpg, 37, 23, 3, OIIO::TypeDesc::UINT8, rgb.data());

    for (const fs::path& path : {png, jpg}) {
        const std::string mime = path.extension() == ".png" ? "image/png" : "image/jpeg";
        const Texture fromFile = lfd::bake::bakeTexture(fileSource(path, true), {});
        const Texture embedded =
            lfd::bake::bakeTexture(embeddedSource(readBytes(path), mime, true), {});
        expectChain(embedded, 37, 23);
        EXPECT_EQ(embedded.name, "embedded_image");
        EXPECT_EQ(fromFile.texels, embedded.texels) << path;
        // A wrong mimeType does not matter: the signature decides.
        const Texture mislabelled =
            lfd::bake::bakeTexture(embeddedSource(readBytes(path), "image/webp", true), {});
        EXPECT_EQ(fromFile.texels, mislabelled.texels) << path;
        EXPECT_EQ(lfd::bake::probeTextureSize(embeddedSource(readBytes(path), mime, true)),
                  glm::uvec2(37, 23));
    }
    EXPECT_TRUE(std::equal(rgba.begin(), rgba.end(),
                           lfd::bake::bakeTexture(fileSource(png, true), {}).texels.begin()));
}

// ---- errors ----------------------------------------------------------------------

TEST(TextureBake, ErrorsNameTheSourceOnOneLine)
{
    const fs::path missing = tempDir() / "textures" / "wood.png";
    std::string m = bakeErrorOf([&] { lfd::bake::bakeTexture(fileSource(missing, true), {}); });
    expectOneLineNaming(m, missing.string());
    EXPECT_NE(m.find("not found"), std::string::npos) << m;
    m = bakeErrorOf([&] { lfd::bake::probeTextureSize(fileSource(missing, true)); });
    expectOneLineNaming(m, missing.string());

    // Not an image, on disk and embedded.
    const fs::path garbage = tempDir() / "garbage.png";
    {
        const std::vector<uint8_t> bytes = noise(1000, 11);
        std::ofstream(garbage, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), 1000);
    }
    m = bakeErrorOf([&] { lfd::bake::bakeTexture(fileSource(garbage, false), {}); });
    expectOneLineNaming(m, garbage.string());
    m = bakeErrorOf([&] { lfd::bake::probeTextureSize(fileSource(garbage, false)); });
    expectOneLineNaming(m, garbage.string());
    m = bakeErrorOf(
        [&] { lfd::bake::bakeTexture(embeddedSource(noise(1000, 12), "image/png", false), {}); });
    expectOneLineNaming(m, "embedded_image");
    m = bakeErrorOf(
        [&] { lfd::bake::bakeTexture(embeddedSource(noise(1000, 13), "image/ktx2", false), {}); });
    expectOneLineNaming(m, "embedded_image");
    EXPECT_NE(m.find("unsupported"), std::string::npos) << m;

    // A directory, and a source with neither file nor bytes.
    m = bakeErrorOf([&] { lfd::bake::bakeTexture(fileSource(tempDir(), false), {}); });
    expectOneLineNaming(m, tempDir().string());
    TextureSource empty;
    empty.name = "nothing";
    m = bakeErrorOf([&] { lfd::bake::bakeTexture(empty, {}); });
    expectOneLineNaming(m, "nothing");

    // Truncated PNG: the header parses, the pixel data ends early.
    const fs::path full = tempDir() / "full.png";
    writeRgba8(full, 64, 64, noise(64 * 64 * 4, 5));
    std::vector<uint8_t> bytes = readBytes(full);
    bytes.resize(bytes.size() / 2);
    const fs::path truncated = tempDir() / "truncated.png";
    std::ofstream(truncated, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    EXPECT_EQ(lfd::bake::probeTextureSize(fileSource(truncated, true)), glm::uvec2(64, 64));
    m = bakeErrorOf([&] { lfd::bake::bakeTexture(fileSource(truncated, true), {}); });
    expectOneLineNaming(m, truncated.string());
    m = bakeErrorOf([&] { lfd::bake::bakeTexture(embeddedSource(bytes, "image/png", true), {}); });
    expectOneLineNaming(m, "embedded_image");
}

// ---- sizes and reduction ---------------------------------------------------------

TEST(TextureBake, StoredSizeHalvesUntilWithinMax)
{
    using lfd::bake::storedTextureSize;
    EXPECT_EQ(storedTextureSize({16384, 16384}, {16384}), glm::uvec2(16384, 16384));
    EXPECT_EQ(storedTextureSize({16384, 16384}, {8192}), glm::uvec2(8192, 8192));
    EXPECT_EQ(storedTextureSize({4096, 1024}, {1024}), glm::uvec2(1024, 256));
    EXPECT_EQ(storedTextureSize({5000, 3}, {1024}), glm::uvec2(625, 1));
    EXPECT_EQ(storedTextureSize({1025, 1025}, {1024}), glm::uvec2(512, 512));
    EXPECT_EQ(storedTextureSize({1024, 1024}, {1024}), glm::uvec2(1024, 1024));
    EXPECT_EQ(storedTextureSize({7, 5}, {1}), glm::uvec2(1, 1));
    EXPECT_EQ(storedTextureSize({7, 5}, {0}), glm::uvec2(1, 1)); // 0 behaves as 1
}

TEST(TextureBake, ReductionMatchesUnreducedChain)
{
    // 4096x1024 with maxSize 1024 -> stored 1024x256 (two halvings); its level 0 is the
    // unreduced chain's level 2 up to the rounding of the intermediate 8-bit levels.
    std::vector<uint8_t> rgba(size_t(4096) * 1024 * 4);
    const std::vector<uint8_t> n = noise(4096, 9);
    for (uint32_t y = 0; y < 1024; ++y)
        for (uint32_t x = 0; x < 4096; ++x) {
            uint8_t* p = &rgba[(size_t(y) * 4096 + x) * 4];
            p[0] = uint8_t(x / 16);
            p[1] = uint8_t(y / 4);
            p[2] = n[(x / 8 + y / 8 * 512) % 4096]; // 8x8 blocks of noise
            p[3] = uint8_t((x ^ y) & 0xff);
        }
    const fs::path path = tempDir() / "wide.png";
    writeRgba8(path, 4096, 1024, rgba);
    rgba = {};

    for (bool srgb : {false, true}) {
        const Texture reduced = lfd::bake::bakeTexture(fileSource(path, srgb), {1024});
        expectChain(reduced, 1024, 256);
        EXPECT_EQ(reduced.sourceWidth, 4096u);
        EXPECT_EQ(reduced.sourceHeight, 1024u);
        ASSERT_EQ(reduced.mips.size(), 11u);
        const Texture full = lfd::bake::bakeTexture(fileSource(path, srgb), {});
        expectChain(full, 4096, 1024);
        EXPECT_EQ(full.sourceWidth, 4096u);
        int maxDiff = 0;
        for (size_t i = 0; i < reduced.mips[0].size; ++i)
            maxDiff = std::max(maxDiff, std::abs(int(reduced.texels[i]) -
                                                 int(full.texels[full.mips[2].offset + i])));
        EXPECT_LE(maxDiff, 1) << "srgb " << srgb;
    }
}

TEST(TextureBake, PeakMemoryStaysNearOneChain)
{
    // 4096^2 RGBA8 = 64 MiB; the bake holds the chain (~85 MiB) plus a few rows.
    const fs::path path = tempDir() / "smooth4096.png";
    writeSmoothPng(path, 4096);
    const double copyMiB = 64.0;
    for (uint32_t maxSize : {16384u, 2048u}) {
        const ChildReport r = bakeInChild(fileSource(path, true), {maxSize});
        ASSERT_TRUE(r.ok) << r.error;
        const uint32_t expected = maxSize < 4096 ? maxSize : 4096;
        EXPECT_EQ(r.width, expected);
        EXPECT_EQ(r.height, expected);
        const double grown = r.peakMiB - r.baselineMiB;
        std::printf("[ memory ] 4096x4096 maxSize %u: %.2f s (cpu %.2f s), peak %.1f MiB above "
                    "baseline %.1f MiB\n",
                    maxSize, r.seconds, r.cpuSeconds, grown, r.baselineMiB);
        EXPECT_LT(grown, 2.2 * copyMiB);
        RecordProperty("peakMiB_max" + std::to_string(maxSize), int(grown));
    }
}

TEST(TextureBake, BigTexture16K)
{
    // The giant measurement (~1.3 GiB of texels, tens of seconds) runs on request only.
    const char* enabled = std::getenv("LFD_BIG_TEXTURE_TEST");
    if (!enabled || std::string(enabled) != "1")
        GTEST_SKIP() << "set LFD_BIG_TEXTURE_TEST=1 to bake a 16384x16384 PNG";
    const fs::path path = fs::temp_directory_path() / "lfd_big_texture_16384.png";
    const auto t0 = std::chrono::steady_clock::now();
    writeSmoothPng(path, 16384);
    std::printf("[ memory ] generated %s (%.1f MiB) in %.1f s\n", path.c_str(),
                double(fs::file_size(path)) / (1 << 20),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    const double copyMiB = 1024.0;
    for (uint32_t maxSize : {16384u, 8192u}) {
        const ChildReport r = bakeInChild(fileSource(path, true), {maxSize});
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(r.width, maxSize);
        EXPECT_EQ(r.levels, uint32_t(std::log2(maxSize)) + 1);
        const double grown = r.peakMiB - r.baselineMiB;
        std::printf("[ memory ] 16384x16384 maxSize %u -> %ux%u: %.2f s (cpu %.2f s), peak %.1f "
                    "MiB above baseline %.1f MiB (VmHWM %.1f MiB)\n",
                    maxSize, r.width, r.height, r.seconds, r.cpuSeconds, grown, r.baselineMiB,
                    r.peakMiB);
        EXPECT_LT(grown, 2.0 * copyMiB);
    }
    fs::remove(path);
}

// ---- a real asset ----------------------------------------------------------------

TEST(TextureBake, DamagedHelmetAlbedo)
{
    const fs::path path = fs::path(LFD_SHARED_SCENES) / "DamagedHelmet" / "Default_albedo.jpg";
    if (!fs::exists(path))
        LFD_SKIP_OR_FAIL(path << " not present");
    EXPECT_EQ(lfd::bake::probeTextureSize(fileSource(path, true)), glm::uvec2(2048, 2048));
    const Texture t = lfd::bake::bakeTexture(fileSource(path, true), {});
    expectChain(t, 2048, 2048);
    ASSERT_EQ(t.mips.size(), 12u);
    EXPECT_EQ(t.sourceWidth, 2048u);

    // The 1x1 level is the box average in linear light of level 0 (up to the rounding of
    // eleven intermediate 8-bit levels), and not black.
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < t.mips[0].size; i += 4)
        for (int c = 0; c < 3; ++c)
            sum[c] += lfd::bake::mip::srgb8ToLinear(t.texels[i + c]);
    const Texel top = texel(t, 11, 0, 0);
    for (int c = 0; c < 3; ++c) {
        const int expected = lfd::bake::mip::linearToSrgb8(float(sum[c] / (2048.0 * 2048.0)));
        EXPECT_NEAR(top[c], expected, 3) << "channel " << c;
    }
    EXPECT_GT(top[0] + top[1] + top[2], 30);
    EXPECT_EQ(top[3], 255);
}

// Leave no temporary files behind.
class TextureTempCleanup : public ::testing::Environment {
public:
    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(fs::temp_directory_path() / ("lfd_texture_test_" + std::to_string(getpid())), ec);
    }
};
const auto* const kTextureTempCleanup =
    ::testing::AddGlobalTestEnvironment(new TextureTempCleanup);
