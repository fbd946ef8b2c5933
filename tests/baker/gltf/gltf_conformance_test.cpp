// glTF conformance (baker/gltf/gltf_load.h): one small file per defect class the baker must name
// with its issue code and JSON path (refused, or baked with a warning, by the specification's
// MUST or SHOULD), and the valid files a lenient loader used to refuse. Each file is written here:
// a unit triangle with unit normals and indices, broken in one place.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "gltf_findings.h"
#include "gltf_test_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>

namespace fs = std::filesystem;
using nlohmann::json;
using lfd::bake::BakeError;
using lfd::bake::ImportedScene;

namespace {

using lfd::test::append;
using lfd::test::base64;
using lfd::test::Chunk;
using lfd::test::glb;
using lfd::test::IssueCode;
using lfd::test::jsonChunk;
using lfd::test::kBin;
using lfd::test::kJson;

// The unit triangle's bytes: POSITION (0, 36 bytes), NORMAL (36, 36), indices (72, 6 + 2
// padding), key times (80, 8), translations (88, 24).
std::vector<uint8_t> triangleBytes(float normalZ = 1.0f, uint16_t lastIndex = 2)
{
    std::vector<uint8_t> bin;
    append<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
    append<float>(bin, {0, 0, normalZ, 0, 0, normalZ, 0, 0, normalZ});
    append<uint16_t>(bin, {0, 1, lastIndex, 0});
    append<float>(bin, {0, 1});
    append<float>(bin, {0, 0, 0, 0, 0, 1});
    return bin;
}

json dataUri(const std::vector<uint8_t>& bin)
{
    return "data:application/octet-stream;base64," + base64(bin);
}

// A valid scene: one node drawing the triangle; `animated` adds a translation animation.
json triangleScene(const std::vector<uint8_t>& bin = triangleBytes(), bool animated = false)
{
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 6}, {"target", 34963}}}},
        {"buffers", {{{"byteLength", bin.size()}, {"uri", dataUri(bin)}}}},
    };
    if (animated) {
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 8}});
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 88}, {"byteLength", 24}});
        doc["accessors"].push_back(
            {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {1}}});
        doc["accessors"].push_back({{"bufferView", 4}, {"componentType", 5126}, {"count", 2}, {"type", "VEC3"}});
        doc["animations"] = {{{"samplers", {{{"input", 3}, {"output", 4}}}},
                              {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
    }
    return doc;
}

// The triangle scene as a GLB whose buffers[0] is the BIN chunk.
std::vector<uint8_t> triangleGlb(std::vector<uint8_t> bin = triangleBytes())
{
    json doc = triangleScene(bin);
    doc["buffers"][0].erase("uri");
    return glb({jsonChunk(doc), {kBin, bin, 0}});
}

class GltfConformance : public lfd::test::GltfCaseFiles {
protected:
    GltfConformance() : GltfCaseFiles("lfd_gltf_conformance_test") {}

    static ImportedScene import(const fs::path& path) { return lfd::bake::importGltf(path, lfd::bake::Log{}); }

    // Refused with one line, "<file>: <jsonPath>: ...", whose finding is `code`.
    static void expectRefused(const fs::path& path, IssueCode code, const std::string& jsonPath)
    {
        lfd::test::expectRefusedWith(path, code, jsonPath);
        try {
            import(path);
            ADD_FAILURE() << "accepted, expected: " << jsonPath;
        } catch (const BakeError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path.string() + ": " + jsonPath + ": ", 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }

    // Baked, with a warning `code` at `jsonPath`.
    static ImportedScene expectWarned(const fs::path& path, IssueCode code, const std::string& jsonPath)
    {
        lfd::test::expectWarningWith(path, code, jsonPath);
        return expectWarned(path, jsonPath + ": ");
    }

    // Baked, with a warning that starts with `expected` (the importer's own warnings,
    // which have no issue code).
    static ImportedScene expectWarned(const fs::path& path, const std::string& expected)
    {
        ImportedScene r;
        EXPECT_NO_THROW(r = import(path));
        bool found = false;
        for (const std::string& w : r.warnings)
            found = found || w.rfind(expected, 0) == 0;
        EXPECT_TRUE(found) << "expected warning: " << expected << "\nwarnings:"
                           << [&] {
                                  std::string all;
                                  for (const std::string& w : r.warnings)
                                      all += "\n  " + w;
                                  return all;
                              }();
        return r;
    }
};

// ---- Defects in the data the baker reads: one file per class ----------------------

TEST_F(GltfConformance, TheValidTriangleBakesWithoutWarnings)
{
    for (bool animated : {false, true}) {
        const ImportedScene r = import(write(triangleScene(triangleBytes(), animated)));
        EXPECT_EQ(r.sourceTriangles, 1u);
        EXPECT_EQ(r.scene.animations.size(), animated ? 1u : 0u);
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    }
    const ImportedScene r = import(writeBytes(triangleGlb(), ".glb"));
    EXPECT_EQ(r.sourceTriangles, 1u);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST_F(GltfConformance, NonUnitNormalsAreNamedAndRenormalised)
{
    const ImportedScene r = expectWarned(write(triangleScene(triangleBytes(2.0f))), IssueCode::ACCESSOR_NON_UNIT, "accessors[1]");
    ASSERT_EQ(r.scene.vertices.normals.size(), 3u);
    EXPECT_FLOAT_EQ(r.scene.vertices.normals[0].z, 1.0f);
}

TEST_F(GltfConformance, IndexDataWithThePrimitiveRestartValueIsRefused)
{
    expectRefused(write(triangleScene(triangleBytes(1.0f, 0xFFFF))), IssueCode::ACCESSOR_INDEX_PRIMITIVE_RESTART, "meshes[0].primitives[0].indices");
}

TEST_F(GltfConformance, IndexOutOfRangeIsRefused)
{
    expectRefused(write(triangleScene(triangleBytes(1.0f, 3))), IssueCode::ACCESSOR_INDEX_OOB, "meshes[0].primitives[0].indices");
}

TEST_F(GltfConformance, IndexViewWithAByteStrideIsRefused)
{
    json doc = triangleScene();
    doc["bufferViews"][2]["byteStride"] = 4;
    doc["bufferViews"][2]["byteLength"] = 8;
    expectRefused(write(doc), IssueCode::BUFFER_VIEW_STRIDE_ON_INDEX_DATA, "bufferViews[2].byteStride");
}

TEST_F(GltfConformance, VertexAccessorsSharingAViewWithoutByteStrideAreRefused)
{
    json doc = triangleScene();
    doc["bufferViews"][0]["byteLength"] = 72;
    doc["accessors"][1]["bufferView"] = 0;
    doc["accessors"][1]["byteOffset"] = 36;
    expectRefused(write(doc), IssueCode::BUFFER_VIEW_SHARED_WITHOUT_STRIDE, "bufferViews[0]");
}

TEST_F(GltfConformance, ByteStrideLongerThanItsViewIsRefused)
{
    json doc = triangleScene();
    doc["bufferViews"][1]["byteStride"] = 40;
    expectRefused(write(doc), IssueCode::BUFFER_VIEW_STRIDE_EXCEEDS_LENGTH, "bufferViews[1].byteStride");
}

TEST_F(GltfConformance, ByteStrideNotAMultipleOf4IsRefused)
{
    json doc = triangleScene();
    doc["bufferViews"][1]["byteStride"] = 14;
    expectRefused(write(doc), IssueCode::BUFFER_VIEW_INVALID_BYTE_STRIDE, "bufferViews[1].byteStride");
}

TEST_F(GltfConformance, ByteOffsetWithoutBufferViewIsRefused)
{
    json doc = triangleScene();
    doc["accessors"][1].erase("bufferView");
    doc["accessors"][1]["byteOffset"] = 4;
    expectRefused(write(doc), IssueCode::ACCESSOR_OFFSET_WITHOUT_BUFFER_VIEW, "accessors[1].byteOffset");
}

TEST_F(GltfConformance, AccessorOverrunningItsViewIsRefused)
{
    json doc = triangleScene();
    doc["accessors"][0]["count"] = 4;
    doc["accessors"][1]["count"] = 4;
    expectRefused(write(doc), IssueCode::ACCESSOR_TOO_LONG, "accessors[0]");
}

TEST_F(GltfConformance, PositionWithoutMinAndMaxIsRefused)
{
    json doc = triangleScene();
    doc["accessors"][0].erase("min");
    expectRefused(write(doc), IssueCode::ACCESSOR_BOUNDS_MISSING, "accessors[0]");
}

TEST_F(GltfConformance, TwoChannelsTargetingOnePropertyAreRefused)
{
    json doc = triangleScene(triangleBytes(), true);
    doc["animations"][0]["channels"].push_back(doc["animations"][0]["channels"][0]);
    expectRefused(write(doc), IssueCode::ANIMATION_DUPLICATE_TARGETS, "animations[0].channels[1].target");
}

TEST_F(GltfConformance, AnimatedNodeWithAMatrixIsRefused)
{
    json doc = triangleScene(triangleBytes(), true);
    doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    expectRefused(write(doc), IssueCode::ANIMATION_CHANNEL_TARGET_NODE_MATRIX, "animations[0].channels[0].target.node");
}

TEST_F(GltfConformance, KeyTimesNotStoredAsFloatAreRefused)
{
    json doc = triangleScene(triangleBytes(), true);
    doc["accessors"][3] = {{"bufferView", 3}, {"componentType", 5123}, {"count", 2}, {"type", "SCALAR"},
                           {"min", {0}}, {"max", {1}}};
    expectRefused(write(doc), IssueCode::ACCESSOR_WRONG_FORMAT, "animations[0].samplers[0].input");
}

TEST_F(GltfConformance, KeyTimesThatDoNotIncreaseAreRefused)
{
    std::vector<uint8_t> bin = triangleBytes();
    std::memset(bin.data() + 84, 0, 4); // times 0, 0
    json doc = triangleScene(bin, true);
    doc["accessors"][3]["max"] = {0};
    expectRefused(write(doc), IssueCode::ANIMATION_KEY_TIMES_NOT_INCREASING, "accessors[3]");
}

TEST_F(GltfConformance, SceneListingANonRootNodeIsRefused)
{
    json doc = triangleScene();
    doc["nodes"].push_back({{"children", {0}}});
    doc["scenes"][0]["nodes"] = {1, 0};
    expectRefused(write(doc), IssueCode::SCENE_NON_ROOT_NODE, "scenes[0].nodes[1]");
}

TEST_F(GltfConformance, NodeCycleIsRefused)
{
    json doc = triangleScene();
    doc["nodes"][0]["children"] = {1};
    doc["nodes"].push_back({{"children", {0}}});
    expectRefused(write(doc), IssueCode::NODE_LOOP, "nodes[0]");
}

TEST_F(GltfConformance, NodeWeightsNotMatchingTheMorphTargetsAreRefused)
{
    json doc = triangleScene();
    doc["meshes"][0]["primitives"][0]["targets"] = {{{"NORMAL", 1}}};
    doc["nodes"][0]["weights"] = {0.5, 0.5};
    expectRefused(write(doc), IssueCode::WEIGHTS_COUNT_MISMATCH, "nodes[0].weights");
}

TEST_F(GltfConformance, EmptyTopLevelArraysAreWarnings)
{
    json doc = triangleScene();
    doc["cameras"] = json::array();
    doc["materials"] = json::array();
    expectWarned(write(doc), IssueCode::EMPTY_ARRAY, "cameras");
    expectWarned(write(doc), IssueCode::EMPTY_ARRAY, "materials");
}

TEST_F(GltfConformance, ByteOrderMarkBeforeTheJsonIsRefused)
{
    const std::string text = "\xEF\xBB\xBF" + triangleScene().dump();
    const fs::path gltf = writeBytes(std::vector<uint8_t>(text.begin(), text.end()), ".gltf");
    expectRefused(gltf, IssueCode::JSON_BYTE_ORDER_MARK, "(top level)");

    json doc = triangleScene();
    const std::string body = "\xEF\xBB\xBF" + doc.dump();
    const fs::path bin = writeBytes(glb({{kJson, std::vector<uint8_t>(body.begin(), body.end()), ' '}}), ".glb");
    expectRefused(bin, IssueCode::JSON_BYTE_ORDER_MARK, "GLB chunk 0 (JSON)");
}

TEST_F(GltfConformance, GlbContainerDefectsAreRefusedByName)
{
    json doc = triangleScene();
    doc["buffers"][0].erase("uri");
    const std::vector<uint8_t> bin = triangleBytes();

    // A chunk whose length is not a multiple of 4.
    std::vector<uint8_t> odd = bin;
    odd.push_back(0);
    expectRefused(writeBytes(glb({jsonChunk(doc), {kBin, odd, 0}}, false), ".glb"),
                  IssueCode::GLB_CHUNK_INVALID, "GLB chunk 1 (BIN)");
    // A JSON chunk followed by two BIN chunks.
    expectRefused(writeBytes(glb({jsonChunk(doc), {kBin, bin, 0}, {kBin, bin, 0}}), ".glb"),
                  IssueCode::GLB_CHUNK_INVALID, "GLB chunk 2 (BIN)");
    // Two JSON chunks.
    expectRefused(writeBytes(glb({jsonChunk(doc), jsonChunk(doc), {kBin, bin, 0}}), ".glb"),
                  IssueCode::GLB_CHUNK_INVALID, "GLB chunk 1 (JSON)");
    // The BIN chunk first.
    expectRefused(writeBytes(glb({{kBin, bin, 0}, jsonChunk(doc)}), ".glb"),
                  IssueCode::GLB_CHUNK_INVALID, "GLB chunk 0");
    // Header defects: version, declared length, truncation.
    std::vector<uint8_t> file = triangleGlb();
    file[4] = 1;
    expectRefused(writeBytes(file, ".glb"), IssueCode::GLB_HEADER_INVALID, "GLB header.version");
    file = triangleGlb();
    const size_t size = file.size();
    file.resize(size - 10);
    expectRefused(writeBytes(file, ".glb"), IssueCode::GLB_HEADER_INVALID, "GLB header.length");
    const uint32_t truncated = uint32_t(file.size());
    std::memcpy(file.data() + 8, &truncated, 4); // a consistent header: the BIN chunk runs past the end
    expectRefused(writeBytes(file, ".glb"), IssueCode::GLB_CHUNK_INVALID, "GLB chunk 1 (BIN)");
    // The buffer claims more bytes than the BIN chunk holds.
    doc["buffers"][0]["byteLength"] = bin.size() + 8;
    expectRefused(writeBytes(glb({jsonChunk(doc), {kBin, bin, 0}}), ".glb"),
                  IssueCode::BUFFER_BYTE_LENGTH_MISMATCH, "buffers[0].byteLength");
}

TEST_F(GltfConformance, ContainerAndJsonFindingsByCode)
{
    json doc = triangleScene();
    doc["buffers"][0].erase("uri");
    const std::vector<uint8_t> bin = triangleBytes();
    // No BIN chunk for the buffer without uri.
    expectRefused(writeBytes(glb({jsonChunk(doc)}), ".glb"), IssueCode::GLB_BIN_CHUNK_MISSING, "buffers[0]");
    // Invalid JSON; a number beyond double precision.
    const std::string broken = "{\"asset\": ";
    expectRefused(writeBytes(std::vector<uint8_t>(broken.begin(), broken.end()), ".gltf"), IssueCode::INVALID_JSON,
                  "(top level)");
    json huge = triangleScene();
    huge["nodes"][0]["translation"] = {12345, 0, 0};
    std::string text = huge.dump();
    text.replace(text.find("12345"), 5, "1e400");
    expectRefused(writeBytes(std::vector<uint8_t>(text.begin(), text.end()), ".gltf"), IssueCode::NUMBER_OUT_OF_RANGE,
                  "nodes[0].translation[0]");
    // Bakeable: bytes after the declared length, an unknown chunk, a BIN chunk more than 3
    // bytes longer than the buffer.
    std::vector<uint8_t> file = triangleGlb();
    file.insert(file.end(), {0, 0, 0, 0});
    expectWarned(writeBytes(file, ".glb"), IssueCode::GLB_TRAILING_BYTES, "GLB header.length");
    expectWarned(writeBytes(glb({jsonChunk(doc), {kBin, bin, 0}, {0x12345678u, {1, 2, 3, 4}, 0}}), ".glb"),
                 IssueCode::GLB_UNKNOWN_CHUNK, "GLB chunk 2");
    std::vector<uint8_t> longer = bin;
    longer.insert(longer.end(), 8, 0);
    expectWarned(writeBytes(glb({jsonChunk(doc), {kBin, longer, 0}}), ".glb"), IssueCode::GLB_BIN_CHUNK_UNUSED_BYTES,
                 "buffers[0].byteLength");
}

// ---- Valid files that bake ----------------------------------------------------------

TEST_F(GltfConformance, BufferWithoutUriThatNothingReadsBakes)
{
    json doc = triangleScene();
    doc["buffers"].push_back({{"byteLength", 16}});
    const ImportedScene r = import(write(doc));
    EXPECT_EQ(r.sourceTriangles, 1u);
}

TEST_F(GltfConformance, GeometryInABufferWithoutUriIsSkippedByName)
{
    // Its bytes are "provided by other means" (valid glTF): the primitive that needs them
    // is skipped with a warning, the rest of the file bakes.
    json doc = triangleScene();
    doc["buffers"].push_back({{"byteLength", 36}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 36}});
    doc["accessors"].push_back(doc["accessors"][0]);
    doc["accessors"][3]["bufferView"] = 3;
    doc["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 3}}}}}}});
    doc["nodes"].push_back({{"mesh", 1}});
    doc["scenes"][0]["nodes"] = {0, 1};
    const ImportedScene r = expectWarned(write(doc), "meshes[1].primitives[0].attributes.POSITION: accessors[3] lies "
                                                     "in buffers[1], which has no uri: its bytes are not in the file: "
                                                     "primitive skipped");
    EXPECT_EQ(r.sourceTriangles, 1u);
}

TEST_F(GltfConformance, GlbPlaceholderBufferWithoutUriBakes)
{
    json doc = triangleScene();
    doc["buffers"][0].erase("uri");
    doc["buffers"].push_back({{"byteLength", 1024}}); // buffers[1]: supplied by other means
    const std::vector<uint8_t> bin = triangleBytes();
    std::vector<uint8_t> padded = bin;
    doc["buffers"][0]["byteLength"] = bin.size() - 2; // the BIN chunk may be padded by up to 3 bytes
    const ImportedScene r = import(writeBytes(glb({jsonChunk(doc), {kBin, padded, 0}}), ".glb"));
    EXPECT_EQ(r.sourceTriangles, 1u);
}

TEST_F(GltfConformance, AccessorWithoutBufferViewReadsZerosWithSparseOnTop)
{
    // POSITION without a bufferView: zeros, then the sparse values at indices 1 and 2.
    std::vector<uint8_t> bin = triangleBytes();
    const size_t sparseAt = bin.size();
    append<uint16_t>(bin, {1, 2});
    append<float>(bin, {1, 0, 0, 0, 1, 0});
    json doc = triangleScene(bin);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", sparseAt}, {"byteLength", 4}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", sparseAt + 4}, {"byteLength", 24}});
    doc["accessors"][0].erase("bufferView");
    doc["accessors"][0]["sparse"] = {{"count", 2},
                                     {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
                                     {"values", {{"bufferView", 4}}}};
    const ImportedScene r = import(write(doc));
    ASSERT_EQ(r.sourceTriangles, 1u);
    ASSERT_EQ(r.scene.vertices.positions.size(), 3u);
    EXPECT_EQ(r.scene.vertices.positions[0], glm::vec3(0, 0, 0));
    EXPECT_EQ(r.scene.vertices.positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(r.scene.vertices.positions[2], glm::vec3(0, 1, 0));
}

TEST_F(GltfConformance, KeyTimesWithoutDataLeaveTheChannelOutByName)
{
    // Key times from an accessor without a bufferView read as zeros (valid glTF; an
    // extension would supply them): not "strictly increasing", so the channel is left out.
    json doc = triangleScene(triangleBytes(), true);
    doc["accessors"][3].erase("bufferView");
    doc["accessors"][3]["max"] = {0};
    const ImportedScene r = expectWarned(write(doc), "animations[0].channels[0]: its sampler's input (accessors[3]) "
                                                     "has no data in the file: channel ignored");
    EXPECT_EQ(r.sourceTriangles, 1u);
}

TEST_F(GltfConformance, DataUriWithoutBase64IsPercentDecoded)
{
    const std::vector<uint8_t> bin = triangleBytes();
    std::string uri = "data:application/gltf-buffer,";
    for (uint8_t b : bin) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", b);
        uri += hex;
    }
    json doc = triangleScene(bin);
    doc["buffers"][0]["uri"] = uri;
    const ImportedScene r = import(write(doc));
    ASSERT_EQ(r.sourceTriangles, 1u);
    EXPECT_EQ(r.scene.vertices.positions[1], glm::vec3(1, 0, 0));
}

TEST_F(GltfConformance, IntegersWrittenWithAFractionBake)
{
    std::string text = triangleScene().dump();
    for (const char* key : {"\"count\":3", "\"componentType\":5126", "\"byteLength\":36", "\"mesh\":0"}) {
        const std::string k = key;
        for (size_t at = text.find(k); at != std::string::npos; at = text.find(k, at + k.size() + 2))
            text.insert(at + k.size(), ".0");
    }
    ASSERT_NE(text.find("\"count\":3.0"), std::string::npos);
    const ImportedScene r = import(writeBytes(std::vector<uint8_t>(text.begin(), text.end()), ".gltf"));
    EXPECT_EQ(r.sourceTriangles, 1u);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST_F(GltfConformance, RemoteUrisAreNotFetched)
{
    json doc = triangleScene();
    doc["buffers"][0]["uri"] = "http://example.com/triangle.bin";
    expectRefused(write(doc), IssueCode::URI_NOT_FETCHED, "buffers[0].uri");
}

// ---- --strict: the first line is the real defect -----------------------------------

TEST_F(GltfConformance, StrictReportsTheErrorBeforeAnyWarning)
{
    // Warnings (a schema one, no normals) and an error (the restart value): under
    // --strict, where any reported warning refuses the file, the error is still the one named.
    json doc = triangleScene(triangleBytes(1.0f, 0xFFFF));
    doc["nodes"][0]["name"] = 7;
    doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    const fs::path path = write(doc);
    lfd::bake::Log strict;
    strict.warn = [&](const std::string& s) { throw BakeError(path.string() + ": " + s + " (--strict)"); };
    try {
        lfd::bake::importGltf(path, strict);
        ADD_FAILURE() << "accepted";
    } catch (const BakeError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": meshes[0].primitives[0].indices: accessors[2] element 2 "
                                                              "is 65535, the primitive-restart value",
                                              0),
                  0u)
            << e.what();
    }
    // An error the import stage finds (a missing image file a material uses) after
    // warnings found before it: the error is still the one named.
    json late = triangleScene();
    late["nodes"][0]["name"] = 7;
    late["images"] = {{{"uri", "missing.png"}}};
    late["textures"] = {{{"source", 0}}};
    late["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    late["meshes"][0]["primitives"][0]["material"] = 0;
    const fs::path latePath = write(late);
    const std::string expected = latePath.string() + ": images[0].uri: image file " +
                                 (dir_ / "missing.png").string() + " (used by materials[0] baseColorTexture) not found";
    for (bool isStrict : {false, true})
        try {
            lfd::bake::importGltf(latePath, isStrict ? strict : lfd::bake::Log{});
            ADD_FAILURE() << "accepted";
        } catch (const BakeError& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
}

} // namespace
