// Material extensions (MEXT: unlit, texture transforms) and lights (LGHT) in a pack
// (formats/README.md "MEXT", "LGHT"): round trips through every reader, the sections
// present only when used, the rules the reader enforces (each broken by patching a
// record and resealing the checksums) and the writer refusing the same scenes.
#include "pack_test_scenes.h"

#include "lfd/pack_mapped.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <limits>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;
using namespace lfd::pack;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// Raw sections, so records can be patched in place.
std::vector<uint8_t> rawPack(const Scene& scene = makeFullScene())
{
    return writePackToMemory(scene, {}, PackWriteOptions{false});
}

// Writes `value` at `byteOffset` of element `i` of section `tag`, reseals, expects `needle`.
template <typename T>
void expectPatchRejected(uint32_t tag, uint64_t i, size_t byteOffset, const T& value, const std::string& needle)
{
    SCOPED_TRACE(tagName(tag) + " element " + std::to_string(i) + " +" + std::to_string(byteOffset));
    std::vector<uint8_t> bytes = rawPack();
    writeElement(bytes, tag, i, value, byteOffset);
    resealPack(bytes);
    expectPackRejected(bytes, needle);
}

void expectWriterRefuses(const Scene& scene, const std::string& needle)
{
    try {
        writePackToMemory(scene);
        ADD_FAILURE() << "written, expected '" << needle << "'";
    } catch (const PackError& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

fs::path tempPath(const std::string& name)
{
    return fs::temp_directory_path() / ("lfd_pack_ml_" + std::to_string(::getpid()) + "_" + name);
}

TEST(PackMaterialsLights, EveryReaderKeepsUnlitTransformsAndLights)
{
    const Scene scene = makeFullScene();
    for (const bool compress : {false, true}) {
        SCOPED_TRACE(compress ? "zstd" : "raw");
        const std::vector<uint8_t> bytes = writePackToMemory(scene, {}, PackWriteOptions{compress});
        const Scene memory = readPackFromMemory(bytes.data(), bytes.size(), kTestPackName);
        expectSameScene(scene, memory);
        EXPECT_TRUE(memory.materials[1].unlit);
        EXPECT_FALSE(memory.materials[0].unlit);
        EXPECT_FALSE(memory.materials[0].transform(TextureSlot::BaseColor).identity());
        EXPECT_TRUE(memory.materials[0].transform(TextureSlot::Occlusion).identity());
        ASSERT_EQ(memory.lights.size(), 3u);
        EXPECT_EQ(memory.lights[2].type, LightType::Spot);

        const fs::path path = tempPath(compress ? "zstd.lfdpack" : "raw.lfdpack");
        writePack(path, scene, {}, PackWriteOptions{compress});
        expectSameScene(scene, readPack(path));
        EXPECT_NO_THROW(verifyPack(path));
        {
            const MappedPack mapped(path);
            Scene withTexels = mapped.scene(); // the mapped reader leaves texels in the file
            for (size_t t = 0; t < withTexels.textures.size(); ++t)
                withTexels.textures[t].texels = scene.textures[t].texels;
            expectSameScene(scene, withTexels);
            EXPECT_EQ(mapped.section(kTagMaterialExtensions).size(), scene.materials.size() * 176);
            EXPECT_EQ(mapped.section(kTagLights).size(), scene.lights.size() * 48);
        }
        fs::remove(path);
    }
}

TEST(PackMaterialsLights, SectionsAreWrittenOnlyWhenUsed)
{
    Scene plain = makeFullScene();
    plain.lights.clear();
    for (Material& m : plain.materials) {
        m.unlit = false;
        for (TextureTransform& t : m.textureTransforms)
            t = TextureTransform{};
    }
    std::vector<uint8_t> bytes = rawPack(plain);
    EXPECT_FALSE(entryIndex(bytes, kTagMaterialExtensions).has_value());
    EXPECT_FALSE(entryIndex(bytes, kTagLights).has_value());

    // Lights alone: LGHT only. One unlit material: MEXT for every material.
    Scene lit = plain;
    lit.lights = makeFullScene().lights;
    bytes = rawPack(lit);
    EXPECT_FALSE(entryIndex(bytes, kTagMaterialExtensions).has_value());
    EXPECT_EQ(entryFor(bytes, kTagLights).count, 3u);
    Scene unlit = plain;
    unlit.materials[1].unlit = true;
    bytes = rawPack(unlit);
    EXPECT_EQ(entryFor(bytes, kTagMaterialExtensions).count, 2u);
    EXPECT_FALSE(entryIndex(bytes, kTagLights).has_value());
    const Scene back = readPackFromMemory(bytes.data(), bytes.size(), kTestPackName);
    EXPECT_TRUE(back.materials[1].unlit);
    EXPECT_TRUE(back.materials[0].transform(TextureSlot::BaseColor).identity());
}

// The records at the offsets formats/README.md gives, read without the layout structs.
TEST(PackMaterialsLights, RecordsMatchTheDocumentedLayout)
{
    const Scene scene = makeFullScene();
    const std::vector<uint8_t> bytes = rawPack(scene);
    auto f32 = [&](uint32_t tag, uint64_t i, size_t offset) { return readElement<float>(bytes, tag, i, offset); };
    auto u32 = [&](uint32_t tag, uint64_t i, size_t offset) { return readElement<uint32_t>(bytes, tag, i, offset); };
    EXPECT_EQ(entryFor(bytes, kTagMaterialExtensions).stride, 176u);
    EXPECT_EQ(u32(kTagMaterialExtensions, 0, 0), 0u);
    EXPECT_EQ(u32(kTagMaterialExtensions, 1, 0), 1u); // unlit
    const TextureTransform& normal = scene.materials[0].transform(TextureSlot::Normal);
    const size_t slot = 16 + 32 * 2; // the normal map's uv map
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 0), normal.linear[0][0]);
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 4), normal.linear[0][1]);
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 8), normal.linear[1][0]);
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 12), normal.linear[1][1]);
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 16), normal.offset.x);
    EXPECT_EQ(f32(kTagMaterialExtensions, 0, slot + 20), normal.offset.y);
    EXPECT_EQ(u32(kTagMaterialExtensions, 0, slot + 24), 0u);
    EXPECT_EQ(f32(kTagMaterialExtensions, 1, 16), 1.0f); // identity of an unlit material
    EXPECT_EQ(f32(kTagMaterialExtensions, 1, 20), 0.0f);

    EXPECT_EQ(entryFor(bytes, kTagLights).stride, 48u);
    const Light& spot = scene.lights[2];
    EXPECT_EQ(u32(kTagLights, 2, 0), 2u);
    EXPECT_EQ(u32(kTagLights, 2, 4), spot.node);
    EXPECT_EQ(f32(kTagLights, 1, 8), scene.lights[1].color.r);
    EXPECT_EQ(f32(kTagLights, 1, 16), scene.lights[1].color.b);
    EXPECT_EQ(f32(kTagLights, 1, 20), scene.lights[1].intensity);
    EXPECT_EQ(f32(kTagLights, 1, 24), scene.lights[1].range);
    EXPECT_EQ(f32(kTagLights, 2, 28), spot.innerConeAngle);
    EXPECT_EQ(f32(kTagLights, 2, 32), spot.outerConeAngle);
    EXPECT_EQ(u32(kTagLights, 2, 32), 0x3FC90FDBu); // pi/2 as f32
    EXPECT_EQ(u32(kTagLights, 0, 36), 0u);
    EXPECT_EQ(u32(kTagLights, 0, 44), uint32_t(scene.lights[0].name.size())); // str length
}

TEST(PackMaterialsLights, ReaderRefusesBrokenMaterialExtensions)
{
    expectPatchRejected<uint32_t>(kTagMaterialExtensions, 0, 0, 2, "material 0 extensions: unknown flags 2");
    expectPatchRejected<uint32_t>(kTagMaterialExtensions, 1, 8, 1, "material 1 extensions: non-zero reserved");
    expectPatchRejected<uint32_t>(kTagMaterialExtensions, 0, 16 + 32 * 4 + 28, 1,
                                  "material 0 extensions: non-zero reserved");
    expectPatchRejected<float>(kTagMaterialExtensions, 0, 16 + 4, kNan, "material 0: texture transform is not finite");
    expectPatchRejected<float>(kTagMaterialExtensions, 1, 16 + 32 * 3 + 20, std::numeric_limits<float>::infinity(),
                               "material 1: texture transform is not finite");

    // One record short: the section shrinks by a record (its bytes become zero padding).
    std::vector<uint8_t> bytes = rawPack();
    const uint32_t i = *entryIndex(bytes, kTagMaterialExtensions);
    SectionEntry e = entryAt(bytes, i);
    std::fill(bytes.begin() + ptrdiff_t(e.offset + e.size - 176), bytes.begin() + ptrdiff_t(e.offset + e.size), 0);
    e.size -= 176;
    e.count -= 1;
    setEntry(bytes, i, e);
    resealPack(bytes);
    expectPackRejected(bytes, "'MEXT' holds 1 records for 2 materials");
}

TEST(PackMaterialsLights, ReaderRefusesBrokenLights)
{
    expectPatchRejected<uint32_t>(kTagLights, 0, 0, 3, "light 0: invalid type 3");
    expectPatchRejected<uint32_t>(kTagLights, 1, 4, 4, "light 1: node 4 does not exist (4 nodes)");
    expectPatchRejected<float>(kTagLights, 0, 12, kNan, "light 0: values are not finite");
    expectPatchRejected<float>(kTagLights, 2, 32, std::numeric_limits<float>::infinity(),
                               "light 2: values are not finite");
    expectPatchRejected<float>(kTagLights, 1, 16, -0.5f, "light 1: colour is negative");
    expectPatchRejected<float>(kTagLights, 0, 20, -1.0f, "light 0: intensity is negative");
    expectPatchRejected<float>(kTagLights, 1, 24, -2.0f, "light 1: range is negative");
    expectPatchRejected<float>(kTagLights, 2, 28, -0.01f, "light 2: spot cone angles");
    expectPatchRejected<float>(kTagLights, 2, 28, pack::kMaxSpotConeAngle, "light 2: spot cone angles");
    expectPatchRejected<float>(kTagLights, 2, 32, 1.6f, "light 2: spot cone angles");
    expectPatchRejected<uint32_t>(kTagLights, 1, 36, 7, "light 1: non-zero reserved field");
    expectPatchRejected<uint32_t>(kTagLights, 1, 40, 1u << 20, "light 1: name [1048576, +");
    // A point light's cone angles are not a spot cone: only finite.
    std::vector<uint8_t> bytes = rawPack();
    writeElement<float>(bytes, kTagLights, 1, 1.6f, 28);
    resealPack(bytes);
    EXPECT_FLOAT_EQ(readPackFromMemory(bytes.data(), bytes.size(), kTestPackName).lights[1].innerConeAngle, 1.6f);
}

TEST(PackMaterialsLights, WriterRefusesWhatTheReaderWould)
{
    Scene s = makeFullScene();
    s.materials[0].textureTransforms[uint32_t(TextureSlot::Normal)].linear[1][0] = kNan;
    expectWriterRefuses(s, "material 0: texture transform is not finite");
    s = makeFullScene();
    s.lights[0].type = LightType(7);
    expectWriterRefuses(s, "light 0: invalid type 7");
    s = makeFullScene();
    s.lights[1].node = 99;
    expectWriterRefuses(s, "light 1: node 99 does not exist");
    s = makeFullScene();
    s.lights[1].range = kNan;
    expectWriterRefuses(s, "light 1: values are not finite");
    s = makeFullScene();
    s.lights[0].color.g = -1.0f;
    expectWriterRefuses(s, "light 0: colour is negative");
    s = makeFullScene();
    s.lights[0].intensity = -1.0f;
    expectWriterRefuses(s, "light 0: intensity is negative");
    s = makeFullScene();
    s.lights[1].range = -1.0f;
    expectWriterRefuses(s, "light 1: range is negative");
    s = makeFullScene();
    s.lights[2].innerConeAngle = s.lights[2].outerConeAngle;
    expectWriterRefuses(s, "light 2: spot cone angles");
}

} // namespace
} // namespace lfd::test
