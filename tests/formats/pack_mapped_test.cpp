// MappedPack (memory-mapped read for streaming): the same Scene as readPack but texels,
// texel bytes found in the mapping, the deferred TEXL checksum, and rejection of
// truncated and crafted packs before any allocation they could drive.
#include "pack_test_scenes.h"

#include "lfd/pack_mapped.h"

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

fs::path writeBytes(const std::string& name, const std::vector<uint8_t>& bytes)
{
    const fs::path path = fs::temp_directory_path() / ("lfd_pack_mapped_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

// Reads every texel through the mapping, coarsest level first as the streamer does.
void readAllTexels(MappedPack& pack)
{
    const auto& textures = pack.scene().textures;
    for (size_t t = 0; t < textures.size(); ++t)
        for (size_t l = textures[t].mips.size(); l-- > 0;) {
            const auto bytes = pack.mipBytes(uint32_t(t), uint32_t(l));
            pack.noteTexelsRead(pack.mipTexelOffset(uint32_t(t), uint32_t(l)), bytes.size());
            pack.releasePages(bytes.data(), bytes.size());
        }
    pack.finishTexelVerification();
}

TEST(PackMapped, SameSceneAsReadPackAndTexelsInTheMapping)
{
    const Scene scene = makeFullScene();
    const fs::path path = writeBytes("full.lfdpack", writePackToMemory(scene));
    const Scene eager = readPack(path);
    MappedPack mapped(path);
    expectSameScene(withoutTexels(eager), [&] {
        Scene s = mapped.scene();
        for (Texture& t : s.textures)
            t.mips.clear(); // withoutTexels drops the chains too
        return s;
    }());
    ASSERT_EQ(mapped.scene().textures.size(), eager.textures.size());
    for (size_t t = 0; t < eager.textures.size(); ++t) {
        const Texture& e = eager.textures[t];
        EXPECT_TRUE(mapped.scene().textures[t].texels.empty());
        ASSERT_EQ(mapped.scene().textures[t].mips.size(), e.mips.size());
        for (size_t l = 0; l < e.mips.size(); ++l) {
            const auto stored = mapped.mipBytes(uint32_t(t), uint32_t(l));
            std::vector<uint8_t> bytes(stored.begin(), stored.end());
            if (mapped.levelsZstd(uint32_t(t))) { // compressible levels are zstd frames by default
                bytes.resize(size_t(e.mips[l].size));
                LevelInflater(stored, e.mips[l].size, "full", "level").read(bytes.data(), bytes.size());
            }
            ASSERT_EQ(bytes.size(), e.mips[l].size);
            EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), e.texels.begin() + long(e.mips[l].offset)))
                << "texture " << t << " level " << l;
        }
    }
    EXPECT_EQ(mapped.info().sections.size(), verifyPack(path).sections.size());
    EXPECT_NO_THROW(readAllTexels(mapped));
    EXPECT_TRUE(mapped.texelsVerified());
    fs::remove(path);
}

TEST(PackMapped, GoldenPackMatchesReadPack)
{
    const fs::path golden = fs::path(LFD_TEST_DATA) / "golden_v1.lfdpack";
    MappedPack mapped(golden);
    const Scene eager = readPack(golden);
    EXPECT_EQ(mapped.scene().vertices.positions, eager.vertices.positions);
    EXPECT_EQ(mapped.scene().indices, eager.indices);
    EXPECT_EQ(mapped.scene().nodes.size(), eager.nodes.size());
    EXPECT_NO_THROW(readAllTexels(mapped));
}

TEST(PackMapped, CorruptTexelByteIsDetectedWithOneLineNamingTheFile)
{
    std::vector<uint8_t> bytes = writePackToMemory(makeFullScene());
    const auto texl = entryAt(bytes, *entryIndex(bytes, pack::kTagTexels));
    ASSERT_GT(texl.size, 0u);
    bytes[size_t(texl.offset + texl.size / 2)] ^= 0x01;
    const fs::path path = writeBytes("corrupt texel.lfdpack", bytes);
    EXPECT_THROW(readPack(path), PackError); // the whole-file reader still refuses it up front
    MappedPack mapped(path);                 // the mapped reader defers the texel checksum
    try {
        readAllTexels(mapped);
        FAIL() << "corrupt texel not detected";
    } catch (const PackError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
        EXPECT_NE(what.find("TEXL"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    fs::remove(path);
}

TEST(PackMapped, CorruptNonTexelBytesAreRejectedAtOpen)
{
    std::vector<uint8_t> bytes = writePackToMemory(makeFullScene());
    const auto vpos = entryAt(bytes, *entryIndex(bytes, pack::kTagPositions));
    bytes[size_t(vpos.offset)] ^= 0x40;
    const fs::path path = writeBytes("corrupt vpos.lfdpack", bytes);
    EXPECT_THROW(MappedPack{path}, PackError);
    fs::remove(path);
}

TEST(PackMapped, EveryTruncationIsRejected)
{
    const std::vector<uint8_t> bytes = writePackToMemory(makeFullScene());
    // Every prefix length up to the table, then a spread of lengths through the payloads.
    for (size_t n = 0; n < bytes.size(); n += (n < 256 ? 1 : 211)) {
        const fs::path path = writeBytes("trunc.lfdpack", std::vector<uint8_t>(bytes.begin(), bytes.begin() + long(n)));
        EXPECT_THROW(MappedPack{path}, PackError) << n << " bytes";
    }
    fs::remove(writeBytes("trunc.lfdpack", {}));
}

TEST(PackMapped, HugeClaimedCountsAreRejectedWithoutAllocating)
{
    // A texture claiming 65536x65536 (16 GiB of texels) in a small file, resealed so only
    // the semantic checks can catch it: the reader must fail, not try to allocate.
    std::vector<uint8_t> bytes = writePackToMemory(makeFullScene());
    const auto texd = entryAt(bytes, *entryIndex(bytes, pack::kTagTextures));
    pack::TextureRecord r{};
    std::memcpy(&r, bytes.data() + texd.offset, sizeof r);
    r.width = 65536;
    r.height = 65536;
    std::memcpy(bytes.data() + texd.offset, &r, sizeof r);
    pack::resealPack(bytes);
    const fs::path path = writeBytes("huge.lfdpack", bytes);
    try {
        MappedPack mapped(path);
        FAIL() << "huge texture accepted";
    } catch (const PackError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
    fs::remove(path);
}

TEST(PackMapped, MissingFileAndDirectoryAreOneLineErrors)
{
    EXPECT_THROW(MappedPack{fs::path("/nonexistent/x.lfdpack")}, PackError);
    EXPECT_THROW(MappedPack{fs::temp_directory_path()}, PackError);
}

} // namespace
} // namespace lfd::test
