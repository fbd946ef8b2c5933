// Format 2's encodings: zstd sections, zstd texture levels and block-compressed
// textures round trip exactly, shrink what they should, and every forged or corrupted
// compressed payload is a one-line PackError, never a crash or a huge allocation.
#include "pack_test_scenes.h"

#include "lfd/pack_mapped.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace lfd::test {
namespace {

using namespace lfd::pack;
namespace fs = std::filesystem;

const std::string kName = "zstd.lfdpack";

// makeFullScene plus a 64x64 vertex grid (compressible streams) and a smooth 64x64
// RGBA8 texture (compressible levels) next to a block-compressed one of noise (raw).
Scene compressibleScene()
{
    Scene s = makeFullScene();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            s.vertices.positions.push_back({x / 63.0f, y / 63.0f, 0.25f});
            s.vertices.normals.push_back({0, 0, 1});
            s.vertices.tangents.push_back({1, 0, 0, 1});
            s.vertices.uvs.push_back({x / 63.0f, y / 63.0f});
        }
    Texture smooth = makeTexture("smooth", 64, 64, true, 1);
    for (size_t i = 0; i < smooth.texels.size(); ++i)
        smooth.texels[i] = uint8_t((i / 256) & 0xff);
    s.textures[0] = smooth;
    // Noise blocks: zstd cannot save 5% of them, so they stay raw.
    Texture noise = makeTexture("blocks", 16, 8, false, 2, TextureFormat::Bc5);
    uint32_t state = 12345;
    for (uint8_t& b : noise.texels) {
        state = state * 1664525u + 1013904223u;
        b = uint8_t(state >> 24);
    }
    s.textures[1] = noise;
    return s;
}

std::vector<uint8_t> compressedPack() { return writePackToMemory(compressibleScene()); }

std::string rejection(const std::vector<uint8_t>& bytes)
{
    try {
        readPackFromMemory(bytes.data(), bytes.size(), kName);
    } catch (const PackError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind(kName + ": ", 0), 0u) << what;
        return what;
    }
    ADD_FAILURE() << "pack accepted";
    return "";
}

void expectRejected(std::vector<uint8_t> bytes, const std::string& needle)
{
    resealPack(bytes);
    const std::string what = rejection(bytes);
    EXPECT_NE(what.find(needle), std::string::npos) << "message: " << what << "\nexpected: " << needle;
}

TEST(PackCompression, SameSceneSmallerPack)
{
    const Scene scene = compressibleScene();
    const std::vector<uint8_t> zstd = writePackToMemory(scene);
    const std::vector<uint8_t> raw = writePackToMemory(scene, {}, PackWriteOptions{false});
    EXPECT_LT(zstd.size() * 3, raw.size()) << "zstd " << zstd.size() << " raw " << raw.size();
    expectSameScene(scene, readPackFromMemory(zstd.data(), zstd.size(), kName));
    expectSameScene(scene, readPackFromMemory(raw.data(), raw.size(), kName));
    EXPECT_EQ(entryFor(zstd, kTagPositions).encoding, kEncodingZstd);
    EXPECT_EQ(entryFor(zstd, kTagTexels).encoding, kEncodingRaw); // levels carry their own
    for (uint32_t tag : {kTagPositions, kTagNormals, kTagTexels})
        EXPECT_EQ(entryFor(raw, tag).encoding, kEncodingRaw);
}

TEST(PackCompression, MappedPackInflatesSectionsAndStreamsLevels)
{
    const Scene scene = compressibleScene();
    const fs::path path = fs::temp_directory_path() / ("lfd_zstd_" + std::to_string(::getpid()) + ".lfdpack");
    {
        const std::vector<uint8_t> bytes = writePackToMemory(scene);
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
    }
    MappedPack mapped(path);
    const auto positions = mapped.section(kTagPositions);
    ASSERT_EQ(positions.size(), scene.vertices.positions.size() * 12);
    EXPECT_EQ(std::memcmp(positions.data(), scene.vertices.positions.data(), positions.size()), 0);
    ASSERT_TRUE(mapped.levelsZstd(0));
    EXPECT_FALSE(mapped.levelsZstd(1)); // noise blocks: zstd would not save 5%
    for (uint32_t t = 0; t < 2; ++t)
        for (uint32_t l = 0; l < scene.textures[t].mips.size(); ++l) {
            const MipLevel& level = scene.textures[t].mips[l];
            const auto stored = mapped.mipBytes(t, l);
            std::vector<uint8_t> texels(stored.begin(), stored.end());
            if (mapped.levelsZstd(t)) {
                texels.assign(size_t(level.size), 0);
                LevelInflater inflater(stored, level.size, kName, "level");
                const size_t first = std::min<size_t>(5, texels.size()); // piece by piece, as streamed
                inflater.read(texels.data(), first);
                inflater.read(texels.data() + first, texels.size() - first);
                EXPECT_EQ(inflater.remaining(), 0u);
            }
            ASSERT_EQ(texels.size(), level.size);
            EXPECT_TRUE(std::equal(texels.begin(), texels.end(), scene.textures[t].texels.begin() + long(level.offset)));
            mapped.noteTexelsRead(mapped.mipTexelOffset(t, l), stored.size());
        }
    EXPECT_NO_THROW(mapped.finishTexelVerification());
    fs::remove(path);
}

TEST(PackCompression, CorruptZstdSectionIsRejected)
{
    std::vector<uint8_t> bytes = compressedPack();
    const SectionEntry e = entryFor(bytes, kTagPositions);
    ASSERT_EQ(e.encoding, kEncodingZstd);
    bytes[size_t(e.offset + e.size / 2)] ^= 0x5a;
    expectRejected(bytes, "section 'VPOS'");
}

TEST(PackCompression, FrameMustHoldExactlyTheCount)
{
    std::vector<uint8_t> bytes = compressedPack();
    const auto i = *entryIndex(bytes, kTagPositions);
    SectionEntry e = entryAt(bytes, i);
    e.count -= 1;
    setEntry(bytes, i, e);
    expectRejected(bytes, "section 'VPOS': zstd frame holds");
}

TEST(PackCompression, ForgedExpansionIsRefusedBeforeAllocation)
{
    std::vector<uint8_t> bytes = compressedPack();
    const auto i = *entryIndex(bytes, kTagPositions);
    SectionEntry e = entryAt(bytes, i);
    e.count = uint64_t(1) << 40;
    setEntry(bytes, i, e);
    expectRejected(bytes, "compressed bytes may hold");
}

TEST(PackCompression, EncodingRules)
{
    const std::vector<uint8_t> good = compressedPack();
    {
        std::vector<uint8_t> bytes = good;
        const auto i = *entryIndex(bytes, kTagTexels);
        SectionEntry e = entryAt(bytes, i);
        e.encoding = kEncodingZstd;
        setEntry(bytes, i, e);
        expectRejected(bytes, "section 'TEXL' cannot be zstd-compressed as a whole");
    }
    {
        std::vector<uint8_t> bytes = good;
        const auto i = *entryIndex(bytes, kTagNormals);
        SectionEntry e = entryAt(bytes, i);
        e.encoding = 2;
        setEntry(bytes, i, e);
        expectRejected(bytes, "section 'VNRM' has unknown encoding 2");
    }
    {
        // Format 1 had a reserved word there.
        std::vector<uint8_t> bytes = good;
        FileHeader h = headerOf(bytes);
        h.formatVersion = 1;
        setHeader(bytes, h);
        expectRejected(bytes, "section 'VPOS' has a non-zero reserved field");
    }
}

TEST(PackCompression, TextureFormatRules)
{
    const std::vector<uint8_t> good = compressedPack();
    auto patched = [&](uint32_t texture, size_t field, uint32_t value) {
        std::vector<uint8_t> bytes = good;
        writeElement<uint32_t>(bytes, kTagTextures, texture, value, field);
        return bytes;
    };
    expectRejected(patched(1, offsetof(TextureRecord, format), 9), "texture 1: unknown format 9");
    // Raw blocks flagged as zstd frames.
    expectRejected(patched(1, offsetof(TextureRecord, flags), kTextureZstdLevels), "texture 1 mip level 0");
    // A BC5 record read as BC1 no longer matches its level sizes.
    expectRejected(patched(1, offsetof(TextureRecord, format), uint32_t(TextureFormat::Bc1)),
                   "texture 1: mip level 0 is 16x8 at +0 size 128, expected 16x8 at +0 size 64");
}

TEST(PackCompression, CorruptTextureLevelIsRejectedByReadAndVerify)
{
    std::vector<uint8_t> bytes = compressedPack();
    const SectionEntry texl = entryFor(bytes, kTagTexels);
    // Texture 0's level 0 frame starts TEXL: break its magic. (A flipped literal inside a
    // resealed frame would decode to other texels of the right size - harmless, and
    // without a forged checksum the TEXL checksum catches it.)
    bytes[size_t(texl.offset)] ^= 0x33;
    resealPack(bytes);
    const std::string what = rejection(bytes);
    EXPECT_NE(what.find("texture 0 mip level 0"), std::string::npos) << what;

    const fs::path path = fs::temp_directory_path() / ("lfd_zstd_bad_" + std::to_string(::getpid()) + ".lfdpack");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
    EXPECT_THROW(verifyPack(path), PackError);
    // The mapped reader opens it (texels are checked as they stream) and fails on the level.
    MappedPack mapped(path);
    const MipLevel& level = mapped.textures()[0].mips[0];
    std::vector<uint8_t> out(size_t(level.size));
    EXPECT_THROW(LevelInflater(mapped.mipBytes(0, 0), level.size, kName, "level").read(out.data(), out.size()),
                 PackError);
    fs::remove(path);
}

// A uniform level past 16 MiB compresses beyond the reader's expansion bound: the
// writer pads its frame with a skippable frame, and every reader path takes it.
TEST(PackCompression, UniformLevelIsPaddedToTheExpansionBound)
{
    Scene s = makeFullScene();
    Texture flat = makeTexture("flat", 4096, 1100, false, 1);
    std::fill(flat.texels.begin(), flat.texels.end(), uint8_t(77));
    s.textures[0] = flat;
    const std::vector<uint8_t> bytes = writePackToMemory(s);
    EXPECT_LT(bytes.size(), flat.texels.size() / 64); // still tiny
    expectSameScene(s, readPackFromMemory(bytes.data(), bytes.size(), kName));

    const fs::path path = fs::temp_directory_path() / ("lfd_zstd_flat_" + std::to_string(::getpid()) + ".lfdpack");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
    EXPECT_NO_THROW(verifyPack(path));
    MappedPack mapped(path);
    ASSERT_TRUE(mapped.levelsZstd(0));
    const MipLevel& level0 = mapped.textures()[0].mips[0];
    const auto stored = mapped.mipBytes(0, 0);
    EXPECT_LE(level0.size, stored.size() * kZstdMaxRatio);
    LevelInflater inflater(stored, level0.size, kName, "level 0");
    std::vector<uint8_t> chunk(1 << 20);
    for (uint64_t left = level0.size; left > 0;) {
        const size_t n = size_t(std::min<uint64_t>(left, chunk.size()));
        inflater.read(chunk.data(), n);
        EXPECT_TRUE(std::all_of(chunk.begin(), chunk.begin() + long(n), [](uint8_t b) { return b == 77; }));
        left -= n;
    }
    fs::remove(path);
}

TEST(PackCompression, BlockLevelSizes)
{
    EXPECT_EQ(textureLevelBytes(TextureFormat::Rgba8, 5, 3), 60u);
    EXPECT_EQ(textureLevelBytes(TextureFormat::Bc1, 1, 1), 8u);  // one block, however small
    EXPECT_EQ(textureLevelBytes(TextureFormat::Bc1, 5, 3), 16u); // 2 x 1 blocks
    EXPECT_EQ(textureLevelBytes(TextureFormat::Bc3, 8, 8), 64u);
    EXPECT_EQ(textureLevelBytes(TextureFormat::Bc4, 16, 4), 32u);
    EXPECT_EQ(textureLevelBytes(TextureFormat::Bc5, 2048, 2048), 4u << 20);
    // 8x8 BC1: 8x8 (4 blocks), 4x4, 2x2, 1x1 (one block each) = 7 blocks.
    EXPECT_EQ(textureChainBytes(8, 8, TextureFormat::Bc1), 56u);
}

} // namespace
} // namespace lfd::test
