// glTF import of KHR_texture_transform, KHR_materials_unlit and KHR_lights_punctual
// (Khronos extension specifications): defaults, values, the texCoord override, required
// and optional use, lights on nodes (instanced, unreachable, light-only nodes), and bad
// JSON refused or warned about with its JSON path. Each case is a small file written here.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_findings.h"
#include "gltf_import.h"
#include "import_test_cases.h"
#include "gltf_test_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

namespace fs = std::filesystem;
using nlohmann::json;
using lfd::bake::BakeError;
using lfd::test::IssueCode;
using lfd::bake::ImportedScene;
using lfd::test::hasWarning;

namespace {

using lfd::test::append;
using lfd::test::base64;

const std::string kPng = "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR4nGM4kWL0HwAFtAJeHzr7ywAAAABJRU5ErkJggg==";
const std::string kBaseColorTransform = "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform";

// A unit triangle with TEXCOORD_0 (and TEXCOORD_1 if asked) drawn by node 0 with material
// 0, which the caller fills in; one texture of a 1x1 PNG. Bytes: POSITION (0, 36), NORMAL
// (36, 36), TEXCOORD_0 (72, 24), indices (96, 6 + 2 padding), TEXCOORD_1 (104, 24).
json texturedTriangle(const json& material, bool texCoord1 = false)
{
    std::vector<uint8_t> bin;
    append<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
    append<float>(bin, {0, 0, 1, 0, 0, 1, 0, 0, 1});
    append<float>(bin, {0, 0, 1, 0, 0, 1});
    append<uint16_t>(bin, {0, 1, 2, 0});
    append<float>(bin, {0, 0, 0.5f, 0, 0, 0.5f});
    auto view = [](int offset, int length, int target) {
        return json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}, {"target", target}};
    };
    json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"name", "triangle"}, {"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}, {"material", 0}}}}}}},
        {"materials", {material}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", kPng}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
          {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
          {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
          {{"bufferView", 3}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
        {"bufferViews", {view(0, 36, 34962), view(36, 36, 34962), view(72, 24, 34962), view(96, 6, 34963)}},
        {"buffers", {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}}},
    };
    if (texCoord1) {
        doc["bufferViews"].push_back(view(104, 24, 34962));
        doc["accessors"].push_back({{"bufferView", 4}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
        doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 4;
    }
    return doc;
}

json textured(const json& baseColorInfo) { return {{"pbrMetallicRoughness", {{"baseColorTexture", baseColorInfo}}}}; }

json transformInfo(const json& transform, int texCoord = 0)
{
    return {{"index", 0}, {"texCoord", texCoord}, {"extensions", {{"KHR_texture_transform", transform}}}};
}

// The triangle plus three lights: 0 a directional, 1 a point, 2 a spot. Node 1 (a child
// of node 0, no mesh) carries light 0; nodes 2 and 3 (roots) both carry light 1; node 4
// carries light 2 and is in no scene.
json litTriangle()
{
    json doc = texturedTriangle(textured({{"index", 0}}));
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 3.0}},
        {{"type", "point"}, {"range", 5.0}},
        {{"name", "cone"}, {"type", "spot"}, {"intensity", 200.0}, {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}}};
    doc["nodes"][0]["children"] = {1};
    auto lightNode = [](const char* name, int light) {
        return json{{"name", name}, {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}}};
    };
    doc["nodes"].push_back(lightNode("sun node", 0));
    doc["nodes"].push_back(lightNode("bulb a", 1));
    doc["nodes"].push_back(lightNode("bulb b", 1));
    doc["nodes"].push_back(lightNode("stray spot", 2));
    doc["scenes"][0]["nodes"] = {0, 2, 3};
    return doc;
}

void expectSameTransform(const lfd::TextureTransform& a, const lfd::TextureTransform& b)
{
    for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 2; ++r)
            EXPECT_NEAR(a.linear[c][r], b.linear[c][r], 1e-6f) << c << r;
    EXPECT_NEAR(a.offset.x, b.offset.x, 1e-6f);
    EXPECT_NEAR(a.offset.y, b.offset.y, 1e-6f);
}

class GltfMaterialLights : public lfd::test::GltfCaseFiles {
protected:
    GltfMaterialLights() : GltfCaseFiles("lfd_gltf_material_lights") {}

    ImportedScene import(const json& doc) { return lfd::bake::importGltf(write(doc), lfd::bake::Log{}); }

    // The import refuses `doc` with one line naming the file and containing `part`.
    void expectRefused(const json& doc, const std::string& part)
    {
        const fs::path path = write(doc);
        try {
            lfd::bake::importGltf(path, lfd::bake::Log{});
            ADD_FAILURE() << "accepted, expected an error containing '" << part << "'";
        } catch (const BakeError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_NE(what.find(part), std::string::npos) << what;
        }
    }

    // Refused with one line naming `jsonPath`, whose finding is `code` (gltf_issue_codes.h).
    void expectRefused(const json& doc, IssueCode code, const std::string& jsonPath)
    {
        lfd::test::expectRefusedWith(write(doc), code, jsonPath);
        expectRefused(doc, ": " + jsonPath + ": ");
    }
};

TEST_F(GltfMaterialLights, TextureTransformValuesAndDefaults)
{
    json material = textured(transformInfo({{"offset", {0.5, 0.25}}, {"rotation", 0.3}, {"scale", {2.0, 3.0}}}));
    material["normalTexture"] = transformInfo(json::object()); // every default: identity
    material["occlusionTexture"] = {{"index", 0}};             // no extension: identity
    material["emissiveTexture"] = transformInfo({{"scale", {4.0, 4.0}}});
    json doc = texturedTriangle(material);
    doc["extensionsUsed"] = {"KHR_texture_transform"};
    const ImportedScene r = import(doc);
    ASSERT_EQ(r.scene.materials.size(), 1u);
    const lfd::Material& m = r.scene.materials[0];
    expectSameTransform(m.transform(lfd::TextureSlot::BaseColor),
                        lfd::TextureTransform::fromOffsetRotationScale({0.5f, 0.25f}, 0.3f, {2.0f, 3.0f}));
    EXPECT_NEAR(m.transform(lfd::TextureSlot::BaseColor).areaScale(), 6.0f, 1e-5f);
    EXPECT_TRUE(m.transform(lfd::TextureSlot::Normal).identity());
    EXPECT_TRUE(m.transform(lfd::TextureSlot::Occlusion).identity());
    EXPECT_TRUE(m.transform(lfd::TextureSlot::MetallicRoughness).identity()); // no texture
    expectSameTransform(m.transform(lfd::TextureSlot::Emissive),
                        lfd::TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {4.0f, 4.0f}));
    EXPECT_TRUE(m.hasExtensions());
    EXPECT_FALSE(m.unlit);
    EXPECT_FALSE(hasWarning(r, "KHR_texture_transform")) << r.warnings.front();
}

// The extension's rotation is counter-clockwise in uv space as the Khronos sample viewer
// applies it: uv' = R(r) S uv + offset with R rows [[cos, sin], [-sin, cos]].
TEST_F(GltfMaterialLights, RotationAndOffsetMapUvsAsTheSpecificationsMatrix)
{
    const double quarter = std::numbers::pi / 2.0;
    const ImportedScene r = import(texturedTriangle(textured(
        transformInfo({{"offset", {0.25, 0.5}}, {"rotation", quarter}, {"scale", {2.0, 1.0}}}))));
    const lfd::TextureTransform& t = r.scene.materials[0].transform(lfd::TextureSlot::BaseColor);
    const glm::vec2 u = t.apply({1.0f, 0.0f}); // u' = 2 cos r + 0.25 = 0.25, v' = -2 sin r + 0.5 = -1.5
    const glm::vec2 v = t.apply({0.0f, 1.0f}); // u' = sin r + 0.25 = 1.25, v' = cos r + 0.5 = 0.5
    EXPECT_NEAR(u.x, 0.25f, 1e-6f);
    EXPECT_NEAR(u.y, -1.5f, 1e-6f);
    EXPECT_NEAR(v.x, 1.25f, 1e-6f);
    EXPECT_NEAR(v.y, 0.5f, 1e-6f);
}

TEST_F(GltfMaterialLights, TexCoordOverrideDecidesWhetherASlotIsTextured)
{
    // baseColor: texCoord 1 overridden to 0 (usable); emissive: 0 overridden to 1 (not).
    json material = textured(transformInfo({{"texCoord", 0}, {"offset", {0.5, 0.0}}}, 1));
    material["emissiveTexture"] = transformInfo({{"texCoord", 1}});
    const ImportedScene r = import(texturedTriangle(material, true));
    const lfd::Material& m = r.scene.materials[0];
    EXPECT_NE(m.baseColorTexture, lfd::kNone);
    EXPECT_EQ(m.transform(lfd::TextureSlot::BaseColor).offset, glm::vec2(0.5f, 0.0f));
    EXPECT_EQ(m.emissiveTexture, lfd::kNone);
    EXPECT_TRUE(m.transform(lfd::TextureSlot::Emissive).identity());
    EXPECT_TRUE(hasWarning(r, "emissiveTexture uses TEXCOORD_1 (only TEXCOORD_0 is supported): treated as untextured"));
    EXPECT_FALSE(hasWarning(r, "baseColorTexture uses TEXCOORD_1"));
    EXPECT_FALSE(r.scene.vertices.uvs.empty());

    // The semantic check follows the override too: a primitive without TEXCOORD_1 is
    // complete for a texture info whose texCoord 1 is overridden to 0.
    const ImportedScene overridden = import(texturedTriangle(textured(transformInfo({{"texCoord", 0}}, 1))));
    EXPECT_TRUE(overridden.warnings.empty()) << overridden.warnings.front();
    EXPECT_NE(overridden.scene.materials[0].baseColorTexture, lfd::kNone);
    const fs::path missingFile = write(texturedTriangle(textured({{"index", 0}, {"texCoord", 1}})));
    const ImportedScene missing = lfd::bake::importGltf(missingFile, lfd::bake::Log{});
    EXPECT_FALSE(missing.warnings.empty());
    lfd::test::expectWarningWith(missingFile, IssueCode::TEXCOORD_MISSING, "meshes[0].primitives[0].material");
}

TEST_F(GltfMaterialLights, UnlitMaterials)
{
    json unlit = textured({{"index", 0}});
    unlit["extensions"]["KHR_materials_unlit"] = json::object();
    json doc = texturedTriangle(unlit);
    doc["materials"].push_back({{"name", "lit"}});
    doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
    doc["meshes"][0]["primitives"][1]["material"] = 1;
    doc["extensionsUsed"] = {"KHR_materials_unlit"};
    const ImportedScene r = import(doc);
    ASSERT_EQ(r.scene.materials.size(), 2u);
    EXPECT_TRUE(r.scene.materials[0].unlit);
    EXPECT_TRUE(r.scene.materials[0].hasExtensions());
    EXPECT_FALSE(r.scene.materials[1].unlit);
    EXPECT_FALSE(r.scene.materials[1].hasExtensions());
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST_F(GltfMaterialLights, RequiredExtensionsBakeAndOnlyUnknownOnesWarn)
{
    json material = textured(transformInfo({{"scale", {2.0, 2.0}}}));
    material["extensions"]["KHR_materials_unlit"] = json::object();
    json doc = litTriangle();
    doc["materials"][0] = material;
    doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_unlit", "KHR_lights_punctual", "EXT_made_up"};
    doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_materials_unlit", "KHR_lights_punctual"};
    const ImportedScene r = import(doc);
    EXPECT_TRUE(r.scene.materials[0].unlit);
    EXPECT_FALSE(r.scene.materials[0].transform(lfd::TextureSlot::BaseColor).identity());
    EXPECT_EQ(r.scene.lights.size(), 3u);
    EXPECT_TRUE(hasWarning(r, "ignores optional extension EXT_made_up"));
    EXPECT_FALSE(hasWarning(r, "ignores optional extension KHR"));

    // A required extension the baker does not implement is still refused.
    doc["extensionsUsed"].push_back("EXT_required_unknown");
    doc["extensionsRequired"].push_back("EXT_required_unknown");
    expectRefused(doc, "requires unsupported extension EXT_required_unknown");
}

TEST_F(GltfMaterialLights, LightsOnNodesInstancedAndUnreachable)
{
    const ImportedScene r = import(litTriangle());
    const lfd::Scene& s = r.scene;
    // Nodes 0 (triangle), 1 (its light-only child) and the two bulbs are imported; the
    // stray spot's node is in no scene.
    ASSERT_EQ(s.nodes.size(), 4u);
    ASSERT_EQ(s.lights.size(), 3u);
    auto nodeName = [&](const lfd::Light& l) { return s.nodes[l.node].name; };

    const lfd::Light& sun = s.lights[0];
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(nodeName(sun), "sun node");
    EXPECT_EQ(s.nodes[sun.node].parent, 0);
    EXPECT_EQ(s.nodes[sun.node].mesh, lfd::kNone);
    EXPECT_EQ(sun.type, lfd::LightType::Directional);
    EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(sun.intensity, 3.0f);
    EXPECT_EQ(sun.range, 0.0f);

    // One glTF light on two nodes: two instances.
    for (size_t i : {size_t(1), size_t(2)}) {
        const lfd::Light& bulb = s.lights[i];
        EXPECT_EQ(bulb.type, lfd::LightType::Point);
        EXPECT_EQ(bulb.name, "light 1"); // unnamed: by index
        EXPECT_EQ(bulb.color, glm::vec3(1.0f)); // defaults
        EXPECT_EQ(bulb.intensity, 1.0f);
        EXPECT_EQ(bulb.range, 5.0f);
    }
    EXPECT_EQ(nodeName(s.lights[1]), "bulb a");
    EXPECT_EQ(nodeName(s.lights[2]), "bulb b");
    EXPECT_TRUE(hasWarning(r, "nodes[4].extensions.KHR_lights_punctual.light: light 2 is on a node outside the "
                              "imported scene: dropped"));
}

TEST_F(GltfMaterialLights, SpotConeValuesAndDefaults)
{
    json doc = litTriangle();
    doc["nodes"][4]["name"] = "reachable spot";
    doc["scenes"][0]["nodes"].push_back(4);
    doc["extensions"]["KHR_lights_punctual"]["lights"].push_back({{"type", "spot"}, {"spot", json::object()}});
    doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 3;
    const ImportedScene r = import(doc);
    ASSERT_EQ(r.scene.lights.size(), 4u);
    const lfd::Light& defaults = r.scene.lights[1];
    EXPECT_EQ(defaults.type, lfd::LightType::Spot);
    EXPECT_EQ(defaults.innerConeAngle, 0.0f);
    EXPECT_FLOAT_EQ(defaults.outerConeAngle, float(std::numbers::pi / 4.0));
    const lfd::Light& cone = r.scene.lights[3];
    EXPECT_EQ(cone.name, "cone");
    EXPECT_EQ(cone.intensity, 200.0f);
    EXPECT_EQ(cone.innerConeAngle, 0.25f);
    EXPECT_EQ(cone.outerConeAngle, 0.5f);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST_F(GltfMaterialLights, OutOfRangeLightValuesAreClampedWithWarnings)
{
    json doc = litTriangle();
    json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
    lights[0]["color"] = {2.0, 0.5, -1.0};
    lights[0]["intensity"] = -3.0;
    lights[1]["range"] = 0.0;
    lights[1]["spot"] = {{"outerConeAngle", 0.1}};
    doc["nodes"][4]["extensions"]["KHR_lights_punctual"]["light"] = 0;
    lights[2]["spot"]["outerConeAngle"] = 2.0;
    doc["scenes"][0]["nodes"].push_back(4);
    doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 2;
    const fs::path file = write(doc);
    const ImportedScene r = lfd::bake::importGltf(file, lfd::bake::Log{});
    const std::string path = "extensions.KHR_lights_punctual.lights";
    const std::pair<IssueCode, std::string> warnings[] = {
        {IssueCode::VALUE_CLAMPED, path + "[0].color[0]"},
        {IssueCode::VALUE_CLAMPED, path + "[0].color[2]"},
        {IssueCode::VALUE_CLAMPED, path + "[0].intensity"},
        {IssueCode::LIGHT_RANGE_NOT_POSITIVE, path + "[1].range"},
        {IssueCode::PROPERTY_NOT_APPLICABLE, path + "[1].spot"},
        {IssueCode::VALUE_CLAMPED, path + "[2].spot.outerConeAngle"},
    };
    for (const auto& [code, at] : warnings) {
        lfd::test::expectWarningWith(file, code, at);
        EXPECT_TRUE(hasWarning(r, at + ": ")) << at;
    }
    ASSERT_EQ(r.scene.lights.size(), 4u);
    EXPECT_EQ(r.scene.lights[0].color, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(r.scene.lights[0].intensity, 0.0f);
    EXPECT_EQ(r.scene.lights[2].range, 0.0f);
    EXPECT_EQ(r.scene.lights[1].outerConeAngle, float(std::numbers::pi / 2.0));
}

TEST_F(GltfMaterialLights, BadTextureTransformJsonIsRefusedWithItsPath)
{
    const struct {
        json transform;
        IssueCode code;
        std::string path;
    } cases[] = {
        {{{"offset", "left"}}, IssueCode::TYPE_MISMATCH, kBaseColorTransform + ".offset"},
        {{{"offset", json::array({1.0})}}, IssueCode::ARRAY_LENGTH_MISMATCH, kBaseColorTransform + ".offset"},
        {{{"scale", {1.0, "2"}}}, IssueCode::TYPE_MISMATCH, kBaseColorTransform + ".scale[1]"},
        {{{"rotation", json::array({0.5})}}, IssueCode::TYPE_MISMATCH, kBaseColorTransform + ".rotation"},
        {{{"texCoord", -1}}, IssueCode::VALUE_OUT_OF_RANGE, kBaseColorTransform + ".texCoord"},
        {{{"texCoord", 0.5}}, IssueCode::TYPE_MISMATCH, kBaseColorTransform + ".texCoord"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.transform.dump());
        expectRefused(texturedTriangle(textured(transformInfo(c.transform))), c.code, c.path);
    }
    // A transform too large for the pack's floats: one line naming the slot.
    expectRefused(texturedTriangle(textured(transformInfo({{"scale", {1e30, 1e30}}}))),
                  "baseColorTexture KHR_texture_transform is too large for 32-bit floats");
    // Not an object: ignored with a warning, as any extension value.
    const fs::path file = write(texturedTriangle(textured(transformInfo(json::array({1, 2})))));
    const ImportedScene r = lfd::bake::importGltf(file, lfd::bake::Log{});
    lfd::test::expectWarningWith(file, IssueCode::TYPE_MISMATCH, kBaseColorTransform);
    EXPECT_TRUE(r.scene.materials[0].transform(lfd::TextureSlot::BaseColor).identity());
}

TEST_F(GltfMaterialLights, BadLightJsonIsRefusedWithItsPath)
{
    const std::string lights = "extensions.KHR_lights_punctual.lights";
    auto broken = [](auto&& edit) {
        json doc = litTriangle();
        edit(doc, doc["extensions"]["KHR_lights_punctual"]["lights"]);
        return doc;
    };
    expectRefused(broken([](json&, json& l) { l[0]["type"] = "area"; }), IssueCode::VALUE_NOT_IN_LIST,
                  lights + "[0].type");
    expectRefused(broken([](json&, json& l) { l[1].erase("type"); }), IssueCode::MISSING_REQUIRED_PROPERTY,
                  lights + "[1].type");
    expectRefused(broken([](json&, json& l) { l[2].erase("spot"); }), IssueCode::MISSING_REQUIRED_PROPERTY,
                  lights + "[2].spot");
    expectRefused(broken([](json&, json& l) { l[2]["spot"] = {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.4}}; }),
                  IssueCode::SPOT_CONE_INVALID, lights + "[2].spot");
    // Angles beyond pi/2 are clamped first (a warning), then compared.
    expectRefused(broken([](json&, json& l) { l[2]["spot"] = {{"innerConeAngle", 2.0}, {"outerConeAngle", 3.0}}; }),
                  IssueCode::SPOT_CONE_INVALID, lights + "[2].spot");
    expectRefused(broken([](json&, json& l) { l[0]["color"] = {1.0, 1.0}; }), IssueCode::ARRAY_LENGTH_MISMATCH,
                  lights + "[0].color");
    expectRefused(broken([](json&, json& l) { l[1]["intensity"] = "bright"; }), IssueCode::TYPE_MISMATCH,
                  lights + "[1].intensity");
    expectRefused(broken([](json&, json& l) { l[1]["range"] = true; }), IssueCode::TYPE_MISMATCH, lights + "[1].range");
    expectRefused(broken([](json&, json& l) { l[0] = 5; }), IssueCode::TYPE_MISMATCH, lights + "[0]");
    expectRefused(broken([](json& d, json&) { d["extensions"]["KHR_lights_punctual"]["lights"] = json::object(); }),
                  IssueCode::TYPE_MISMATCH, lights);
    expectRefused(broken([](json& d, json&) { d["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 7; }),
                  IssueCode::UNRESOLVED_REFERENCE, "nodes[2].extensions.KHR_lights_punctual.light");
    expectRefused(broken([](json& d, json&) { d["nodes"][3]["extensions"]["KHR_lights_punctual"].erase("light"); }),
                  IssueCode::MISSING_REQUIRED_PROPERTY, "nodes[3].extensions.KHR_lights_punctual.light");
    expectRefused(broken([](json& d, json&) { d.erase("extensions"); }), IssueCode::UNRESOLVED_REFERENCE,
                  "nodes[1].extensions.KHR_lights_punctual.light");
}

} // namespace
