// glTF import stage: hand-made edge cases (tests/data/gltf, see make_cases.py), the
// glTF files of Debian's assimp-testmodels (valid and deliberately broken ones) and the
// third-party scenes in ../shared/scenes.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_findings.h"
#include "gltf_import.h"
#include "import_test_cases.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <unistd.h>

namespace fs = std::filesystem;
using lfd::bake::BakeError;
using lfd::bake::ImportedScene;
using lfd::test::hasWarning;
using lfd::test::kGltfCases;

namespace {

const fs::path kAssimp = "/usr/share/assimp/models/glTF2";
const fs::path kShared = LFD_SHARED_SCENES;

struct Captured {
    std::vector<std::string> info;
    std::vector<std::string> warn;
};

ImportedScene import(const fs::path& path, Captured* captured = nullptr)
{
    lfd::bake::Log log;
    if (captured) {
        log.info = [captured](const std::string& s) { captured->info.push_back(s); };
        log.warn = [captured](const std::string& s) { captured->warn.push_back(s); };
    }
    return lfd::bake::importGltf(path, log);
}

// Import must fail with a one-line BakeError that starts with the file path and says `part`.
void expectRejected(const fs::path& path, const std::string& part)
{
    SCOPED_TRACE(path.string());
    try {
        import(path);
        ADD_FAILURE() << "accepted, expected an error containing '" << part << "'";
    } catch (const BakeError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_NE(what.find(part), std::string::npos) << what;
    }
}

// Refused with one line naming the file and `jsonPath`, whose finding is `code`
// (baker/gltf/gltf_issue_codes.h).
void expectRejected(const fs::path& path, lfd::test::IssueCode code, const std::string& jsonPath)
{
    SCOPED_TRACE(path.string());
    lfd::test::expectRefusedWith(path, code, jsonPath);
    expectRejected(path, ": " + jsonPath + ": ");
}

// Triangle t of primitive p as indices relative to the primitive's first vertex.
std::vector<uint32_t> relativeIndices(const lfd::Scene& s, size_t p)
{
    const lfd::Primitive& prim = s.primitives[p];
    uint32_t base = UINT32_MAX;
    for (uint32_t i = 0; i < prim.indexCount; ++i)
        base = std::min(base, s.indices[prim.firstIndex + i]);
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < prim.indexCount; ++i)
        out.push_back(s.indices[prim.firstIndex + i] - base);
    return out;
}

glm::vec3 geometricNormal(const lfd::Scene& s, size_t triangle)
{
    const glm::vec3& a = s.vertices.positions[s.indices[3 * triangle]];
    const glm::vec3& b = s.vertices.positions[s.indices[3 * triangle + 1]];
    const glm::vec3& c = s.vertices.positions[s.indices[3 * triangle + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// Scene-wide invariants every import must satisfy.
void expectWellFormed(const ImportedScene& r)
{
    const lfd::Scene& s = r.scene;
    const size_t n = s.vertices.size();
    EXPECT_EQ(s.vertices.normals.size(), n);
    EXPECT_TRUE(s.vertices.uvs.empty() || s.vertices.uvs.size() == n);
    EXPECT_TRUE(s.vertices.tangents.empty() || s.vertices.tangents.size() == n);
    EXPECT_EQ(s.indices.size() % 3, 0u);
    EXPECT_EQ(r.sourceTriangles, s.triangleCount());
    for (uint32_t i : s.indices)
        ASSERT_LT(i, n);
    uint32_t next = 0;
    for (const lfd::Mesh& m : s.meshes)
        for (uint32_t p = m.firstPrimitive; p < m.firstPrimitive + m.primitiveCount; ++p) {
            ASSERT_LT(p, s.primitives.size());
            EXPECT_EQ(s.primitives[p].firstIndex, next);
            next += s.primitives[p].indexCount;
        }
    EXPECT_EQ(next, s.indices.size());
    for (size_t i = 0; i < s.nodes.size(); ++i)
        EXPECT_LT(s.nodes[i].parent, int32_t(i));
    for (const glm::vec3& v : s.vertices.normals)
        EXPECT_NEAR(glm::length(v), 1.0f, 1e-4f);
    EXPECT_EQ(s.textures.size(), r.textureSources.size());
    for (size_t t = 0; t < s.textures.size(); ++t)
        EXPECT_EQ(s.textures[t].srgb, r.textureSources[t].srgb);
}

size_t instancedTriangles(const lfd::Scene& s)
{
    size_t total = 0;
    for (const lfd::Node& node : s.nodes)
        if (node.mesh >= 0) {
            const lfd::Mesh& m = s.meshes[size_t(node.mesh)];
            for (uint32_t p = m.firstPrimitive; p < m.firstPrimitive + m.primitiveCount; ++p)
                total += s.primitives[p].indexCount / 3;
        }
    return total;
}

class TempDir {
public:
    TempDir() : path_(fs::temp_directory_path() / ("lfd_gltf_import_test_" + std::to_string(::getpid())))
    {
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

} // namespace

// ---- Hand-made cases ---------------------------------------------------------------

TEST(GltfImport, StripBecomesListWithAlternatingWindingAndNoDegenerates)
{
    const ImportedScene r = import(kGltfCases / "strip.gltf");
    expectWellFormed(r);
    ASSERT_EQ(r.scene.primitives.size(), 2u);
    EXPECT_EQ(relativeIndices(r.scene, 0), (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4}));
    // [0,1,2,2,3]: the two stitching triangles are dropped, and so is the vertex only they used.
    EXPECT_EQ(relativeIndices(r.scene, 1), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(r.scene.vertices.size(), 6u + 3u);
    for (size_t t = 0; t < r.scene.triangleCount(); ++t)
        expectVec(geometricNormal(r.scene, t), {0, 0, 1});
}

TEST(GltfImport, NonIndexedFanBecomesList)
{
    const ImportedScene r = import(kGltfCases / "fan.gltf");
    expectWellFormed(r);
    EXPECT_EQ(r.scene.indices, (std::vector<uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
    for (size_t t = 0; t < r.scene.triangleCount(); ++t)
        expectVec(geometricNormal(r.scene, t), {0, 0, 1});
}

TEST(GltfImport, MissingNormalsBecomeFlatNormalsWithWarning)
{
    const ImportedScene r = import(kGltfCases / "no_normals.gltf");
    expectWellFormed(r);
    EXPECT_EQ(r.scene.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    for (int v = 0; v < 3; ++v)
        expectVec(r.scene.vertices.normals[size_t(v)], {0, 0, 1});
    for (int v = 3; v < 6; ++v)
        expectVec(r.scene.vertices.normals[size_t(v)], {0, 0, -1});
    EXPECT_TRUE(hasWarning(r, "no normals"));
}

TEST(GltfImport, HierarchyParentsFirstMatrixDecomposedOrphansDropped)
{
    const ImportedScene r = import(kGltfCases / "hierarchy.gltf");
    expectWellFormed(r);
    const lfd::Scene& s = r.scene;
    ASSERT_EQ(s.nodes.size(), 2u); // "orphan" is not in the scene
    EXPECT_EQ(s.nodes[0].name, "parent");
    EXPECT_EQ(s.nodes[0].parent, lfd::kNone);
    EXPECT_EQ(s.nodes[0].mesh, lfd::kNone);
    EXPECT_EQ(s.nodes[1].name, "child");
    EXPECT_EQ(s.nodes[1].parent, 0);
    EXPECT_EQ(s.nodes[1].mesh, 0);

    // matrix = T(1,2,3) * Rz(90 deg) * S(2,3,4)
    expectVec(s.nodes[0].translation, {1, 2, 3});
    expectVec(s.nodes[0].scale, {2, 3, 4});
    const glm::quat expected = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    EXPECT_NEAR(std::abs(glm::dot(s.nodes[0].rotation, expected)), 1.0f, 1e-5f);
    expectVec(s.nodes[1].translation, {0, 0, 5});

    // The channel on the child is remapped; the one on the orphan is ignored.
    ASSERT_EQ(s.animations.size(), 1u);
    ASSERT_EQ(s.animations[0].channels.size(), 1u);
    const lfd::AnimationChannel& c = s.animations[0].channels[0];
    EXPECT_EQ(c.node, 1u);
    EXPECT_EQ(c.interpolation, lfd::Interpolation::Step);
    EXPECT_EQ(c.times, (std::vector<float>{0.0f, 1.0f}));
    expectVec(glm::vec3(c.values[1]), {0, 0, 6});
}

TEST(GltfImport, CubicSplineLinearisedWithWarningAndRotationsNormalised)
{
    const ImportedScene r = import(kGltfCases / "cubic_spline.gltf");
    expectWellFormed(r);
    ASSERT_EQ(r.scene.animations.size(), 1u);
    const std::vector<lfd::AnimationChannel>& ch = r.scene.animations[0].channels;
    ASSERT_EQ(ch.size(), 2u);
    EXPECT_EQ(ch[0].path, lfd::AnimationPath::Translation);
    EXPECT_EQ(ch[0].interpolation, lfd::Interpolation::Linear);
    EXPECT_EQ(ch[0].times, (std::vector<float>{0.0f, 2.0f}));
    ASSERT_EQ(ch[0].values.size(), 2u);
    expectVec(glm::vec3(ch[0].values[0]), {1, 2, 3});
    expectVec(glm::vec3(ch[0].values[1]), {4, 5, 6});
    EXPECT_TRUE(hasWarning(r, "CUBICSPLINE"));

    EXPECT_EQ(ch[1].path, lfd::AnimationPath::Rotation);
    EXPECT_EQ(ch[1].values[0], glm::vec4(0, 0, 0, 1)); // xyzw
    EXPECT_EQ(ch[1].values[1], glm::vec4(0, 0, 1, 0));
}

TEST(GltfImport, LinesPrimitiveSkippedWithWarningNamingIt)
{
    Captured log;
    const ImportedScene r = import(kGltfCases / "lines_and_triangles.gltf", &log);
    expectWellFormed(r);
    EXPECT_EQ(r.scene.triangleCount(), 1u);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].primitiveCount, 1u);
    EXPECT_TRUE(hasWarning(r, "meshes[0].primitives[0] ('mixed') is LINES, not triangles: skipped"));
    EXPECT_EQ(log.warn, r.warnings); // warnings go to the log too
    ASSERT_FALSE(log.info.empty());
    EXPECT_NE(log.info.back().find("1 triangles"), std::string::npos) << log.info.back();
}

TEST(GltfImport, UnusedStreamsAreNotStored)
{
    // uvs and tangents given, but no material has a texture.
    const ImportedScene r = import(kGltfCases / "unused_streams.gltf");
    expectWellFormed(r);
    EXPECT_TRUE(r.scene.vertices.uvs.empty());
    EXPECT_TRUE(r.scene.vertices.tangents.empty());
    EXPECT_EQ(r.scene.vertices.mask(), lfd::kStreamPosition | lfd::kStreamNormal);
    EXPECT_TRUE(hasWarning(r, "COLOR_n"));
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_FLOAT_EQ(r.scene.materials[0].baseColorFactor.r, 0.5f);
    EXPECT_EQ(r.scene.primitives[0].material, 0);
}

TEST(GltfImport, NormalMapGivesUvsTangentsAndSeparateColourSpaces)
{
    const ImportedScene r = import(kGltfCases / "normal_map.gltf");
    expectWellFormed(r);
    const lfd::Scene& s = r.scene;
    EXPECT_EQ(s.vertices.mask(), lfd::kStreamPosition | lfd::kStreamNormal | lfd::kStreamUv | lfd::kStreamTangent);

    // One image used as sRGB colour and as linear data: two textures; occlusion shares
    // the linear one.
    ASSERT_EQ(s.textures.size(), 2u);
    ASSERT_EQ(s.materials.size(), 2u);
    const lfd::Material& m = s.materials[0];
    ASSERT_NE(m.baseColorTexture, lfd::kNone);
    ASSERT_NE(m.normalTexture, lfd::kNone);
    EXPECT_TRUE(s.textures[size_t(m.baseColorTexture)].srgb);
    EXPECT_FALSE(s.textures[size_t(m.normalTexture)].srgb);
    EXPECT_NE(m.baseColorTexture, m.normalTexture);
    EXPECT_EQ(m.occlusionTexture, m.normalTexture);
    EXPECT_EQ(m.metallicRoughnessTexture, lfd::kNone);
    EXPECT_EQ(m.emissiveTexture, lfd::kNone);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
    EXPECT_FLOAT_EQ(m.metallicFactor, 0.25f);
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.75f);
    EXPECT_EQ(m.alphaMode, lfd::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    expectVec(s.materials[1].emissiveFactor, {1.0f, 0.5f, 0.25f});

    // Embedded (data URI) image: encoded PNG bytes, never decoded.
    for (const lfd::bake::TextureSource& src : r.textureSources) {
        EXPECT_TRUE(src.file.empty());
        ASSERT_GT(src.encoded.size(), 8u);
        EXPECT_EQ(src.encoded[1], 'P');
        EXPECT_EQ(src.mimeType, "image/png");
    }

    // Primitive 0: generated tangent along dP/du = +x, w = -1 (bitangent towards -v).
    const uint32_t v0 = s.indices[s.primitives[0].firstIndex];
    for (uint32_t v = v0; v < v0 + 3; ++v) {
        expectVec(glm::vec3(s.vertices.tangents[v]), {1, 0, 0});
        EXPECT_EQ(s.vertices.tangents[v].w, -1.0f);
    }
    EXPECT_EQ(s.vertices.uvs[v0 + 1], glm::vec2(1, 0));
    EXPECT_TRUE(hasWarning(r, "generated tangents"));
    // Primitive 1 has no uvs: zeros in the scene-wide stream.
    const uint32_t v1 = s.indices[s.primitives[1].firstIndex];
    EXPECT_EQ(s.vertices.uvs[v1], glm::vec2(0));
    EXPECT_EQ(s.primitives[1].material, 1);
}

TEST(GltfImport, InterleavedNormalizedAndSparseAccessors)
{
    const ImportedScene r = import(kGltfCases / "interleaved_sparse.gltf");
    expectWellFormed(r);
    const lfd::VertexStreams& v = r.scene.vertices;
    ASSERT_EQ(v.size(), 3u);
    expectVec(v.positions[1], {1, 0, 0});
    expectVec(v.positions[2], {0, 2, 0}); // sparse substitution
    EXPECT_EQ(v.uvs[0], glm::vec2(0, 0));
    EXPECT_EQ(v.uvs[1], glm::vec2(1, 0)); // normalized ushort 65535
    EXPECT_EQ(v.uvs[2], glm::vec2(0, 1));
    EXPECT_EQ(r.scene.indices, (std::vector<uint32_t>{0, 1, 2}));
}

// make_cases.py materials_and_lights(): the three extensions, required.
TEST(GltfImport, TextureTransformUnlitAndLightsOfAHandMadeFile)
{
    const ImportedScene r = import(kGltfCases / "materials_and_lights.gltf");
    expectWellFormed(r);
    const lfd::Scene& s = r.scene;
    ASSERT_EQ(s.materials.size(), 2u);
    const lfd::Material& tiled = s.materials[0];
    EXPECT_FALSE(tiled.unlit);
    const lfd::TextureTransform& base = tiled.transform(lfd::TextureSlot::BaseColor);
    EXPECT_NEAR(base.areaScale(), 8.0f, 1e-5f);
    EXPECT_EQ(base.offset, glm::vec2(0.5f, 0.25f));
    EXPECT_NEAR(base.linear[0][0], 4.0f * std::cos(0.5f), 1e-6f);
    EXPECT_NEAR(base.linear[1][0], 2.0f * std::sin(0.5f), 1e-6f);
    EXPECT_NE(tiled.normalTexture, lfd::kNone); // texCoord 1 overridden to 0
    EXPECT_EQ(tiled.transform(lfd::TextureSlot::Normal).offset, glm::vec2(0.0f, 0.5f));
    EXPECT_TRUE(s.materials[1].unlit);
    EXPECT_TRUE(s.materials[1].transform(lfd::TextureSlot::BaseColor).identity());

    // Nodes: quad, sun node, bulb node, spot left, spot right (the unused sun's node is out).
    ASSERT_EQ(s.nodes.size(), 5u);
    ASSERT_EQ(s.lights.size(), 4u);
    const char* nodes[] = {"sun node", "bulb node", "spot left", "spot right"};
    const lfd::LightType types[] = {lfd::LightType::Directional, lfd::LightType::Point, lfd::LightType::Spot,
                                    lfd::LightType::Spot};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(s.nodes[s.lights[i].node].name, nodes[i]);
        EXPECT_EQ(s.lights[i].type, types[i]);
    }
    EXPECT_EQ(s.lights[1].name, "light 1");
    EXPECT_EQ(s.lights[1].range, 4.0f);
    EXPECT_EQ(s.lights[3].innerConeAngle, 0.2f);
    EXPECT_EQ(s.lights[3].outerConeAngle, 0.6f);
    EXPECT_EQ(s.nodes[s.lights[0].node].parent, 0);
    // The dropped light and the generated tangents, nothing about the extensions.
    EXPECT_EQ(r.warnings.size(), 2u);
    EXPECT_TRUE(hasWarning(r, "nodes[5].extensions.KHR_lights_punctual.light: light 0 is on a node outside the "
                              "imported scene: dropped"));
    EXPECT_TRUE(hasWarning(r, "has a normal map but no TANGENT"));
}

TEST(GltfImport, BrokenHandMadeFilesAreRejected)
{
    using lfd::test::IssueCode;
    expectRejected(kGltfCases / "sheared_matrix.gltf", IssueCode::NODE_MATRIX_NON_TRS, "nodes[0].matrix");
    expectRejected(kGltfCases / "recursive_nodes.gltf", IssueCode::NODE_LOOP, "nodes[0]");
    expectRejected(kGltfCases / "accessor_out_of_bounds.gltf", IssueCode::ACCESSOR_TOO_LONG, "accessors[0]");
    expectRejected(kGltfCases / "index_out_of_range.gltf", IssueCode::ACCESSOR_INDEX_OOB, "meshes[0].primitives[0].indices");
    expectRejected(kGltfCases / "basisu_required.gltf", "requires unsupported extension KHR_texture_basisu");
    expectRejected(kGltfCases / "missing_bin.gltf", "missing_bin_does_not_exist.bin");
    expectRejected(kGltfCases / "malformed.gltf", "parse error");
    expectRejected(kGltfCases / "bad_key_times.gltf", IssueCode::ANIMATION_KEY_TIMES_NOT_INCREASING, "accessors[2]");
    expectRejected(kGltfCases / "does_not_exist.gltf", "file not found");
    expectRejected(kGltfCases, "is a directory");
}

TEST(GltfImport, AccessorWithoutBufferViewCannotAllocateGigabytes)
{
    // Without a bufferView an accessor is zeros (plus sparse patches): no buffer bounds its
    // count. A 232-byte file declaring 2^28 - 1 POSITIONs made the importer allocate over
    // 3 GiB and fail with std::bad_alloc; more than 256 MiB of zeros is refused by name.
    TempDir dir;
    auto scene = [](uint64_t count) {
        return nlohmann::json{{"asset", {{"version", "2.0"}}},
                              {"accessors", {{{"componentType", 5126},
                                              {"count", count},
                                              {"type", "VEC3"},
                                              {"min", {0, 0, 0}},
                                              {"max", {0, 0, 0}}}}},
                              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                              {"nodes", {{{"mesh", 0}}}},
                              {"scenes", {{{"nodes", {0}}}}}};
    };
    std::ofstream(dir.path() / "bomb.gltf") << scene((uint64_t(1) << 28) - 1).dump();
    expectRejected(dir.path() / "bomb.gltf",
                   "accessors[0]: 268435455 elements without a bufferView would need 3071 MiB of zeros "
                   "(more than 256 MiB)");
    // At the limit it imports: all-zero positions, degenerate but valid.
    std::ofstream(dir.path() / "zeros.gltf") << scene(3 * 1024).dump();
    const ImportedScene r = import(dir.path() / "zeros.gltf");
    EXPECT_EQ(r.sourceTriangles, 1024u);
}

TEST(GltfImport, BufferStartingWithPngSignatureStillLoads)
{
    // The importer hands tinygltf only the signature of files that look like images;
    // a .bin that starts with an embedded PNG must still load in full (retry path).
    TempDir dir;
    std::vector<uint8_t> bin = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 1, 2, 3, 4, 5, 6, 7, 8};
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    bin.insert(bin.end(), reinterpret_cast<const uint8_t*>(tri), reinterpret_cast<const uint8_t*>(tri) + sizeof tri);
    std::ofstream(dir.path() / "data.bin", std::ios::binary).write(reinterpret_cast<const char*>(bin.data()),
                                                                  std::streamsize(bin.size()));
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"uri", "data.bin"}, {"byteLength", bin.size()}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 16}},
                         {{"buffer", 0}, {"byteOffset", 16}, {"byteLength", 36}}}},
        {"accessors",
         {{{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}},
        {"images", {{{"bufferView", 0}, {"mimeType", "image/png"}}}},
        {"textures", {{{"source", 0}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}}};
    std::ofstream(dir.path() / "scene.gltf") << doc.dump();

    const ImportedScene r = import(dir.path() / "scene.gltf");
    expectWellFormed(r);
    EXPECT_EQ(r.scene.triangleCount(), 1u);
    expectVec(r.scene.vertices.positions[1], {1, 0, 0});
    ASSERT_EQ(r.textureSources.size(), 1u);
    EXPECT_EQ(r.textureSources[0].encoded, std::vector<uint8_t>(bin.begin(), bin.begin() + 16));
    EXPECT_EQ(r.scene.vertices.uvs.size(), 3u); // textured material, no TEXCOORD_0: zeros
    EXPECT_TRUE(hasWarning(r, "meshes[0].primitives[0].material: materials[0].pbrMetallicRoughness.baseColorTexture "
                              "uses TEXCOORD_0, which the primitive does not have: uvs set to zero"));
}

// ---- Debian assimp-testmodels -------------------------------------------------------

class AssimpModels : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (!fs::is_directory(kAssimp))
            LFD_SKIP_OR_FAIL(kAssimp << " absent (install Debian package assimp-testmodels)");
    }
};

TEST_F(AssimpModels, ValidFilesImportWithKnownCounts)
{
    struct Case {
        const char* file;
        size_t triangles;
        size_t vertices;
        size_t textures;
        const char* warning; // expected warning, or nullptr
    };
    // Counts cross-checked with an independent Python reader of the same files
    // (vertices: those the triangles use; one per corner where normals are generated).
    const Case cases[] = {
        {"BoxTextured-glTF/BoxTextured.gltf", 12, 24, 1, nullptr},
        {"BoxTextured-glTF-Binary/BoxTextured.glb", 12, 24, 1, nullptr},
        {"BoxTextured-glTF-Embedded/BoxTextured.gltf", 12, 24, 1, nullptr},
        {"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12, 24, 1,
         "KHR_materials_pbrSpecularGlossiness"},
        {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12, 24, 0, "invalid normals"},
        {"BoxTexcoords-glTF/boxTexcoords.gltf", 12, 24, 1, "TEXCOORD_1"},
        {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 75730, 55843, 0, nullptr},
        {"ClearCoat-glTF/ClearCoatTest.gltf", 37116, 20106, 5, "KHR_materials_clearcoat"},
        {"cameras/Cameras.gltf", 2, 6, 0, "no normals"},
        {"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12, 24, 0, nullptr}, // morphed: skin_bake_test
        {"simple_skin/simple_skin.gltf", 8, 24, 0, "no normals"}, // skinned: skin_bake_test
        {"issue_3269/texcoord_crash.gltf", 10, 20, 1, "uses TEXCOORD_0, which the primitive does not have"},
        {"textureTransform/TextureTransformTest.gltf", 18, 54, 5, "no normals"}, // transforms: next test
        // Schema violations a sensible bake survives: warnings naming the JSON path (the
        // rest of each file is a valid box). The refused ones are in the next test.
        {"wrongTypes/badExtension.gltf", 12, 24, 1,
         "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform: expected an object"},
        {"wrongTypes/badString.gltf", 12, 24, 1, "scenes[0].name: expected a string, got 42: name ignored"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        const ImportedScene r = import(kAssimp / c.file);
        expectWellFormed(r);
        EXPECT_EQ(r.sourceTriangles, c.triangles);
        EXPECT_EQ(r.scene.vertices.size(), c.vertices);
        EXPECT_EQ(r.scene.textures.size(), c.textures);
        if (c.warning)
            EXPECT_TRUE(hasWarning(r, c.warning));
        else
            EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    }
}

// The Khronos TextureTransformTest model: offset, rotation and scale per material.
TEST_F(AssimpModels, TextureTransformTestModel)
{
    const ImportedScene r = import(kAssimp / "textureTransform/TextureTransformTest.gltf");
    std::map<std::string, lfd::TextureTransform> byName;
    for (const lfd::Material& m : r.scene.materials)
        byName[m.name] = m.transform(lfd::TextureSlot::BaseColor);
    ASSERT_EQ(byName.size(), 9u);
    EXPECT_EQ(byName["Offset U"].offset, glm::vec2(0.5f, 0.0f));
    EXPECT_EQ(byName["Offset U"].linear, glm::mat2(1.0f));
    EXPECT_EQ(byName["Offset UV"].offset, glm::vec2(0.5f, 0.5f));
    EXPECT_NEAR(byName["Rotation"].linear[1][0], std::sin(0.39269908f), 1e-6f); // u' = u cos r + v sin r
    EXPECT_NEAR(byName["Rotation"].linear[0][1], -std::sin(0.39269908f), 1e-6f);
    EXPECT_NEAR(byName["Scale"].areaScale(), 2.25f, 1e-6f);
    EXPECT_EQ(byName["All"].offset, glm::vec2(-0.2f, -0.1f));
    EXPECT_NEAR(byName["All"].areaScale(), 2.25f, 1e-5f);
    for (const char* plain : {"Correct", "NotSupported", "Error"})
        EXPECT_TRUE(byName[plain].identity()) << plain;
    EXPECT_FALSE(hasWarning(r, "KHR_texture_transform"));
}

TEST_F(AssimpModels, TextureSourcesOfExternalEmbeddedAndBinaryFiles)
{
    const ImportedScene ext = import(kAssimp / "BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_EQ(ext.textureSources.size(), 1u);
    EXPECT_EQ(ext.textureSources[0].file, kAssimp / "BoxTextured-glTF/CesiumLogoFlat.png");
    EXPECT_TRUE(ext.textureSources[0].encoded.empty());
    EXPECT_EQ(ext.textureSources[0].mimeType, "image/png");
    EXPECT_TRUE(ext.textureSources[0].srgb);
    EXPECT_EQ(ext.scene.vertices.mask(), lfd::kStreamPosition | lfd::kStreamNormal | lfd::kStreamUv);

    const auto fileSize = fs::file_size(kAssimp / "BoxTextured-glTF/CesiumLogoFlat.png");
    for (const char* file : {"BoxTextured-glTF-Embedded/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
        SCOPED_TRACE(file);
        const ImportedScene r = import(kAssimp / file);
        ASSERT_EQ(r.textureSources.size(), 1u);
        EXPECT_TRUE(r.textureSources[0].file.empty());
        EXPECT_EQ(r.textureSources[0].encoded.size(), fileSize); // the same PNG, still encoded
        EXPECT_EQ(r.textureSources[0].mimeType, "image/png");
    }
}

TEST_F(AssimpModels, PrimitiveModesOfAssetGenerator)
{
    // Every triangle mode (list/strip/fan, with and without indices of each width) is the
    // same unit quad facing +z; points and lines alone leave nothing to import.
    const fs::path dir = kAssimp / "glTF-Asset-Generator/Mesh_PrimitiveMode";
    for (int i = 0; i <= 15; ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "Mesh_PrimitiveMode_%02d.gltf", i);
        SCOPED_TRACE(name);
        const bool triangles = (i >= 4 && i <= 6) || i >= 11;
        if (!triangles) {
            expectRejected(dir / name, "no triangles");
            continue;
        }
        const ImportedScene r = import(dir / name);
        expectWellFormed(r);
        ASSERT_EQ(r.scene.triangleCount(), 2u);
        float area = 0.0f;
        for (size_t t = 0; t < 2; ++t) {
            expectVec(geometricNormal(r.scene, t), {0, 0, 1});
            const glm::vec3* p = r.scene.vertices.positions.data();
            const uint32_t* idx = &r.scene.indices[3 * t];
            area += 0.5f * glm::length(glm::cross(p[idx[1]] - p[idx[0]], p[idx[2]] - p[idx[0]]));
        }
        EXPECT_NEAR(area, 1.0f, 1e-5f);
    }
}

TEST_F(AssimpModels, BrokenFilesAreRejectedWithOneLineErrors)
{
    using lfd::test::IssueCode;
    // Findings of the glTF checks: by code and JSON path.
    const std::tuple<const char*, IssueCode, const char*> findings[] = {
        {"IndexOutOfRange/IndexOutOfRange.gltf", IssueCode::ACCESSOR_INDEX_OOB, "meshes[0].primitives[0].indices"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", IssueCode::ACCESSOR_INDEX_PRIMITIVE_RESTART,
         "meshes[0].primitives[0].indices"},
        {"MissingBin/BoxTextured.gltf", IssueCode::RESOURCE_NOT_FOUND, "buffers[0].uri"},
        {"RecursiveNodes/RecursiveNodes.gltf", IssueCode::NODE_LOOP, "nodes[0]"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", IssueCode::ACCESSOR_NON_FINITE, "accessors[2]"},
        {"TestNoRootNode/NoScene.gltf", IssueCode::UNRESOLVED_REFERENCE, "scene"},
        // Its truncated POSITION accessors lack the min and max glTF requires of POSITION
        // (three overrunning bufferViews nothing reads are warnings).
        {"IncorrectVertexArrays/Cube.gltf", IssueCode::ACCESSOR_BOUNDS_MISSING, "accessors[6]"},
        // Schema violations tinygltf would drop silently, refused with the JSON path.
        {"wrongTypes/badArray.gltf", IssueCode::TYPE_MISMATCH, "meshes[0].primitives"},
        {"wrongTypes/badNumber.gltf", IssueCode::TYPE_MISMATCH, "materials[0].normalTexture.scale"},
        {"wrongTypes/badObject.gltf", IssueCode::TYPE_MISMATCH, "materials[0].pbrMetallicRoughness"},
        {"wrongTypes/badUint.gltf", IssueCode::UNRESOLVED_REFERENCE,
         "materials[0].pbrMetallicRoughness.baseColorTexture.index"},
        {"SchemaFailures/sceneWrongType.gltf", IssueCode::TYPE_MISMATCH, "scene"},
    };
    for (const auto& [file, code, jsonPath] : findings)
        expectRejected(kAssimp / file, code, jsonPath);
    // Refusals of the importer itself (no issue code).
    const std::pair<const char*, const char*> cases[] = {
        {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "requires unsupported extension KHR_technique_webgl"},
        {"TestNoRootNode/SceneWithoutNodes.gltf", "no triangles"},
    };
    for (const auto& [file, part] : cases)
        expectRejected(kAssimp / file, part);
}

// ---- Third-party scenes (../shared/scenes) ----------------------------------------

class SharedScenes : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (!fs::is_directory(kShared))
            LFD_SKIP_OR_FAIL(kShared << " absent: third-party scene tests skipped");
    }
};

TEST_F(SharedScenes, DamagedHelmet)
{
    const ImportedScene r = import(kShared / "DamagedHelmet/DamagedHelmet.gltf");
    expectWellFormed(r);
    EXPECT_EQ(r.sourceTriangles, 15452u);
    EXPECT_EQ(r.scene.textures.size(), 5u);
    size_t srgb = 0;
    for (const lfd::Texture& t : r.scene.textures)
        srgb += t.srgb;
    EXPECT_EQ(srgb, 2u); // albedo and emissive
    for (const lfd::bake::TextureSource& s : r.textureSources) {
        EXPECT_TRUE(fs::is_regular_file(s.file)) << s.file;
        EXPECT_EQ(s.mimeType, "image/jpeg");
    }
    EXPECT_EQ(r.scene.vertices.tangents.size(), r.scene.vertices.size());
    EXPECT_TRUE(hasWarning(r, "generated tangents"));
}

TEST_F(SharedScenes, BoomBoxUsesMetallicRoughnessAndAuthoredTangents)
{
    const ImportedScene r = import(kShared / "BoomBox/BoomBox.gltf");
    expectWellFormed(r);
    EXPECT_EQ(r.sourceTriangles, 6036u);
    EXPECT_EQ(r.scene.textures.size(), 5u); // the two specular-glossiness images are unused
    EXPECT_TRUE(hasWarning(r, "KHR_materials_pbrSpecularGlossiness"));
    EXPECT_FALSE(hasWarning(r, "generated tangents"));
    EXPECT_EQ(r.scene.vertices.tangents.size(), r.scene.vertices.size());
}

TEST_F(SharedScenes, GeneratedTangentsMatchBoomBoxAuthoredOnes)
{
    // Same scene with TANGENT removed (images and buffer linked, not copied).
    TempDir dir;
    const fs::path src = kShared / "BoomBox";
    for (const auto& entry : fs::directory_iterator(src))
        if (entry.path().extension() != ".gltf")
            fs::create_symlink(entry.path(), dir.path() / entry.path().filename());
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(src / "BoomBox.gltf"));
    doc["meshes"][0]["primitives"][0]["attributes"].erase("TANGENT");
    std::ofstream(dir.path() / "BoomBox.gltf") << doc.dump();

    const ImportedScene authored = import(src / "BoomBox.gltf");
    const ImportedScene generated = import(dir.path() / "BoomBox.gltf");
    expectWellFormed(generated);
    EXPECT_TRUE(hasWarning(generated, "generated tangents"));
    const auto& a = authored.scene.vertices.tangents;
    const auto& g = generated.scene.vertices.tangents;
    ASSERT_EQ(a.size(), g.size());
    size_t sameHandedness = 0, sameDirection = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        sameHandedness += a[i].w == g[i].w;
        sameDirection += glm::dot(glm::vec3(a[i]), glm::vec3(g[i])) > 0.9f;
    }
    EXPECT_EQ(sameHandedness, a.size());
    EXPECT_GT(double(sameDirection), 0.99 * double(a.size()));
}

TEST_F(SharedScenes, CesiumMilkTruckAnimationAndInstancedWheels)
{
    const ImportedScene r = import(kShared / "CesiumMilkTruck/CesiumMilkTruck.gltf");
    expectWellFormed(r);
    const lfd::Scene& s = r.scene;
    EXPECT_EQ(r.sourceTriangles, 2856u);       // each mesh stored once
    EXPECT_EQ(instancedTriangles(s), 3624u);   // the wheel mesh drawn twice
    EXPECT_EQ(s.textures.size(), 1u);          // two glTF textures, one image, both sRGB
    ASSERT_EQ(s.meshes.size(), 2u);

    size_t wheelUsers = 0;
    int32_t wheel = lfd::kNone;
    for (size_t m = 0; m < s.meshes.size(); ++m)
        if (s.meshes[m].name == "Wheels")
            wheel = int32_t(m);
    ASSERT_NE(wheel, lfd::kNone);
    std::set<uint32_t> wheelNodes;
    for (size_t n = 0; n < s.nodes.size(); ++n)
        if (s.nodes[n].mesh == wheel) {
            ++wheelUsers;
            wheelNodes.insert(uint32_t(n));
        }
    EXPECT_EQ(wheelUsers, 2u);

    // KHR_lights_punctual: the head light (a child of the camera node) and the key light.
    ASSERT_EQ(s.lights.size(), 2u);
    for (const lfd::Light& l : s.lights) {
        EXPECT_EQ(l.type, lfd::LightType::Directional);
        EXPECT_EQ(l.color, glm::vec3(1.0f, float(0.9333333333333333), float(0.8666666666666667)));
    }
    EXPECT_EQ(s.lights[0].name, "headLight");
    EXPECT_EQ(s.nodes[s.lights[0].node].name, "headLightNode");
    EXPECT_EQ(s.lights[0].intensity, 0.25f);
    EXPECT_EQ(s.lights[1].name, "keyLight");
    EXPECT_EQ(s.nodes[s.lights[1].node].name, "keyLightNode");
    EXPECT_FALSE(hasWarning(r, "KHR_lights_punctual"));

    ASSERT_EQ(s.animations.size(), 1u);
    ASSERT_EQ(s.animations[0].channels.size(), 2u);
    for (const lfd::AnimationChannel& c : s.animations[0].channels) {
        EXPECT_EQ(c.path, lfd::AnimationPath::Rotation);
        EXPECT_TRUE(wheelNodes.count(c.node)) << "channel should spin a wheel node";
        EXPECT_GT(c.times.size(), 1u);
        for (const glm::vec4& q : c.values)
            EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    }
}
