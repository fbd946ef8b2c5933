// Round trips through memory and files, with eager texels and with a TextureProducer.
#include "pack_test_scenes.h"
#include "skip_or_fail.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("lfd_pack_rt_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<uint8_t> fileBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

TEST(PackRoundTrip, MemoryPreservesEveryField)
{
    const Scene scene = makeFullScene();
    const std::vector<uint8_t> bytes = writePackToMemory(scene);
    const Scene back = readPackFromMemory(bytes.data(), bytes.size(), "full.lfdpack");
    expectSameScene(scene, back);
}

TEST(PackRoundTrip, FileMatchesMemoryAndPreservesEveryField)
{
    const fs::path dir = freshDir("file");
    const fs::path path = dir / "full scene ü.lfdpack";
    const Scene scene = makeFullScene();
    writePack(path, scene);

    EXPECT_EQ(fileBytes(path), writePackToMemory(scene));
    expectSameScene(scene, readPack(path));
    // Only the pack itself: the temporary file was renamed, not left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

TEST(PackRoundTrip, OptionalStreamsAreAbsentWhenEmpty)
{
    Scene scene = makeFullScene();
    scene.vertices.tangents.clear();
    scene.vertices.uvs.clear();
    const std::vector<uint8_t> bytes = writePackToMemory(scene);
    EXPECT_TRUE(entryIndex(bytes, pack::kTagNormals).has_value());
    EXPECT_FALSE(entryIndex(bytes, pack::kTagTangents).has_value());
    EXPECT_FALSE(entryIndex(bytes, pack::kTagUvs).has_value());
    const Scene back = readPackFromMemory(bytes.data(), bytes.size(), "streams.lfdpack");
    EXPECT_EQ(back.vertices.mask(), kStreamPosition | kStreamNormal);
    expectSameScene(scene, back);
}

TEST(PackRoundTrip, EmptySceneRoundTrips)
{
    const Scene scene;
    const std::vector<uint8_t> bytes = writePackToMemory(scene);
    expectSameScene(scene, readPackFromMemory(bytes.data(), bytes.size(), "empty.lfdpack"));
}

TEST(PackRoundTrip, ProducerGivesTheSameBytesAsEagerTexels)
{
    const Scene eager = makeFullScene();
    const Scene lazy = withoutTexels(eager);
    std::vector<uint32_t> calls;
    const TextureProducer produce = [&](uint32_t i) {
        calls.push_back(i);
        return eager.textures.at(i);
    };
    const std::vector<uint8_t> lazyBytes = writePackToMemory(lazy, produce);
    EXPECT_EQ(lazyBytes, writePackToMemory(eager));
    EXPECT_EQ(calls, (std::vector<uint32_t>{0, 1})); // each texture produced once, in order

    // The file path too, and what it reads back is the eager scene.
    const fs::path dir = freshDir("producer");
    calls.clear();
    writePack(dir / "lazy.lfdpack", lazy, produce);
    EXPECT_EQ(fileBytes(dir / "lazy.lfdpack"), lazyBytes);
    expectSameScene(eager, readPack(dir / "lazy.lfdpack"));
    fs::remove_all(dir);
}

// The writer must drop texture i before asking for texture i + 1 (16K textures are
// 1.3 GiB each with mips). Measured with glibc's heap counters: when the producer is
// called, no earlier produced texture may still be allocated.
TEST(PackRoundTrip, ProducerTexturesAreReleasedBeforeTheNext)
{
#ifndef __GLIBC__
    LFD_SKIP_OR_FAIL("needs glibc mallinfo2 to measure live heap bytes");
#else
    constexpr uint32_t kSize = 512; // 1.33 MiB with mips, far above the writer's own needs
    Scene lazy = withoutTexels(makeFullScene());
    lazy.textures.clear();
    for (uint32_t i = 0; i < 4; ++i) {
        Texture t;
        t.name = "big" + std::to_string(i);
        t.width = t.height = kSize;
        lazy.textures.push_back(t);
    }
    const Texture pattern = makeTexture("", kSize, kSize, false, 9);
    const size_t textureBytes = pattern.texels.size();
    auto liveBytes = [] {
        const struct mallinfo2 info = mallinfo2();
        return size_t(info.uordblks + info.hblkhd);
    };

    const fs::path dir = freshDir("release");
    const size_t baseline = liveBytes();
    size_t peak = 0;
    const TextureProducer produce = [&](uint32_t i) {
        peak = std::max(peak, liveBytes());
        Texture t = pattern;
        t.name = lazy.textures[i].name;
        return t;
    };
    writePack(dir / "big.lfdpack", lazy, produce);
    EXPECT_LT(peak, baseline + textureBytes / 2) << "a produced texture outlived its section write";
    EXPECT_EQ(readPack(dir / "big.lfdpack").textures[3].texels, pattern.texels);
    fs::remove_all(dir);
#endif
}

TEST(PackRoundTrip, ProducerMismatchIsAnError)
{
    const Scene eager = makeFullScene();
    const Scene lazy = withoutTexels(eager);
    auto expectError = [&](const TextureProducer& produce, const std::string& needle) {
        try {
            writePackToMemory(lazy, produce);
            ADD_FAILURE() << "expected PackError containing '" << needle << "'";
        } catch (const PackError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    expectError([&](uint32_t i) { Texture t = eager.textures[i]; t.width += 1; return t; }, "produced 6x3");
    expectError([&](uint32_t i) { Texture t = eager.textures[i]; t.texels.pop_back(); return t; }, "texel bytes");
    expectError([&](uint32_t i) { Texture t = eager.textures[i]; t.mips.pop_back(); return t; }, "mip levels");
    expectError([&](uint32_t i) { Texture t = eager.textures[i]; t.srgb = !t.srgb; return t; }, "sRGB");
    expectError([&](uint32_t) -> Texture { throw std::runtime_error("decoder exploded"); }, "decoder exploded");
}

TEST(PackRoundTrip, VerifyPackReportsTheSectionTable)
{
    const fs::path dir = freshDir("verify");
    const fs::path path = dir / "v.lfdpack";
    const Scene scene = makeFullScene();
    writePack(path, scene, {}, PackWriteOptions{false}); // raw: sizes are count * stride
    const PackInfo info = verifyPack(path);
    EXPECT_EQ(info.formatVersion, pack::kFormatVersion);
    EXPECT_EQ(info.fileSize, fs::file_size(path));

    const std::vector<std::string> expectedTags = {"BAKE", "BNDS", "STRS", "VPOS", "VNRM", "VTAN", "VTUV", "INDX",
                                                   "TSTA", "PRIM", "MESH", "MATL", "MEXT", "NODE", "LGHT", "ANIM",
                                                   "ACHN", "AKTM", "AKVL", "TEXL", "TEXD", "MIPS"};
    ASSERT_EQ(info.sections.size(), expectedTags.size());
    uint64_t previousEnd = 0;
    for (size_t i = 0; i < info.sections.size(); ++i) {
        const PackSectionInfo& s = info.sections[i];
        EXPECT_EQ(s.tag, expectedTags[i]);
        EXPECT_EQ(s.version, pack::kSectionVersion);
        EXPECT_EQ(s.offset % pack::kAlignment, 0u) << s.tag;
        EXPECT_GE(s.offset, previousEnd) << s.tag;
        previousEnd = s.offset + s.size;
    }
    EXPECT_EQ(previousEnd, info.fileSize);
    EXPECT_EQ(info.sections[3].count, scene.vertices.size());
    EXPECT_EQ(info.sections[7].count, scene.indices.size());
    EXPECT_EQ(info.sections[8].size, scene.triangleStats.size() * 24);
    EXPECT_EQ(info.sections[12].count, scene.materials.size());
    EXPECT_EQ(info.sections[14].count, scene.lights.size());
    EXPECT_EQ(info.sections[19].size, scene.textures[0].texels.size() + scene.textures[1].texels.size());

    // readPack hands out the same table from its one read (lfd-bake --inspect uses it).
    PackInfo fromRead;
    expectSameScene(scene, readPack(path, &fromRead));
    EXPECT_EQ(fromRead.fileSize, info.fileSize);
    ASSERT_EQ(fromRead.sections.size(), info.sections.size());
    for (size_t i = 0; i < info.sections.size(); ++i) {
        EXPECT_EQ(fromRead.sections[i].tag, info.sections[i].tag);
        EXPECT_EQ(fromRead.sections[i].offset, info.sections[i].offset);
        EXPECT_EQ(fromRead.sections[i].checksum, info.sections[i].checksum);
    }
    fs::remove_all(dir);
}

TEST(PackRoundTrip, WriterRefusesScenesTheReaderWouldReject)
{
    auto expectRefused = [](const Scene& scene, const std::string& needle) {
        try {
            writePackToMemory(scene);
            ADD_FAILURE() << "expected PackError containing '" << needle << "'";
        } catch (const PackError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    Scene s = makeFullScene();
    s.indices[4] = 8;
    expectRefused(s, "there are 8 vertices");
    s = makeFullScene();
    s.vertices.positions[2].y = std::numeric_limits<float>::quiet_NaN();
    expectRefused(s, "vertex 2: position is not finite");
    s = makeFullScene();
    s.triangleStats.pop_back();
    expectRefused(s, "3 triangle statistics for 4 triangles");
    s = makeFullScene();
    s.materials[0].emissiveTexture = 2;
    expectRefused(s, "emissive texture 2 does not exist");
    s = makeFullScene();
    s.nodes[1].parent = 1;
    expectRefused(s, "node 1: parent 1 does not precede");
    s = makeFullScene();
    s.animations[0].channels[0].times[2] = 0.5f;
    expectRefused(s, "not strictly increasing");
    s = makeFullScene();
    s.animations[1].channels[0].times.clear();
    s.animations[1].channels[0].values.clear();
    expectRefused(s, "animation 1 channel 0: has no keys");
    s = makeFullScene();
    s.textures[1].texels.resize(3);
    expectRefused(s, "texture 1: has 3 texel bytes");
    s = makeFullScene();
    s.vertices.uvs.pop_back();
    expectRefused(s, "vertex stream 'uv' has 7 entries");
}

} // namespace
} // namespace lfd::test
