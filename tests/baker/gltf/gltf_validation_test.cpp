// Strict glTF schema validation (baker/gltf/gltf_validation.h): one valid scene that uses every
// top-level property the baker reads, broken one property at a time. Each case checks the
// outcome by issue code (gltf_issue_codes.h) and JSON path: refused, with one line naming the
// file and the JSON path, or baked with a warning of that code at that path.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "gltf_findings.h"
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
using lfd::test::IssueCode;

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
    const char* pointer;  // JSON pointer of the property to change
    json value;           // new value; null removes the property
    IssueCode code;       // the finding expected
    const char* jsonPath; // where
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

// One property changed per case; each refuses the file with `code` at `jsonPath`.
const Mutation kSchemaErrors[] = {
    // wrong JSON types
    {"/materials/0/pbrMetallicRoughness", json::array({"x"}),
     IssueCode::TYPE_MISMATCH, "materials[0].pbrMetallicRoughness"},
    {"/materials/0/pbrMetallicRoughness/metallicFactor", "0.5",
     IssueCode::TYPE_MISMATCH, "materials[0].pbrMetallicRoughness.metallicFactor"},
    {"/materials/0/doubleSided", 1, IssueCode::TYPE_MISMATCH, "materials[0].doubleSided"},
    {"/materials/0/emissiveFactor", json::array({1, 1}), IssueCode::ARRAY_LENGTH_MISMATCH, "materials[0].emissiveFactor"},
    {"/meshes/0/primitives", json::object(), IssueCode::TYPE_MISMATCH, "meshes[0].primitives"},
    {"/nodes/0/translation", json::array({0, 0}), IssueCode::ARRAY_LENGTH_MISMATCH, "nodes[0].translation"},
    {"/nodes/0/matrix", json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, "1"}),
     IssueCode::TYPE_MISMATCH, "nodes[0].matrix[15]"},
    {"/nodes/0/matrix", json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
     IssueCode::NODE_MATRIX_TRS, "nodes[0].matrix"},
    {"/extensionsRequired", "KHR_mesh_quantization", IssueCode::TYPE_MISMATCH, "extensionsRequired"},
    {"/extensionsRequired", json::array({"KHR_mesh_quantization"}),
     IssueCode::REQUIRED_EXTENSION_NOT_USED, "extensionsRequired[0]"},
    {"/buffers/0/uri", 3, IssueCode::TYPE_MISMATCH, "buffers[0].uri"},
    // references
    {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", -1,
     IssueCode::UNRESOLVED_REFERENCE, "materials[0].pbrMetallicRoughness.baseColorTexture.index"},
    {"/scene", 3, IssueCode::UNRESOLVED_REFERENCE, "scene"},
    {"/scene", "hello", IssueCode::TYPE_MISMATCH, "scene"},
    {"/scenes/0/nodes", json::array({0, 0}), IssueCode::DUPLICATE_ELEMENT, "scenes[0].nodes[1]"},
    {"/nodes/0/mesh", 0.5, IssueCode::TYPE_MISMATCH, "nodes[0].mesh"},
    {"/nodes/0/children", json::array({7}), IssueCode::UNRESOLVED_REFERENCE, "nodes[0].children[0]"},
    {"/meshes/0/primitives/0/attributes/POSITION", 9,
     IssueCode::UNRESOLVED_REFERENCE, "meshes[0].primitives[0].attributes.POSITION"},
    {"/meshes/0/primitives/0/indices", "2", IssueCode::TYPE_MISMATCH, "meshes[0].primitives[0].indices"},
    {"/meshes/0/primitives/0/material", -1, IssueCode::UNRESOLVED_REFERENCE, "meshes[0].primitives[0].material"},
    {"/accessors/0/bufferView", 6, IssueCode::UNRESOLVED_REFERENCE, "accessors[0].bufferView"},
    {"/bufferViews/0/buffer", 1, IssueCode::UNRESOLVED_REFERENCE, "bufferViews[0].buffer"},
    {"/textures/0/source", 3, IssueCode::UNRESOLVED_REFERENCE, "textures[0].source"},
    {"/animations/0/channels/0/sampler", 1,
     IssueCode::UNRESOLVED_REFERENCE, "animations[0].channels[0].sampler"},
    {"/animations/0/channels/0/target/node", 2,
     IssueCode::UNRESOLVED_REFERENCE, "animations[0].channels[0].target.node"},
    {"/animations/0/samplers/0/input", 8, IssueCode::UNRESOLVED_REFERENCE, "animations[0].samplers[0].input"},
    // required properties
    {"/asset", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "asset"},
    {"/asset/version", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "asset.version"},
    {"/meshes/0/primitives/0/attributes", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "meshes[0].primitives[0].attributes"},
    {"/accessors/0/componentType", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "accessors[0].componentType"},
    {"/accessors/0/count", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "accessors[0].count"},
    {"/bufferViews/0/byteLength", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "bufferViews[0].byteLength"},
    {"/buffers/0/byteLength", nullptr, IssueCode::MISSING_REQUIRED_PROPERTY, "buffers[0].byteLength"},
    {"/materials/0/pbrMetallicRoughness/baseColorTexture/index", nullptr,
     IssueCode::MISSING_REQUIRED_PROPERTY, "materials[0].pbrMetallicRoughness.baseColorTexture.index"},
    {"/animations/0/channels/0/target/path", nullptr,
     IssueCode::MISSING_REQUIRED_PROPERTY, "animations[0].channels[0].target.path"},
    {"/images/0/uri", nullptr, IssueCode::IMAGE_SOURCE_MISSING, "images[0]"},
    // values and ranges
    {"/asset/version", "1.0", IssueCode::UNSUPPORTED_VERSION, "asset.version"},
    {"/asset/version", "two", IssueCode::INVALID_VERSION, "asset.version"},
    {"/asset/minVersion", "2.1", IssueCode::UNSUPPORTED_VERSION, "asset.minVersion"},
    {"/meshes/0/primitives/0/mode", 7, IssueCode::VALUE_OUT_OF_RANGE, "meshes[0].primitives[0].mode"},
    {"/accessors/0/componentType", 5124,
     IssueCode::VALUE_NOT_IN_LIST, "accessors[0].componentType"},
    {"/accessors/0/type", "VEC5", IssueCode::VALUE_NOT_IN_LIST, "accessors[0].type"},
    {"/accessors/0/count", 0, IssueCode::VALUE_OUT_OF_RANGE, "accessors[0].count"},
    {"/accessors/0/normalized", true, IssueCode::ACCESSOR_NORMALIZED_INVALID, "accessors[0].normalized"},
    {"/accessors/0/byteOffset", -4, IssueCode::VALUE_OUT_OF_RANGE, "accessors[0].byteOffset"},
    {"/accessors/0/sparse", json{{"count", 1}}, IssueCode::MISSING_REQUIRED_PROPERTY, "accessors[0].sparse.indices"},
    {"/accessors/0/sparse",
     json{{"count", 5}, {"indices", {{"bufferView", 2}, {"componentType", 5123}}}, {"values", {{"bufferView", 0}}}},
     IssueCode::ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE, "accessors[0].sparse.count"},
    {"/accessors/0/sparse",
     json{{"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", 5126}}}, {"values", {{"bufferView", 0}}}},
     IssueCode::VALUE_NOT_IN_LIST, "accessors[0].sparse.indices.componentType"},
    {"/bufferViews/0/byteLength", -4, IssueCode::VALUE_OUT_OF_RANGE, "bufferViews[0].byteLength"},
    {"/bufferViews/0/byteStride", 2, IssueCode::VALUE_OUT_OF_RANGE, "bufferViews[0].byteStride"},
    {"/images/0/bufferView", 0, IssueCode::IMAGE_SOURCE_CONFLICT, "images[0]"},
    {"/animations/0/samplers/0/interpolation", "CUBIC",
     IssueCode::VALUE_NOT_IN_LIST, "animations[0].samplers[0].interpolation"},
};
TEST_F(GltfValidation, SchemaErrorsRefuseTheFileNamingTheJsonPath)
{
    for (const Mutation& m : kSchemaErrors) {
        SCOPED_TRACE(m.pointer);
        const fs::path path = write(mutate(validScene(), m));
        lfd::test::expectRefusedWith(path, m.code, m.jsonPath);
        try {
            import(path);
            ADD_FAILURE() << "accepted, expected: " << m.jsonPath;
        } catch (const lfd::bake::BakeError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path.string() + ": " + m.jsonPath + ": ", 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST_F(GltfValidation, TopLevelMustBeAnObject)
{
    const fs::path path = write(json::array({1, 2}));
    lfd::test::expectRefusedWith(path, IssueCode::TYPE_MISMATCH, "(top level)");
    EXPECT_THROW(import(path), lfd::bake::BakeError);
}

TEST_F(GltfValidation, RecoverableViolationsBakeWithAWarningNamingTheJsonPath)
{
    const Mutation cases[] = {
        {"/materials/0/pbrMetallicRoughness/metallicFactor", 1.5,
         IssueCode::VALUE_CLAMPED, "materials[0].pbrMetallicRoughness.metallicFactor"},
        {"/materials/0/pbrMetallicRoughness/baseColorFactor", json::array({2, 0.5, 0.5, 1}),
         IssueCode::VALUE_CLAMPED, "materials[0].pbrMetallicRoughness.baseColorFactor[0]"},
        {"/materials/0/emissiveFactor", json::array({0, -1, 0}),
         IssueCode::VALUE_CLAMPED, "materials[0].emissiveFactor[1]"},
        {"/materials/0/alphaMode", "CUTOUT",
         IssueCode::VALUE_NOT_IN_LIST, "materials[0].alphaMode"},
        {"/materials/0/alphaCutoff", -0.5, IssueCode::VALUE_CLAMPED, "materials[0].alphaCutoff"},
        {"/nodes/0/rotation", json::array({0, 0, 0, 2}), IssueCode::NODE_ROTATION_NON_UNIT, "nodes[0].rotation"},
        {"/nodes/0/name", 5, IssueCode::TYPE_MISMATCH, "nodes[0].name"},
        {"/nodes/0/camera", 0, IssueCode::UNRESOLVED_REFERENCE, "nodes[0].camera"},
        {"/samplers/0/magFilter", 1, IssueCode::VALUE_NOT_IN_LIST, "samplers[0].magFilter"},
        {"/textures/0/sampler", 4, IssueCode::UNRESOLVED_REFERENCE, "textures[0].sampler"},
        {"/bufferViews/0/target", 1, IssueCode::VALUE_NOT_IN_LIST, "bufferViews[0].target"},
        {"/bufferViews/6", json{{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 400}}, // read by nothing
         IssueCode::BUFFER_VIEW_TOO_LONG, "bufferViews[6]"},
        {"/accessors/6", json{{"bufferView", 0}, {"byteOffset", 2}, {"componentType", 5126}, {"count", 1}, {"type", "SCALAR"}},
         IssueCode::ACCESSOR_OFFSET_ALIGNMENT, "accessors[6].byteOffset"},
        {"/images/0/mimeType", "image/gif",
         IssueCode::IMAGE_MIME_TYPE_UNKNOWN, "images[0].mimeType"},
        {"/animations/0/channels/0/target/path", "pointer",
         IssueCode::VALUE_NOT_IN_LIST, "animations[0].channels[0].target.path"},
        {"/meshes/0/primitives/0/attributes/FOO", 0,
         IssueCode::UNKNOWN_ATTRIBUTE_SEMANTIC, "meshes[0].primitives[0].attributes.FOO"},
        {"/materials/0/extensions", json{{"KHR_materials_clearcoat", 1}},
         IssueCode::TYPE_MISMATCH, "materials[0].extensions.KHR_materials_clearcoat"},
        {"/scenes/0/name", 42, IssueCode::TYPE_MISMATCH, "scenes[0].name"},
    };
    for (const Mutation& m : cases) {
        SCOPED_TRACE(m.pointer);
        const fs::path path = write(mutate(validScene(), m));
        lfd::bake::ImportedScene r;
        ASSERT_NO_THROW(r = import(path));
        lfd::test::expectWarningWith(path, m.code, m.jsonPath);
        bool found = false; // and the importer passes it on, path first
        for (const std::string& w : r.warnings)
            found = found || w.rfind(std::string(m.jsonPath) + ": ", 0) == 0;
        EXPECT_TRUE(found) << "no warning at " << m.jsonPath;
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
    // Document order of the validator: nodes, meshes, accessors, ..., materials.
    lfd::test::expectRefusedWith(path, IssueCode::UNRESOLVED_REFERENCE, "nodes[0].mesh");
    try {
        import(path);
        ADD_FAILURE() << "accepted";
    } catch (const lfd::bake::BakeError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path.string() + ": nodes[0].mesh: ", 0), 0u) << what;
        EXPECT_TRUE(what.ends_with(" (and 2 more errors)")) << what;
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
    lfd::test::expectRefusedWith(path, IssueCode::TYPE_MISMATCH, "materials[0].pbrMetallicRoughness");
    EXPECT_THROW(import(path), lfd::bake::BakeError);
}

struct FindingCase {
    std::vector<std::pair<const char*, json>> edits; // JSON pointer, new value (null: removed)
    IssueCode code;
    const char* jsonPath;
    lfd::test::IssueSeverity severity;
};

constexpr lfd::test::IssueSeverity kError = lfd::test::IssueSeverity::Error, kWarning = lfd::test::IssueSeverity::Warning;

// Two negative key times, as a data-URI buffer.
json negativeKeysBuffer()
{
    std::vector<uint8_t> keys;
    append<float>(keys, {-1, 1});
    return {{"byteLength", 8}, {"uri", "data:application/octet-stream;base64," + base64(keys)}};
}

const json kView6 = {{"buffer", 0}, {"byteLength", 12}};

// The edits of validScene() that each make one kind of finding.
const FindingCase kFindingCases[] = {
    {{{"/nodes/1", {{"children", {3}}}}, {"/nodes/2", {{"children", {3}}}}, {"/nodes/3", json::object()}},
     IssueCode::NODE_MULTIPLE_PARENTS, "nodes[2].children[0]", kError},
    {{{"/meshes/0/primitives/1", {{"attributes", {{"POSITION", 0}}}, {"targets", {{{"POSITION", 0}}}}}}},
     IssueCode::MESH_PRIMITIVES_UNEQUAL_TARGETS_COUNT, "meshes[0].primitives[1].targets", kError},
    {{{"/accessors/1/count", 2}}, IssueCode::MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT,
     "meshes[0].primitives[0].attributes.TEXCOORD_0", kError},
    {{{"/meshes/0/primitives/0/targets", {{{"TANGENT", 0}}}}}, IssueCode::MORPH_TARGET_ATTRIBUTE_UNKNOWN,
     "meshes[0].primitives[0].targets[0].TANGENT", kError},
    {{{"/bufferViews/6", kView6},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}}},
      {"/meshes/0/primitives/0/attributes/_CUSTOM", 6}},
     IssueCode::VERTEX_ATTRIBUTE_UNSIGNED_INT, "meshes[0].primitives[0].attributes._CUSTOM", kWarning},
    {{{"/bufferViews/6", kView6},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5121}, {"count", 3}, {"type", "VEC4"}}},
      {"/meshes/0/primitives/0/attributes/JOINTS_0", 6}},
     IssueCode::SKINNING_ATTRIBUTES_UNPAIRED, "meshes[0].primitives[0].attributes", kWarning},
    {{{"/bufferViews/6", {{"buffer", 0}, {"byteLength", 16}}},
      {"/accessors/6",
       {{"bufferView", 6}, {"byteOffset", 2}, {"componentType", 5123}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}}},
      {"/meshes/0/primitives/0/attributes/TEXCOORD_1", 6}},
     IssueCode::VERTEX_ATTRIBUTE_MISALIGNED, "accessors[6].byteOffset", kError},
    {{{"/accessors/6",
       {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
        {"sparse", {{"count", 3}, {"indices", {{"bufferView", 5}, {"byteOffset", 8}, {"componentType", 5125}}},
                    {"values", {{"bufferView", 0}}}}}}}},
     IssueCode::ACCESSOR_SPARSE_INDEX_OOB, "accessors[6].sparse.indices", kError},
    {{{"/accessors/6",
       {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
        {"sparse", {{"count", 3}, {"indices", {{"bufferView", 5}, {"componentType", 5125}}},
                    {"values", {{"bufferView", 0}}}}}}}},
     IssueCode::ACCESSOR_SPARSE_INDICES_NON_INCREASING, "accessors[6].sparse.indices", kError},
    {{{"/bufferViews/6", {{"buffer", 0}, {"byteLength", 36}, {"byteStride", 8}}},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
     IssueCode::ACCESSOR_ELEMENT_LONGER_THAN_STRIDE, "accessors[6]", kWarning}, // nothing reads it
    {{{"/bufferViews/6", {{"buffer", 0}, {"byteOffset", 2}, {"byteLength", 8}}},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5126}, {"count", 1}, {"type", "SCALAR"}}}},
     IssueCode::ACCESSOR_TOTAL_OFFSET_ALIGNMENT, "accessors[6]", kWarning},
    // NORMAL's data read as VEC4: unit xyz, w = 0.
    {{{"/accessors/6", {{"bufferView", 5}, {"componentType", 5126}, {"count", 2}, {"type", "VEC4"}}},
      {"/meshes/0/primitives/0/attributes/TANGENT", 6}},
     IssueCode::ACCESSOR_INVALID_SIGN, "accessors[6]", kWarning},
    // The index view, without its target, also read as vertex data (tinygltf then gives it
    // the vertex target).
    {{{"/bufferViews/2/target", nullptr},
      {"/accessors/6", {{"bufferView", 2}, {"componentType", 5123}, {"normalized", true}, {"count", 1}, {"type", "VEC2"}}},
      {"/meshes/0/primitives/0/attributes/TEXCOORD_1", 6}},
     IssueCode::BUFFER_VIEW_TARGET_MISMATCH, "bufferViews[2].target", kError},
    {{{"/bufferViews/3/extensions",
       {{"EXT_meshopt_compression", json::object()}, {"KHR_meshopt_compression", json::object()}}}},
     IssueCode::MESHOPT_BOTH_EXTENSIONS, "bufferViews[3].extensions", kError},
    {{{"/buffers/0/uri", "data:application/octet-stream;base64,@@@@"}}, IssueCode::DATA_URI_MALFORMED,
     "buffers[0].uri", kError},
    {{{"/images/0/uri", "data:image/png;base64,"}}, IssueCode::DATA_URI_EMPTY, "images[0].uri", kError},
    {{{"/buffers/0/uri", "data:text/plain;base64,AAAA"}}, IssueCode::DATA_URI_MEDIA_TYPE_INVALID, "buffers[0].uri",
     kError},
    {{{"/images/0", {{"bufferView", 6}, {"mimeType", "image/png"}}},
      {"/bufferViews/6", {{"buffer", 0}, {"byteLength", 8}, {"byteStride", 4}}}},
     IssueCode::IMAGE_BUFFER_VIEW_WITH_BYTESTRIDE, "images[0].bufferView", kError},
    {{{"/images/0", {{"bufferView", 6}}}, {"/bufferViews/6", {{"buffer", 0}, {"byteLength", 8}}}},
     IssueCode::IMAGE_MIME_TYPE_MISSING, "images[0].mimeType", kWarning},
    {{{"/images/0/mimeType", "image/jpeg"}}, IssueCode::IMAGE_MIME_TYPE_MISMATCH, "images[0].mimeType", kWarning},
    {{{"/animations/0/channels/0/target/path", "weights"}},
     IssueCode::ANIMATION_CHANNEL_TARGET_NODE_WEIGHTS_NO_MORPHS, "animations[0].channels[0].target.path", kError},
    {{{"/bufferViews/3/byteStride", 4}}, IssueCode::ANIMATION_SAMPLER_ACCESSOR_WITH_BYTESTRIDE,
     "animations[0].samplers[0].input", kError},
    {{{"/buffers/1", negativeKeysBuffer()},
      {"/bufferViews/6", {{"buffer", 1}, {"byteLength", 8}}},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5126}, {"count", 2}, {"type", "SCALAR"},
                        {"min", {-1}}, {"max", {1}}}},
      {"/animations/0/samplers/0/input", 6}},
     IssueCode::ANIMATION_KEY_TIME_INVALID, "accessors[6]", kError},
    {{{"/accessors/3/count", 1}, {"/animations/0/samplers/0/interpolation", "CUBICSPLINE"}},
     IssueCode::ANIMATION_CUBICSPLINE_TOO_FEW_KEYS, "animations[0].samplers[0].input", kError},
    {{{"/accessors/4/count", 1}}, IssueCode::ANIMATION_SAMPLER_OUTPUT_COUNT_MISMATCH,
     "animations[0].samplers[0].output", kError},
    {{{"/cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 1}, {"znear", 2}, {"zfar", 1}}}}}}},
     IssueCode::CAMERA_ZFAR_NOT_GREATER, "cameras[0].perspective", kWarning},
    {{{"/nodes/1", json::object()}, {"/nodes/2", json::object()},
      {"/skins", {{{"joints", {0, 1, 2}}, {"inverseBindMatrices", 3}, {"skeleton", 1}}}}},
     IssueCode::SKIN_TOO_FEW_MATRICES, "skins[0].inverseBindMatrices", kWarning},
    {{{"/nodes/1", json::object()}, {"/skins", {{{"joints", {0, 1}}}}}},
     IssueCode::SKIN_NO_COMMON_ROOT, "skins[0].joints", kWarning},
    {{{"/nodes/1", json::object()}, {"/skins", {{{"joints", {0}}, {"skeleton", 1}}}}},
     IssueCode::SKIN_SKELETON_INVALID, "skins[0].skeleton", kWarning},
    {{{"/bufferViews/6", {{"buffer", 0}, {"byteLength", 64}, {"byteStride", 64}}},
      {"/accessors/6", {{"bufferView", 6}, {"componentType", 5126}, {"count", 1}, {"type", "MAT4"}}},
      {"/skins", {{{"joints", {0}}, {"inverseBindMatrices", 6}}}}},
     IssueCode::SKIN_IBM_ACCESSOR_WITH_BYTESTRIDE, "skins[0].inverseBindMatrices", kWarning},
};

// One case for each kind of finding the other tests here do not make: the finding (code,
// JSON path, severity) is among those of the file, wherever it comes in the list.
TEST_F(GltfValidation, EveryKindOfFindingHasACase)
{
    for (const FindingCase& c : kFindingCases) {
        SCOPED_TRACE(lfd::test::codeName(c.code));
        json doc = validScene();
        for (const auto& [pointer, value] : c.edits) {
            const json::json_pointer ptr(pointer);
            if (value.is_null())
                doc.at(ptr.parent_pointer()).erase(ptr.back());
            else
                doc[ptr] = value;
        }
        const std::vector<lfd::test::SchemaIssue> issues = lfd::test::gltfFindings(write(doc));
        bool found = false;
        for (const auto& i : issues)
            found = found || (i.code == c.code && i.path == c.jsonPath && i.severity == c.severity);
        EXPECT_TRUE(found) << "expected " << lfd::test::codeName(c.code) << " at " << c.jsonPath
                           << lfd::test::listFindings(issues);
    }
}

} // namespace
