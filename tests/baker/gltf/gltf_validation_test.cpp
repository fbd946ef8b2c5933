// Strict glTF schema validation (baker/gltf/gltf_validation.h): one valid scene that uses every
// top-level property the baker reads, broken one property at a time. Each case imports the
// broken file through importGltf and checks the outcome: refused with one line naming the
// file and the JSON path, or baked with a warning naming the JSON path.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "gltf_test_files.h"
#include "gltf_validation.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using lfd::test::append;
using lfd::test::base64;

// A textured, animated unit triangle: every property family the validator checks.
json validScene()
{
    std::vector<uint8_t> bin;
    append<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});       // 0: POSITION, 36 bytes
    append<float>(bin, {0, 0, 1, 0, 0, 1});                // 36: TEXCOORD_0, 24 bytes
    append<uint16_t>(bin, {0, 1, 2, 0});                   // 60: indices (+ padding), 8 bytes
    append<float>(bin, {0, 1});                            // 68: key times, 8 bytes
    append<float>(bin, {0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f}); // 76: rotations, 32 bytes
    append<float>(bin, {0, 0, 1, 0, 0, 1, 0, 0, 1});       // 108: NORMAL, 36 bytes
    const std::string uri = "data:application/octet-stream;base64," + base64(bin);
    // The import stage never decodes images, so the image is just a PNG signature.
    return {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}, {"name", "root"}, {"rotation", {0, 0, 0, 1}}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 5}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}, {"mode", 4}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
          {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
          {{"bufferView", 3}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"}, {"min", {0}}, {"max", {1}}},
          {{"bufferView", 4}, {"componentType", 5126}, {"count", 2}, {"type", "VEC4"}},
          {{"bufferView", 5}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 6}, {"target", 34963}},
          {{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 8}},
          {{"buffer", 0}, {"byteOffset", 76}, {"byteLength", 32}},
          {{"buffer", 0}, {"byteOffset", 108}, {"byteLength", 36}, {"target", 34962}}}},
        {"buffers", {{{"byteLength", bin.size()}, {"uri", uri}}}},
        {"materials",
         {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.5}}},
           {"alphaMode", "OPAQUE"},
           {"doubleSided", false}}}},
        {"textures", {{{"source", 0}, {"sampler", 0}}}},
        {"samplers", {{{"magFilter", 9729}, {"wrapS", 10497}}}},
        {"images", {{{"uri", "data:image/png;base64,iVBORw0KGgo="}}}},
        {"animations",
         {{{"samplers", {{{"input", 3}, {"output", 4}, {"interpolation", "LINEAR"}}}},
           {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}}}}}}},
    };
}

class GltfValidation : public lfd::test::GltfCaseFiles {
protected:
    GltfValidation() : GltfCaseFiles("lfd_gltf_validation_test") {}

    lfd::bake::ImportedScene import(const fs::path& path)
    {
        return lfd::bake::importGltf(path, lfd::bake::Log{});
    }
};

struct Mutation {
    const char* pointer; // JSON pointer of the property to change
    json value;          // new value; null removes the property
    const char* expected; // "<JSON path>: <message>" (or the start of it)
};

json mutate(json doc, const Mutation& m)
{
    const json::json_pointer ptr(m.pointer);
    if (m.value.is_null())
        doc.at(ptr.parent_pointer()).erase(ptr.back());
    else
        doc[ptr] = m.value;
    return doc;
}

TEST_F(GltfValidation, ValidSceneImportsWithoutWarnings)
{
    const lfd::bake::ImportedScene r = import(write(validScene()));
    EXPECT_EQ(r.sourceTriangles, 1u);
    EXPECT_EQ(r.scene.animations.size(), 1u);
    EXPECT_EQ(r.scene.textures.size(), 1u);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    EXPECT_TRUE(lfd::bake::gltf::validateGltfSchema(validScene()).empty());
}

TEST_F(GltfValidation, SchemaErrorsRefuseTheFileNamingTheJsonPath)
{
    const Mutation cases[] = {
        // wrong JSON types
        {"/materials/0/pbrMetallicRoughness", json::array({"x"}),
         "materials[0].pbrMetallicRoughness: expected an object, got an array"},
        {"/materials/0/pbrMetallicRoughness/metallicFactor", "0.5",
         "materials[0].pbrMetallicRoughness.metallicFactor: expected a number, got the string \"0.5\""},
        {"/materials/0/doubleSided", 1, "materials[0].doubleSided: expected a boolean, got 1"},
        {"/materials/0/emissiveFactor", json::array({1, 1}), "materials[0].emissiveFactor: expected 3 numbers, got 2"},
        {"/meshes/0/primitives", json::object(), "meshes[0].primitives: expected an array, got an object"},
        {"/nodes/0/translation", json::array({0, 0}), "nodes[0].translation: expected 3 numbers, got 2"},
        {"/nodes/0/matrix", json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "1"}),
         "nodes[0].matrix[15]: expected a number, got the string \"1\""},
        {"/nodes/0/matrix", json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
         "nodes[0].matrix: given together with translation/rotation/scale (a node has one or the other)"},
        {"/extensionsRequired", "KHR_mesh_quantization", "extensionsRequired: expected an array, got the string"},
        {"/extensionsRequired", json::array({"KHR_mesh_quantization"}),
         "extensionsRequired[0]: \"KHR_mesh_quantization\" is not in extensionsUsed"},
        {"/buffers/0/uri", 3, "buffers[0].uri: expected a string, got 3"},
        // references
        {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", -1,
         "materials[0].pbrMetallicRoughness.baseColorTexture.index: -1 is not an index into textures (1 element)"},
        {"/scene", 3, "scene: 3 is not an index into scenes (1 element)"},
        {"/scene", "hello", "scene: expected an index into scenes, got the string \"hello\""},
        {"/scenes/0/nodes", json::array({0, 0}), "scenes[0].nodes[1]: node 0 listed twice"},
        {"/nodes/0/mesh", 0.5, "nodes[0].mesh: expected an index into meshes, got 0.5"},
        {"/nodes/0/children", json::array({7}), "nodes[0].children[0]: 7 is not an index into nodes (1 element)"},
        {"/meshes/0/primitives/0/attributes/POSITION", 9,
         "meshes[0].primitives[0].attributes.POSITION: 9 is not an index into accessors (6 elements)"},
        {"/meshes/0/primitives/0/indices", "2", "meshes[0].primitives[0].indices: expected an index into accessors"},
        {"/meshes/0/primitives/0/material", -1, "meshes[0].primitives[0].material: -1 is not an index into materials"},
        {"/accessors/0/bufferView", 6, "accessors[0].bufferView: 6 is not an index into bufferViews (6 elements)"},
        {"/bufferViews/0/buffer", 1, "bufferViews[0].buffer: 1 is not an index into buffers (1 element)"},
        {"/textures/0/source", 3, "textures[0].source: 3 is not an index into images (1 element)"},
        {"/animations/0/channels/0/sampler", 1,
         "animations[0].channels[0].sampler: 1 is not an index into animations[0].samplers (1 element)"},
        {"/animations/0/channels/0/target/node", 2,
         "animations[0].channels[0].target.node: 2 is not an index into nodes"},
        {"/animations/0/samplers/0/input", 8, "animations[0].samplers[0].input: 8 is not an index into accessors"},
        // required properties
        {"/asset", nullptr, "asset: required property missing"},
        {"/asset/version", nullptr, "asset.version: required property missing"},
        {"/meshes/0/primitives/0/attributes", nullptr, "meshes[0].primitives[0].attributes: required property missing"},
        {"/accessors/0/componentType", nullptr, "accessors[0].componentType: required property missing"},
        {"/accessors/0/count", nullptr, "accessors[0].count: required property missing"},
        {"/bufferViews/0/byteLength", nullptr, "bufferViews[0].byteLength: required property missing"},
        {"/buffers/0/byteLength", nullptr, "buffers[0].byteLength: required property missing"},
        {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", nullptr,
         "materials[0].pbrMetallicRoughness.baseColorTexture.index: required property missing"},
        {"/animations/0/channels/0/target/path", nullptr,
         "animations[0].channels[0].target.path: required property missing"},
        {"/images/0/uri", nullptr, "images[0]: has neither uri nor bufferView"},
        // values and ranges
        {"/asset/version", "1.0", "asset.version: glTF 1.0 is not supported"},
        {"/asset/version", "two", "asset.version: expected a version \"<major>.<minor>\""},
        {"/asset/minVersion", "2.1", "asset.minVersion: glTF 2.1 is not supported"},
        {"/meshes/0/primitives/0/mode", 7, "meshes[0].primitives[0].mode: expected an integer in [0, 6], got 7"},
        {"/accessors/0/componentType", 5124,
         "accessors[0].componentType: expected one of 5120, 5121, 5122, 5123, 5125, 5126, got 5124"},
        {"/accessors/0/type", "VEC5", "accessors[0].type: expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4"},
        {"/accessors/0/count", 0, "accessors[0].count: expected an integer >= 1, got 0"},
        {"/accessors/0/normalized", true, "accessors[0].normalized: must not be true for componentType 5126"},
        {"/accessors/0/byteOffset", -4, "accessors[0].byteOffset: expected an integer >= 0, got -4"},
        {"/accessors/0/sparse", json{{"count", 1}}, "accessors[0].sparse.indices: required property missing"},
        {"/accessors/0/sparse",
         json{{"count", 5}, {"indices", {{"bufferView", 2}, {"componentType", 5123}}}, {"values", {{"bufferView", 0}}}},
         "accessors[0].sparse.count: 5 exceeds the accessor count 3"},
        {"/accessors/0/sparse",
         json{{"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", 5126}}}, {"values", {{"bufferView", 0}}}},
         "accessors[0].sparse.indices.componentType: expected one of 5121, 5123, 5125, got 5126"},
        {"/bufferViews/0/byteLength", -4, "bufferViews[0].byteLength: expected an integer >= 1, got -4"},
        {"/bufferViews/0/byteStride", 2, "bufferViews[0].byteStride: expected an integer in [4, 252], got 2"},
        {"/images/0/bufferView", 0, "images[0]: has both uri and bufferView"},
        {"/animations/0/samplers/0/interpolation", "CUBIC",
         "animations[0].samplers[0].interpolation: expected one of LINEAR, STEP, CUBICSPLINE, got the string"},
    };
    for (const Mutation& m : cases) {
        SCOPED_TRACE(m.pointer);
        const fs::path path = write(mutate(validScene(), m));
        try {
            import(path);
            ADD_FAILURE() << "accepted, expected: " << m.expected;
        } catch (const lfd::bake::BakeError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path.string() + ": " + m.expected, 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST_F(GltfValidation, TopLevelMustBeAnObject)
{
    const fs::path path = write(json::array({1, 2}));
    try {
        import(path);
        ADD_FAILURE() << "accepted";
    } catch (const lfd::bake::BakeError& e) {
        EXPECT_EQ(std::string(e.what()), path.string() + ": (top level): expected a JSON object, got an array");
    }
}

TEST_F(GltfValidation, RecoverableViolationsBakeWithAWarningNamingTheJsonPath)
{
    const Mutation cases[] = {
        {"/materials/0/pbrMetallicRoughness/metallicFactor", 1.5,
         "materials[0].pbrMetallicRoughness.metallicFactor: 1.5 is outside [0.0, 1.0]: clamped"},
        {"/materials/0/pbrMetallicRoughness/baseColorFactor", json::array({2, 0.5, 0.5, 1}),
         "materials[0].pbrMetallicRoughness.baseColorFactor[0]: 2 is outside [0.0, 1.0]: clamped"},
        {"/materials/0/emissiveFactor", json::array({0, -1, 0}),
         "materials[0].emissiveFactor[1]: -1 is outside [0.0, 1.0]: clamped"},
        {"/materials/0/alphaMode", "CUTOUT",
         "materials[0].alphaMode: expected one of OPAQUE, MASK, BLEND, got the string \"CUTOUT\": treated as OPAQUE"},
        {"/materials/0/alphaCutoff", -0.5, "materials[0].alphaCutoff: -0.5 is outside [0.0, inf]: clamped"},
        {"/nodes/0/rotation", json::array({0, 0, 0, 2}), "nodes[0].rotation: not a unit quaternion (length 2.0): normalised"},
        {"/nodes/0/name", 5, "nodes[0].name: expected a string, got 5: name ignored"},
        {"/nodes/0/camera", 0, "nodes[0].camera: 0 is not an index into cameras (0 elements)"},
        {"/samplers/0/magFilter", 1, "samplers[0].magFilter: expected one of 9728, 9729, got 1: ignored"},
        {"/textures/0/sampler", 4, "textures[0].sampler: 4 is not an index into samplers (1 element)"},
        {"/bufferViews/0/target", 1, "bufferViews[0].target: expected one of 34962, 34963, got 1: ignored"},
        {"/bufferViews/6", json{{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 400}}, // read by nothing
         "bufferViews[6]: byteOffset 68 + byteLength 400 exceeds buffers[0].byteLength 144: unusable"},
        {"/accessors/6", json{{"bufferView", 0}, {"byteOffset", 2}, {"componentType", 5126}, {"count", 1}, {"type", "SCALAR"}},
         "accessors[6].byteOffset: 2 is not a multiple of 4 (the component size): unusable (nothing reads it)"},
        {"/images/0/mimeType", "image/gif",
         "images[0].mimeType: expected one of image/jpeg, image/png, got the string \"image/gif\": decoded by content"},
        {"/animations/0/channels/0/target/path", "pointer",
         "animations[0].channels[0].target.path: expected one of translation, rotation, scale, weights, got the string "
         "\"pointer\": channel ignored"},
        {"/meshes/0/primitives/0/attributes/FOO", 0,
         "meshes[0].primitives[0].attributes.FOO: unknown attribute semantic"},
        {"/materials/0/extensions", json{{"KHR_materials_clearcoat", 1}},
         "materials[0].extensions.KHR_materials_clearcoat: expected an object, got 1: extension ignored"},
        {"/scenes/0/name", 42, "scenes[0].name: expected a string, got 42: name ignored"},
    };
    for (const Mutation& m : cases) {
        SCOPED_TRACE(m.pointer);
        const fs::path path = write(mutate(validScene(), m));
        lfd::bake::ImportedScene r;
        ASSERT_NO_THROW(r = import(path));
        bool found = false;
        for (const std::string& w : r.warnings)
            found = found || w.rfind(m.expected, 0) == 0;
        EXPECT_TRUE(found) << "expected warning: " << m.expected << "\nfirst warning: "
                           << (r.warnings.empty() ? "(none)" : r.warnings.front());
    }
}

TEST_F(GltfValidation, ClampedFactorsAreWhatTheWarningSays)
{
    json doc = validScene();
    doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 1.5;
    doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = -2;
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {2, 0.5, -1, 1};
    doc["materials"][0]["emissiveFactor"] = {3, 0, 0};
    doc["nodes"][0]["rotation"] = {0, 0, 0, 2};
    const lfd::bake::ImportedScene r = import(write(doc));
    ASSERT_EQ(r.scene.materials.size(), 1u);
    const lfd::Material& m = r.scene.materials[0];
    EXPECT_EQ(m.metallicFactor, 1.0f);
    EXPECT_EQ(m.roughnessFactor, 0.0f);
    EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f, 0.5f, 0.0f, 1.0f));
    EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_FLOAT_EQ(r.scene.nodes[0].rotation.w, 1.0f); // normalised
}

TEST_F(GltfValidation, FirstErrorIsReportedWithTheCountOfTheRest)
{
    json doc = validScene();
    doc["materials"][0]["doubleSided"] = "yes";
    doc["accessors"][0]["type"] = "VEC9";
    doc["nodes"][0]["mesh"] = -3;
    const fs::path path = write(doc);
    try {
        import(path);
        ADD_FAILURE() << "accepted";
    } catch (const lfd::bake::BakeError& e) {
        // Document order of the validator: nodes, meshes, accessors, ..., materials.
        EXPECT_EQ(std::string(e.what()), path.string() + ": nodes[0].mesh: -3 is not an index into meshes (1 element)"
                                                          " (and 2 more errors)");
    }
}

TEST_F(GltfValidation, BinaryGltfJsonChunkIsValidated)
{
    // GLB: header (magic, version 2, length), JSON chunk padded with spaces, no BIN chunk
    // (the buffer stays a data URI).
    json doc = validScene();
    doc["materials"][0]["pbrMetallicRoughness"] = json::array();
    std::string text = doc.dump();
    while (text.size() % 4)
        text += ' ';
    std::vector<uint8_t> glb;
    append<uint32_t>(glb, {0x46546C67u, 2u, uint32_t(12 + 8 + text.size()), uint32_t(text.size()), 0x4E4F534Au});
    glb.insert(glb.end(), text.begin(), text.end());
    const fs::path path = writeBytes(glb, ".glb");
    try {
        import(path);
        ADD_FAILURE() << "accepted";
    } catch (const lfd::bake::BakeError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ": materials[0].pbrMetallicRoughness: expected an object, got an array");
    }
}

} // namespace
