// Format stability: tests/data/golden_v<N>.lfdpack were written from goldenScene() (v1)
// and goldenSceneV2() (v2) below, golden_v2_materials_lights.lfdpack from
// goldenSceneV2MaterialsLights() (v2 with the optional MEXT and LGHT sections). The reader
// must keep reading them, and today's writer must reproduce the current version's files
// byte for byte. An intentional format change is a new format version (golden_v3), not a
// regenerated v2; v1 is frozen (no writer of it is left).
//
// Regenerate the v2 files (only when their scenes themselves change):
//   LFD_REGENERATE_GOLDEN=1 ./lfd_formats_tests --gtest_filter='PackGolden.*'
#include "pack_test_scenes.h"

#include "lfd/pack_mapped.h"

#include <xxhash.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

const fs::path kGoldenV1Path = fs::path(LFD_TEST_DATA) / "golden_v1.lfdpack";
const fs::path kGoldenV2Path = fs::path(LFD_TEST_DATA) / "golden_v2.lfdpack";
const fs::path kGoldenV2MaterialsLightsPath = fs::path(LFD_TEST_DATA) / "golden_v2_materials_lights.lfdpack";

// Fixed forever: every section of version 1, tiny textures so the file stays small.
Scene goldenScene()
{
    Scene s;
    s.vertices.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5f}};
    s.vertices.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0.6f, 0.8f}};
    s.vertices.tangents = {{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}};
    s.vertices.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.indices = {0, 1, 2, 0, 2, 3};
    s.triangleStats = {{0.5f, 0.5f, 7.5f, 0.5f / 7.5f, 1.0f, kTriangleTextured},
                       {0.5590f, 0.5f, 7.5f, 0.5590f / 7.5f, 0.5f / 0.5590f, kTriangleTextured}};
    s.primitives = {{0, 3, 0}, {3, 3, kNone}};
    s.meshes = {{"quad", 0, 2}};
    Material m;
    m.name = "golden µ";
    m.baseColorFactor = {1.0f, 0.5f, 0.25f, 1.0f};
    m.emissiveFactor = {0.0f, 0.0f, 0.125f};
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.5f;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.25f;
    m.doubleSided = true;
    m.baseColorTexture = 0;
    m.metallicRoughnessTexture = 1;
    m.normalTexture = 1;
    m.occlusionTexture = 1;
    m.emissiveTexture = 0;
    s.materials = {m};
    s.textures = {makeTexture("base", 5, 3, true, 3), makeTexture("data", 2, 2, false, 4)};
    Node root;
    root.name = "root";
    root.translation = {0.0f, 1.0f, 0.0f};
    Node child;
    child.name = "child";
    child.parent = 0;
    child.mesh = 0;
    child.rotation = glm::quat(0.0f, 0.0f, 1.0f, 0.0f);
    child.scale = {0.5f, 0.5f, 0.5f};
    s.nodes = {root, child};
    s.animations = {{"turn",
                     {{1, AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f},
                       {{0, 0, 0, 1}, {0, 1, 0, 0}}},
                      {0, AnimationPath::Translation, Interpolation::Step, {0.5f}, {{0, 2, 0, 0}}}}}};
    s.bounds = {{0, 0.5f, -0.25f}, {1, 2, 0.25f}, {0.5f, 1.25f, 0}, 0.9f};
    s.settings.bakerVersion = "golden";
    s.settings.sourceFile = "golden.gltf";
    s.settings.displayProfile = "test-display";
    s.settings.viewWidth = 64;
    s.settings.viewHeight = 48;
    s.settings.viewCount = 8;
    s.settings.maxEdgePx = 100.0f;
    s.settings.framingFill = 0.75f;
    s.settings.viewPixelWorld = 0.03125f;
    s.settings.maxTextureSize = 8;
    return s;
}

// Fixed forever: version 1's scene plus what version 2 added - a zstd-compressed
// geometry stream (a grid of extra vertices compresses, the four quad vertices alone
// would not), zstd texture levels, and one texture of every block format.
Scene goldenSceneV2()
{
    Scene s = goldenScene();
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            s.vertices.positions.push_back({x / 15.0f, y / 15.0f, 0.0f});
            s.vertices.normals.push_back({0, 0, 1});
            s.vertices.tangents.push_back({1, 0, 0, 1});
            s.vertices.uvs.push_back({x / 15.0f, y / 15.0f});
        }
    Texture smooth = makeTexture("base", 16, 16, true, 3); // compressible: zstd levels
    for (size_t i = 0; i < smooth.texels.size(); ++i)
        smooth.texels[i] = uint8_t(i / 64);
    s.textures = {smooth, makeTexture("normal", 8, 8, false, 4, TextureFormat::Bc5),
                  makeTexture("colour", 6, 5, true, 5, TextureFormat::Bc1),
                  makeTexture("mask", 4, 4, true, 6, TextureFormat::Bc3),
                  makeTexture("occlusion", 3, 3, false, 7, TextureFormat::Bc4)};
    Material& m = s.materials[0];
    m.baseColorTexture = 3;
    m.metallicRoughnessTexture = 2;
    m.normalTexture = 1;
    m.occlusionTexture = 4;
    m.emissiveTexture = 0;
    return s;
}

// Fixed forever: version 2's scene plus the optional sections added within version 2 -
// material extensions (an unlit material, texture transforms) and one light of each type.
// Also a fuzzing seed (scripts/fuzz.sh) that reaches the MEXT and LGHT decoders.
Scene goldenSceneV2MaterialsLights()
{
    Scene s = goldenSceneV2();
    Material& m = s.materials[0];
    m.textureTransforms[uint32_t(TextureSlot::BaseColor)] =
        TextureTransform::fromOffsetRotationScale({0.5f, 0.25f}, 0.5f, {4.0f, 2.0f});
    m.textureTransforms[uint32_t(TextureSlot::Occlusion)].offset = {0.0f, -0.5f};
    Material unlit;
    unlit.name = "unlit";
    unlit.unlit = true;
    unlit.baseColorTexture = 2;
    s.materials.push_back(unlit);
    s.primitives[1].material = 1;
    s.lights = {Light{"sun", LightType::Directional, 0, {1.0f, 0.5f, 0.25f}, 2.0f, 0.0f, 0.0f, 0.78539816f},
                Light{"lamp", LightType::Point, 1, {0.5f, 1.0f, 1.0f}, 40.0f, 5.0f, 0.0f, 0.78539816f},
                Light{"spot", LightType::Spot, 1, {1.0f, 1.0f, 1.0f}, 800.0f, 0.0f, 0.25f, 0.5f}};
    return s;
}

std::vector<uint8_t> goldenBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

template <typename T>
T at(const std::vector<uint8_t>& bytes, size_t offset)
{
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

class PackGolden : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        const char* regenerate = std::getenv("LFD_REGENERATE_GOLDEN");
        if (regenerate && std::string(regenerate) == "1") {
            writePack(kGoldenV2Path, goldenSceneV2());
            writePack(kGoldenV2MaterialsLightsPath, goldenSceneV2MaterialsLights());
        }
    }
};

TEST_F(PackGolden, CommittedV1FileIsStillRead)
{
    ASSERT_TRUE(fs::exists(kGoldenV1Path)) << kGoldenV1Path << " is missing";
    expectSameScene(goldenScene(), readPack(kGoldenV1Path));
    EXPECT_NO_THROW(MappedPack{kGoldenV1Path});
}

TEST_F(PackGolden, CommittedV2FileIsSmallAndReadable)
{
    ASSERT_TRUE(fs::exists(kGoldenV2Path)) << kGoldenV2Path << " is missing (LFD_REGENERATE_GOLDEN=1 writes it)";
    EXPECT_LT(fs::file_size(kGoldenV2Path), 16u * 1024u);
    expectSameScene(goldenSceneV2(), readPack(kGoldenV2Path));
}

// The v2 file really holds what v2 added: a zstd section, zstd texture levels and every
// block format.
TEST_F(PackGolden, CommittedV2FileUsesEveryEncoding)
{
    PackInfo info;
    readPack(kGoldenV2Path, &info);
    EXPECT_EQ(info.formatVersion, 2u);
    bool zstdSection = false, rawGeometry = false;
    for (const PackSectionInfo& s : info.sections) {
        zstdSection = zstdSection || s.encoding == pack::kEncodingZstd;
        rawGeometry = rawGeometry || (s.tag == "INDX" && s.encoding == pack::kEncodingRaw);
    }
    EXPECT_TRUE(zstdSection);
    EXPECT_TRUE(rawGeometry);
    const MappedPack mapped(kGoldenV2Path);
    EXPECT_TRUE(mapped.levelsZstd(0));   // smooth RGBA8
    EXPECT_FALSE(mapped.levelsZstd(1)); // pseudo-random blocks stay raw
}

void expectWriterReproduces(const fs::path& path, const Scene& scene)
{
    SCOPED_TRACE(path.string());
    const std::vector<uint8_t> committed = goldenBytes(path);
    const std::vector<uint8_t> today = writePackToMemory(scene);
    ASSERT_EQ(today.size(), committed.size());
    for (size_t i = 0; i < today.size(); ++i)
        ASSERT_EQ(today[i], committed[i]) << "first difference at byte " << i;
}

TEST_F(PackGolden, WriterReproducesTheCommittedBytes)
{
    expectWriterReproduces(kGoldenV2Path, goldenSceneV2());
    expectWriterReproduces(kGoldenV2MaterialsLightsPath, goldenSceneV2MaterialsLights());
}

// The materials-and-lights file is read back as its scene and holds golden_v2's sections
// plus exactly the two optional ones.
TEST_F(PackGolden, MaterialsLightsFileIsTheV2FilePlusTwoSections)
{
    ASSERT_TRUE(fs::exists(kGoldenV2MaterialsLightsPath))
        << kGoldenV2MaterialsLightsPath << " is missing (LFD_REGENERATE_GOLDEN=1 writes it)";
    EXPECT_LT(fs::file_size(kGoldenV2MaterialsLightsPath), 16u * 1024u);
    expectSameScene(goldenSceneV2MaterialsLights(), readPack(kGoldenV2MaterialsLightsPath));
    PackInfo v2, extended;
    readPack(kGoldenV2Path, &v2);
    readPack(kGoldenV2MaterialsLightsPath, &extended);
    std::vector<std::string> added;
    for (const PackSectionInfo& s : extended.sections) {
        bool old = false;
        for (const PackSectionInfo& o : v2.sections)
            old = old || o.tag == s.tag;
        if (!old)
            added.push_back(s.tag);
    }
    EXPECT_EQ(added, (std::vector<std::string>{"MEXT", "LGHT"}));
    EXPECT_EQ(extended.sections.size(), v2.sections.size() + 2);
}

// The header fields at the offsets formats/README.md documents, read without pack_layout.h
// structs, with the checksum computed by xxhash directly.
void expectDocumentedLayout(const fs::path& path, uint32_t version)
{
    SCOPED_TRACE(path.string());
    const std::vector<uint8_t> bytes = goldenBytes(path);
    ASSERT_GE(bytes.size(), 64u);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(bytes.data()), 8), std::string("LFDPACK\x1a", 8));
    EXPECT_EQ(at<uint32_t>(bytes, 8), version); // format version
    EXPECT_EQ(at<uint32_t>(bytes, 12), 64u); // header size
    const uint32_t sectionCount = at<uint32_t>(bytes, 16);
    EXPECT_EQ(sectionCount, 20u);             // every v1 section, optional streams included
    EXPECT_EQ(at<uint32_t>(bytes, 20), 48u);  // section entry size
    EXPECT_EQ(at<uint64_t>(bytes, 24), 64u);  // table offset
    EXPECT_EQ(at<uint64_t>(bytes, 32), bytes.size());
    EXPECT_EQ(at<uint64_t>(bytes, 40), XXH3_64bits(bytes.data() + 64, sectionCount * 48));
    EXPECT_EQ(at<uint64_t>(bytes, 48), 0u);
    EXPECT_EQ(at<uint64_t>(bytes, 56), XXH3_64bits(bytes.data(), 56));
    for (uint32_t i = 0; i < sectionCount; ++i) {
        const size_t entry = 64 + i * 48;
        const uint64_t offset = at<uint64_t>(bytes, entry + 8);
        const uint64_t size = at<uint64_t>(bytes, entry + 16);
        const uint64_t count = at<uint64_t>(bytes, entry + 24);
        const uint32_t stride = at<uint32_t>(bytes, entry + 40);
        const uint32_t encoding = at<uint32_t>(bytes, entry + 44);
        EXPECT_EQ(at<uint32_t>(bytes, entry + 4), 1u);
        EXPECT_EQ(offset % 64, 0u);
        EXPECT_LE(encoding, version == 1 ? 0u : 1u);
        if (encoding == 0)
            EXPECT_EQ(size, count * stride);
        else
            EXPECT_EQ(at<uint32_t>(bytes, size_t(offset)), 0xFD2FB528u); // zstd frame magic
        EXPECT_EQ(at<uint64_t>(bytes, entry + 32), XXH3_64bits(bytes.data() + offset, size));
    }
}

TEST_F(PackGolden, HeaderMatchesTheDocumentedLayout)
{
    expectDocumentedLayout(kGoldenV1Path, 1);
    expectDocumentedLayout(kGoldenV2Path, 2);
}

} // namespace
} // namespace lfd::test
