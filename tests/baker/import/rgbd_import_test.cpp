// RGB-D input (baker/import/rgbd_import.h, docs/baker/rgbd.md): the relief's geometry against
// hand-made depth maps (flat, a step, a ramp), the discontinuity and simplification
// flags, side-by-side images against the two-file form, clear errors, and the generated
// sample pair baked end to end within the tessellation bound.
#include "rgbd_import.h"

#include "lfd/pack.h"

#include "tool_run.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <regex>

namespace fs = std::filesystem;
using lfd::bake::importRgbd;
using lfd::bake::RgbdEdges;
using lfd::bake::RgbdOptions;
using lfd::test::quoted;
using lfd::test::run;

namespace {

// Writes a grey or RGB 8-bit PNG whose value at (x, y) is value(x, y, channel).
void writePng(const fs::path& path, int width, int height, int channels,
              const std::function<uint8_t(int, int, int)>& value)
{
    std::vector<uint8_t> pixels(size_t(width) * size_t(height) * size_t(channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c)] = value(x, y, c);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    ASSERT_TRUE(out->close());
}

class RgbdImport : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("lfd_rgbd_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        writePng(dir_ / "photo.png", 32, 16, 3, [](int x, int y, int c) { return uint8_t(x * 8 + y * c); });
    }
    void TearDown() override { fs::remove_all(dir_); }

    RgbdOptions withDepth(const std::function<uint8_t(int, int)>& depth, int width = 32, int height = 16)
    {
        writePng(dir_ / "depth.png", width, height, 1, [&](int x, int y, int) { return depth(x, y); });
        RgbdOptions o;
        o.color = dir_ / "photo.png";
        o.depth = dir_ / "depth.png";
        return o;
    }
    fs::path dir_;
};

float maxZ(const lfd::Scene& s)
{
    float z = -1e9f;
    for (const glm::vec3& p : s.vertices.positions)
        z = std::max(z, p.z);
    return z;
}

// The largest nearness span (z over relief) of any triangle.
float largestSpan(const lfd::Scene& s, double relief)
{
    float span = 0.0f;
    for (size_t t = 0; t < s.indices.size(); t += 3) {
        const float a = s.vertices.positions[s.indices[t]].z, b = s.vertices.positions[s.indices[t + 1]].z,
                    c = s.vertices.positions[s.indices[t + 2]].z;
        span = std::max(span, float((std::max({a, b, c}) - std::min({a, b, c})) / relief));
    }
    return span;
}


TEST_F(RgbdImport, FlatDepthIsTwoTrianglesSpanningTheImageWithTheTextureCorners)
{
    const lfd::bake::ImportedScene r = importRgbd(withDepth([](int, int) { return 255; }), {});
    EXPECT_EQ(r.scene.triangleCount(), 2u);
    ASSERT_EQ(r.scene.vertices.size(), 4u);
    // Aspect 2: x spans the pixel centres of [-1, 1], y of [-0.5, 0.5]; white = near = relief.
    for (size_t v = 0; v < 4; ++v) {
        const glm::vec3 p = r.scene.vertices.positions[v];
        const glm::vec2 uv = r.scene.vertices.uvs[v];
        EXPECT_NEAR(std::abs(p.x), 1.0 - 1.0 / 32, 1e-5); // pixels are 2/32 wide
        EXPECT_NEAR(std::abs(p.y), 0.5 - 0.5 / 16, 1e-5); // and 1/16 high
        EXPECT_NEAR(p.z, 0.5, 1e-6);
        EXPECT_NEAR(uv.x, (p.x / 2.0 + 0.5), 1e-5); // uv follows x, v runs down
        EXPECT_NEAR(uv.y, 0.5 - p.y, 1e-5);
        EXPECT_NEAR(r.scene.vertices.normals[v].z, 1.0, 1e-6);
    }
    // Counter-clockwise seen from the viewer (+z).
    const glm::vec3 a = r.scene.vertices.positions[r.scene.indices[0]], b = r.scene.vertices.positions[r.scene.indices[1]],
                    c = r.scene.vertices.positions[r.scene.indices[2]];
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_EQ(r.scene.materials[0].emissiveTexture, 0);
    EXPECT_EQ(r.scene.materials[0].baseColorFactor, glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(r.textureSources.at(0).file, dir_ / "photo.png");
    EXPECT_EQ(r.filesRead, (std::vector<fs::path>{dir_ / "photo.png", dir_ / "depth.png"}));
}

TEST_F(RgbdImport, InvertAndDepthRangeMapTheValues)
{
    RgbdOptions o = withDepth([](int, int) { return 0; });
    EXPECT_NEAR(maxZ(importRgbd(o, {}).scene), 0.0, 1e-6); // black is far
    o.invert = true;
    o.relief = 2.0;
    EXPECT_NEAR(maxZ(importRgbd(o, {}).scene), 2.0, 1e-6);
    o = withDepth([](int, int) { return 128; });
    o.depthLow = 0.0;
    o.depthHigh = 0.25; // 128/255 is past the near value: clamped to it
    EXPECT_NEAR(maxZ(importRgbd(o, {}).scene), 0.5, 1e-6);
}

TEST_F(RgbdImport, StepIsDroppedOrStretchedAndOnlyPixelSizedTrianglesAreDropped)
{
    RgbdOptions o = withDepth([](int x, int) { return x < 16 ? 0 : 255; });
    const lfd::Scene dropped = importRgbd(o, {}).scene;
    EXPECT_LE(largestSpan(dropped, o.relief), o.edgeThreshold);
    EXPECT_GT(dropped.triangleCount(), 0u);
    o.edges = RgbdEdges::Stretch;
    const lfd::Scene stretched = importRgbd(o, {}).scene;
    // The grid resamples the step over two of its intervals (33 points over 32 pixels).
    EXPECT_GT(largestSpan(stretched, o.relief), 0.4f);
    EXPECT_GT(stretched.triangleCount(), dropped.triangleCount());
    // A smooth ramp over the whole range is no discontinuity: nothing dropped, however
    // far its large triangles span.
    o = withDepth([](int x, int) { return uint8_t(x * 8); });
    const lfd::Scene ramp = importRgbd(o, {}).scene;
    o.edges = RgbdEdges::Stretch;
    EXPECT_EQ(ramp.triangleCount(), importRgbd(o, {}).scene.triangleCount());
}

TEST_F(RgbdImport, FlatnessZeroKeepsTheFullGridAndSimplificationStaysWithinTolerance)
{
    RgbdOptions o = withDepth([](int x, int y) { return uint8_t(128 + 100 * std::sin(x * 0.3) * std::cos(y * 0.4)); });
    o.edges = RgbdEdges::Stretch; // steep for its size: no discontinuity is wanted here
    o.flatness = 0.0;
    const lfd::Scene full = importRgbd(o, {}).scene;
    EXPECT_EQ(full.triangleCount(), size_t(32 * 32 * 2)); // 33 x 33 grid points
    o.flatness = 0.02;
    const lfd::Scene coarse = importRgbd(o, {}).scene;
    EXPECT_LT(coarse.triangleCount(), full.triangleCount());
    EXPECT_GT(coarse.triangleCount(), 2u);
    // Every full-grid point lies in some coarse triangle whose surface there is within
    // the tolerance of the point's depth (RTIN's error bound, vertical).
    for (const glm::vec3& p : full.vertices.positions) {
        bool inside = false;
        for (size_t t = 0; t < coarse.indices.size() && !inside; t += 3) {
            const glm::vec3 a = coarse.vertices.positions[coarse.indices[t]];
            const glm::vec3 b = coarse.vertices.positions[coarse.indices[t + 1]];
            const glm::vec3 c = coarse.vertices.positions[coarse.indices[t + 2]];
            const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            const float wb = ((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x)) / area;
            const float wc = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / area;
            if (wb < -1e-4f || wc < -1e-4f || wb + wc > 1.0f + 1e-4f)
                continue;
            inside = true;
            const float z = a.z + wb * (b.z - a.z) + wc * (c.z - a.z);
            EXPECT_LE(std::abs(z - p.z), o.flatness + 1e-4) << "at " << p.x << ", " << p.y;
        }
        EXPECT_TRUE(inside) << p.x << ", " << p.y;
    }
}

TEST_F(RgbdImport, SideBySideImageGivesTheSameReliefAsTwoFiles)
{
    const auto depth = [](int x, int y) { return uint8_t(x < 10 ? 40 : 200 - y * 4); };
    RgbdOptions two = withDepth(depth);
    writePng(dir_ / "sbs.png", 64, 16, 3, [&](int x, int y, int c) {
        return x < 32 ? uint8_t(x * 8 + y * c) : depth(x - 32, y);
    });
    RgbdOptions sbs;
    sbs.color = dir_ / "sbs.png";
    const lfd::bake::ImportedScene a = importRgbd(two, {}), b = importRgbd(sbs, {});
    EXPECT_EQ(a.scene.vertices.positions, b.scene.vertices.positions);
    EXPECT_EQ(a.scene.indices, b.scene.indices);
    EXPECT_TRUE(b.textureSources.at(0).file.empty());
    EXPECT_FALSE(b.textureSources.at(0).encoded.empty()); // the colour half, as PNG
    EXPECT_EQ(b.filesRead, std::vector<fs::path>{dir_ / "sbs.png"});
}

TEST_F(RgbdImport, BadInputsGiveOneLineNamingTheFile)
{
    RgbdOptions o = withDepth([](int, int) { return 9; }, 30, 30); // aspect 1 against the photo's 2
    try {
        importRgbd(o, {});
        FAIL() << "aspect mismatch accepted";
    } catch (const lfd::bake::BakeError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir_ / "depth.png").string() + ": aspect 30x30", 0), 0u) << e.what();
    }
    o.depth = dir_ / "missing.png";
    EXPECT_THROW(importRgbd(o, {}), lfd::bake::BakeError);
    writePng(dir_ / "odd.png", 33, 16, 3, [](int, int, int) { return 0; });
    RgbdOptions odd;
    odd.color = dir_ / "odd.png";
    try {
        importRgbd(odd, {});
        FAIL() << "odd side-by-side width accepted";
    } catch (const lfd::bake::BakeError& e) {
        EXPECT_NE(std::string(e.what()).find("odd width 33"), std::string::npos) << e.what();
    }
}

TEST_F(RgbdImport, SamplePairBakesWithinTheEdgeBoundAndVerifies)
{
    const std::string bin = LFD_BINARY_DIR;
    ASSERT_EQ(run(bin + "/samples/lfd-make-samples " + quoted(dir_ / "s") + " --scene rgbd --quiet").exitCode, 0);
    for (const std::string& inputs : {quoted(dir_ / "s/rgbd/photo.png") + " " + quoted(dir_ / "s/rgbd/depth.png"),
                                      quoted(dir_ / "s/rgbd/photo_rgbd.png")}) {
        const lfd::test::RunResult r =
            run(bin + "/baker/lfd-bake --rgbd " + inputs + " -o " + quoted(dir_ / "rgbd.lfdpack") + " --max-edge-px 20");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(max edge: [0-9.]+ view px before, ([0-9.]+) after)")))
            << r.out;
        EXPECT_LE(std::stod(m[1]), 20.0);
        ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(rgbd: .* ([0-9]+) dropped at depth discontinuities)")));
        EXPECT_GT(std::stoul(m[1]), 0u); // the floating box's rim
        const lfd::Scene pack = lfd::readPack(dir_ / "rgbd.lfdpack");
        EXPECT_EQ(pack.textures.size(), 1u);
        EXPECT_EQ(pack.materials.at(0).emissiveTexture, 0);
    }
    const lfd::test::RunResult both = run(bin + "/baker/lfd-bake " + quoted(dir_ / "x.gltf") + " --rgbd " +
                                          quoted(dir_ / "s/rgbd/photo_rgbd.png") + " -o " + quoted(dir_ / "y.lfdpack"));
    EXPECT_EQ(both.exitCode, 1);
    EXPECT_NE(both.out.find("either a glTF INPUT or --rgbd"), std::string::npos) << both.out;
}

// Issue 42: the message names the flag and the values given, through the real lfd-bake.
TEST_F(RgbdImport, ReversedDepthRangeNamesTheValues)
{
    RgbdOptions o = withDepth([](int, int) { return 128; });
    o.depthLow = 0.8;
    o.depthHigh = 0.2;
    try {
        importRgbd(o, {});
        FAIL() << "a reversed depth range was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("--rgbd-depth-range: the near value must exceed the far one, got 0.8 0.2"),
                  std::string::npos)
            << e.what();
    }
    const lfd::test::RunResult r = run(std::string(LFD_BINARY_DIR) + "/baker/lfd-bake --rgbd " +
                                       quoted(dir_ / "photo.png") + " " + quoted(dir_ / "depth.png") +
                                       " --rgbd-depth-range 0.8 0.2 -o " + quoted(dir_ / "r.lfdpack"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("got 0.8 0.2"), std::string::npos) << r.out;
}

} // namespace
