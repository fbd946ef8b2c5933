// Scenes and helpers shared by the pack tests: a scene that exercises every field of the
// format, a small one for byte-level loops, exact field-by-field comparison, and section
// patching (patch a record, then reseal the checksums with lfd::pack::resealPack), and the
// reader's rejections.
#pragma once

#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace lfd::test {

// Deterministic texels (RGBA8 texels or BC blocks) for a full mip chain, different per
// texture `seed`.
inline Texture makeTexture(const std::string& name, uint32_t width, uint32_t height, bool srgb, uint8_t seed,
                           TextureFormat format = TextureFormat::Rgba8)
{
    Texture t;
    t.name = name;
    t.width = width;
    t.height = height;
    t.sourceWidth = width * 2 + 1;
    t.sourceHeight = height * 3;
    t.srgb = srgb;
    t.format = format;
    uint64_t offset = 0;
    for (uint32_t l = 0;; ++l) {
        MipLevel level;
        level.width = std::max(1u, width >> l);
        level.height = std::max(1u, height >> l);
        level.offset = offset;
        level.size = format == TextureFormat::Rgba8 ? uint64_t(level.width) * level.height * 4
                                                    : textureLevelBytes(format, level.width, level.height);
        offset += level.size;
        t.mips.push_back(level);
        if (level.width == 1 && level.height == 1)
            break;
    }
    t.texels.resize(offset);
    for (size_t i = 0; i < t.texels.size(); ++i)
        t.texels[i] = uint8_t(i * 31 + seed * 7 + (i >> 5));
    return t;
}

// makeFullScene's materials (one textured with every slot and transforms, one unlit
// blend) and textures.
inline void addFullSceneMaterials(Scene& s)
{
    Material textured;
    textured.name = "matériau ✨";
    textured.baseColorFactor = {0.9f, 0.5f, 0.25f, 0.75f};
    textured.emissiveFactor = {0.1f, 0.2f, 0.3f};
    textured.metallicFactor = 0.3f;
    textured.roughnessFactor = 0.6f;
    textured.normalScale = 0.8f;
    textured.occlusionStrength = 0.7f;
    textured.alphaCutoff = 0.4f;
    textured.alphaMode = AlphaMode::Mask;
    textured.doubleSided = true;
    textured.baseColorTexture = 0;
    textured.metallicRoughnessTexture = 1;
    textured.normalTexture = 1;
    textured.occlusionTexture = 1;
    textured.emissiveTexture = 0;
    // KHR_texture_transform on three slots (every matrix entry distinct, a mirror included).
    textured.textureTransforms[uint32_t(TextureSlot::BaseColor)] =
        TextureTransform::fromOffsetRotationScale({0.25f, -0.5f}, 0.3f, {2.0f, 3.0f});
    textured.textureTransforms[uint32_t(TextureSlot::Normal)] =
        TextureTransform::fromOffsetRotationScale({0.0f, 1.0f}, -1.25f, {-1.0f, 0.5f});
    textured.textureTransforms[uint32_t(TextureSlot::Emissive)].offset = {0.125f, 0.0f};
    Material blend;
    blend.name = "";
    blend.alphaMode = AlphaMode::Blend;
    blend.baseColorFactor = {0.0f, 1.0f, 0.0f, 0.5f};
    blend.unlit = true; // KHR_materials_unlit
    s.materials = {textured, blend};

    s.textures.push_back(makeTexture("albedo (sRGB) ✓", 5, 3, true, 1));
    s.textures.push_back(makeTexture("orm", 7, 2, false, 2));
}

// makeFullScene's node tree (two roots) and its lights (one of each type).
inline void addFullSceneNodesAndLights(Scene& s)
{
    Node root;
    root.name = "root";
    root.translation = {1.0f, 2.0f, 3.0f};
    root.rotation = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
    root.scale = {2.0f, 2.0f, 2.0f};
    Node child;
    child.name = "child ノード";
    child.parent = 0;
    child.mesh = 0;
    child.scale = {1.0f, 0.5f, 0.25f};
    Node grandchild;
    grandchild.name = "grandchild";
    grandchild.parent = 1;
    grandchild.mesh = 1;
    grandchild.translation = {-1.0f, 0.0f, 0.5f};
    Node other;
    other.name = "second root";
    other.mesh = 1;
    s.nodes = {root, child, grandchild, other};

    // KHR_lights_punctual: one of each type, two on the same node.
    Light sun;
    sun.name = "Sonne ☀";
    sun.node = 0;
    sun.color = {1.0f, 0.9f, 0.75f};
    sun.intensity = 3.5f;
    Light bulb;
    bulb.name = "bulb";
    bulb.type = LightType::Point;
    bulb.node = 3;
    bulb.color = {0.25f, 0.5f, 1.0f};
    bulb.intensity = 120.0f;
    bulb.range = 7.5f;
    Light spot;
    spot.name = "";
    spot.type = LightType::Spot;
    spot.node = 3;
    spot.intensity = 0.0f;
    spot.innerConeAngle = 0.125f;
    spot.outerConeAngle = pack::kMaxSpotConeAngle;
    s.lights = {sun, bulb, spot};
}

// makeFullScene's animations: every path and both interpolations.
inline void addFullSceneAnimations(Scene& s)
{
    AnimationChannel translate{1, AnimationPath::Translation, Interpolation::Linear,
                               {0.0f, 0.5f, 1.25f},
                               {{0, 0, 0, 0}, {1, 0, 0, 0}, {1, 1, 0, 0}}};
    AnimationChannel rotate{0, AnimationPath::Rotation, Interpolation::Step,
                            {0.0f, 1.0f},
                            {{0, 0, 0, 1}, {0, 0.70710677f, 0, 0.70710677f}}};
    AnimationChannel scale{2, AnimationPath::Scale, Interpolation::Linear, {0.25f}, {{2, 2, 2, 0}}};
    s.animations.push_back({"spin — Drehung", {translate, rotate, scale}});
    s.animations.push_back({"step only", {{3, AnimationPath::Scale, Interpolation::Step, {0.0f, 2.0f},
                                           {{1, 1, 1, 0}, {3, 3, 3, 0}}}}});
}

// Every field, every section (deformation aside: pack_deformation_test.cpp), optional
// streams, material extensions and lights present, unicode names.
inline Scene makeFullScene()
{
    Scene s;
    // Two quads (8 vertices, 4 triangles) with all four vertex streams.
    for (int i = 0; i < 8; ++i) {
        const float f = float(i);
        s.vertices.positions.push_back({f * 0.5f, -f, 1.0f / (f + 1.0f)});
        s.vertices.normals.push_back(glm::normalize(glm::vec3{0.1f * f, 1.0f, -0.25f}));
        s.vertices.tangents.push_back({1.0f, 0.0f, 0.0f, i % 2 ? 1.0f : -1.0f});
        s.vertices.uvs.push_back({0.125f * f, 1.0f - 0.0625f * f});
    }
    s.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    s.triangleStats = {
        {0.5f, 0.25f, 12.0f, 0.5f / 12.0f, 0.5f, kTriangleTextured},
        {0.75f, 0.125f, 6.0f, 0.125f, 1.0f / 6.0f, kTriangleTextured},
        {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, kTriangleDegenerate},
        {2.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0},
    };
    s.primitives = {{0, 3, 0}, {3, 3, 1}, {6, 6, kNone}};
    s.meshes = {{"Würfel-網格", 0, 2}, {"plain mesh", 2, 1}};

    addFullSceneMaterials(s);
    addFullSceneNodesAndLights(s);
    addFullSceneAnimations(s);

    s.bounds.min = {-2.0f, -7.0f, 0.0f};
    s.bounds.max = {3.5f, 0.0f, 1.0f};
    s.bounds.center = {0.75f, -3.5f, 0.5f};
    s.bounds.radius = 4.5f;

    s.settings.bakerVersion = "lfd-bake 0.1.0";
    s.settings.sourceFile = "szene_ü.gltf";
    s.settings.displayProfile = "looking-glass-portrait";
    s.settings.viewWidth = 420;
    s.settings.viewHeight = 560;
    s.settings.viewCount = 48;
    s.settings.maxEdgePx = 100.0f;
    s.settings.framingFill = 0.9f;
    s.settings.viewPixelWorld = 0.0125f;
    s.settings.maxTextureSize = 4096;
    return s;
}

// Scene with metadata-only textures, for the TextureProducer path.
inline Scene withoutTexels(Scene s)
{
    for (Texture& t : s.textures) {
        t.texels.clear();
        t.texels.shrink_to_fit();
        t.mips.clear();
    }
    return s;
}

inline void expectSameTexture(const Texture& a, const Texture& b, size_t i)
{
    SCOPED_TRACE("texture " + std::to_string(i));
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.sourceWidth, b.sourceWidth);
    EXPECT_EQ(a.sourceHeight, b.sourceHeight);
    EXPECT_EQ(a.srgb, b.srgb);
    EXPECT_EQ(a.format, b.format);
    ASSERT_EQ(a.mips.size(), b.mips.size());
    for (size_t l = 0; l < a.mips.size(); ++l) {
        EXPECT_EQ(a.mips[l].width, b.mips[l].width);
        EXPECT_EQ(a.mips[l].height, b.mips[l].height);
        EXPECT_EQ(a.mips[l].offset, b.mips[l].offset);
        EXPECT_EQ(a.mips[l].size, b.mips[l].size);
    }
    EXPECT_EQ(a.texels, b.texels);
}

// expectSameScene's vertex streams, indices, triangle statistics, primitives and meshes.
inline void expectSameGeometry(const Scene& a, const Scene& b)
{
    EXPECT_EQ(a.vertices.positions, b.vertices.positions);
    EXPECT_EQ(a.vertices.normals, b.vertices.normals);
    EXPECT_EQ(a.vertices.tangents, b.vertices.tangents);
    EXPECT_EQ(a.vertices.uvs, b.vertices.uvs);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.triangleStats.size(), b.triangleStats.size());
    for (size_t t = 0; t < a.triangleStats.size(); ++t) {
        EXPECT_EQ(a.triangleStats[t].areaWorld, b.triangleStats[t].areaWorld);
        EXPECT_EQ(a.triangleStats[t].areaTexture, b.triangleStats[t].areaTexture);
        EXPECT_EQ(a.triangleStats[t].texelCount, b.triangleStats[t].texelCount);
        EXPECT_EQ(a.triangleStats[t].sizeUv, b.triangleStats[t].sizeUv);
        EXPECT_EQ(a.triangleStats[t].texPerWorld, b.triangleStats[t].texPerWorld);
        EXPECT_EQ(a.triangleStats[t].flags, b.triangleStats[t].flags);
    }
    ASSERT_EQ(a.primitives.size(), b.primitives.size());
    for (size_t p = 0; p < a.primitives.size(); ++p) {
        EXPECT_EQ(a.primitives[p].firstIndex, b.primitives[p].firstIndex);
        EXPECT_EQ(a.primitives[p].indexCount, b.primitives[p].indexCount);
        EXPECT_EQ(a.primitives[p].material, b.primitives[p].material);
    }
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t m = 0; m < a.meshes.size(); ++m) {
        EXPECT_EQ(a.meshes[m].name, b.meshes[m].name);
        EXPECT_EQ(a.meshes[m].firstPrimitive, b.meshes[m].firstPrimitive);
        EXPECT_EQ(a.meshes[m].primitiveCount, b.meshes[m].primitiveCount);
    }
}

// expectSameScene's materials and textures.
inline void expectSameMaterials(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t m = 0; m < a.materials.size(); ++m) {
        const Material& x = a.materials[m];
        const Material& y = b.materials[m];
        SCOPED_TRACE("material " + std::to_string(m));
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.baseColorFactor, y.baseColorFactor);
        EXPECT_EQ(x.emissiveFactor, y.emissiveFactor);
        EXPECT_EQ(x.metallicFactor, y.metallicFactor);
        EXPECT_EQ(x.roughnessFactor, y.roughnessFactor);
        EXPECT_EQ(x.normalScale, y.normalScale);
        EXPECT_EQ(x.occlusionStrength, y.occlusionStrength);
        EXPECT_EQ(x.alphaCutoff, y.alphaCutoff);
        EXPECT_EQ(x.alphaMode, y.alphaMode);
        EXPECT_EQ(x.doubleSided, y.doubleSided);
        EXPECT_EQ(x.baseColorTexture, y.baseColorTexture);
        EXPECT_EQ(x.metallicRoughnessTexture, y.metallicRoughnessTexture);
        EXPECT_EQ(x.normalTexture, y.normalTexture);
        EXPECT_EQ(x.occlusionTexture, y.occlusionTexture);
        EXPECT_EQ(x.emissiveTexture, y.emissiveTexture);
        EXPECT_EQ(x.unlit, y.unlit);
        for (uint32_t slot = 0; slot < kTextureSlotCount; ++slot) {
            EXPECT_EQ(x.textureTransforms[slot].linear, y.textureTransforms[slot].linear) << "slot " << slot;
            EXPECT_EQ(x.textureTransforms[slot].offset, y.textureTransforms[slot].offset) << "slot " << slot;
        }
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (size_t t = 0; t < a.textures.size(); ++t)
        expectSameTexture(a.textures[t], b.textures[t], t);
}

// expectSameScene's nodes and animations.
inline void expectSameNodesAndAnimations(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (size_t n = 0; n < a.nodes.size(); ++n) {
        const Node& x = a.nodes[n];
        const Node& y = b.nodes[n];
        SCOPED_TRACE("node " + std::to_string(n));
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.parent, y.parent);
        EXPECT_EQ(x.mesh, y.mesh);
        EXPECT_EQ(x.translation, y.translation);
        EXPECT_EQ(x.rotation.x, y.rotation.x);
        EXPECT_EQ(x.rotation.y, y.rotation.y);
        EXPECT_EQ(x.rotation.z, y.rotation.z);
        EXPECT_EQ(x.rotation.w, y.rotation.w);
        EXPECT_EQ(x.scale, y.scale);
    }
    ASSERT_EQ(a.animations.size(), b.animations.size());
    for (size_t i = 0; i < a.animations.size(); ++i) {
        SCOPED_TRACE("animation " + std::to_string(i));
        EXPECT_EQ(a.animations[i].name, b.animations[i].name);
        ASSERT_EQ(a.animations[i].channels.size(), b.animations[i].channels.size());
        for (size_t c = 0; c < a.animations[i].channels.size(); ++c) {
            const AnimationChannel& x = a.animations[i].channels[c];
            const AnimationChannel& y = b.animations[i].channels[c];
            EXPECT_EQ(x.node, y.node);
            EXPECT_EQ(x.path, y.path);
            EXPECT_EQ(x.interpolation, y.interpolation);
            EXPECT_EQ(x.times, y.times);
            EXPECT_EQ(x.values, y.values);
        }
    }
}

// expectSameScene's lights, bounds and bake settings.
inline void expectSameLightsBoundsAndSettings(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const Light& x = a.lights[i];
        const Light& y = b.lights[i];
        SCOPED_TRACE("light " + std::to_string(i));
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.type, y.type);
        EXPECT_EQ(x.node, y.node);
        EXPECT_EQ(x.color, y.color);
        EXPECT_EQ(x.intensity, y.intensity);
        EXPECT_EQ(x.range, y.range);
        EXPECT_EQ(x.innerConeAngle, y.innerConeAngle);
        EXPECT_EQ(x.outerConeAngle, y.outerConeAngle);
    }
    EXPECT_EQ(a.bounds.min, b.bounds.min);
    EXPECT_EQ(a.bounds.max, b.bounds.max);
    EXPECT_EQ(a.bounds.center, b.bounds.center);
    EXPECT_EQ(a.bounds.radius, b.bounds.radius);
    EXPECT_EQ(a.settings.bakerVersion, b.settings.bakerVersion);
    EXPECT_EQ(a.settings.sourceFile, b.settings.sourceFile);
    EXPECT_EQ(a.settings.displayProfile, b.settings.displayProfile);
    EXPECT_EQ(a.settings.viewWidth, b.settings.viewWidth);
    EXPECT_EQ(a.settings.viewHeight, b.settings.viewHeight);
    EXPECT_EQ(a.settings.viewCount, b.settings.viewCount);
    EXPECT_EQ(a.settings.maxEdgePx, b.settings.maxEdgePx);
    EXPECT_EQ(a.settings.framingFill, b.settings.framingFill);
    EXPECT_EQ(a.settings.viewPixelWorld, b.settings.viewPixelWorld);
    EXPECT_EQ(a.settings.maxTextureSize, b.settings.maxTextureSize);
}

// Exact comparison of every field (floats compared with ==: the format stores bits).
inline void expectSameScene(const Scene& a, const Scene& b)
{
    expectSameGeometry(a, b);
    expectSameMaterials(a, b);
    expectSameNodesAndAnimations(a, b);
    expectSameLightsBoundsAndSettings(a, b);
}

// --- Byte-level access for the rejection tests -------------------------------------

inline pack::FileHeader headerOf(const std::vector<uint8_t>& bytes)
{
    pack::FileHeader h;
    std::memcpy(&h, bytes.data(), sizeof h);
    return h;
}

inline void setHeader(std::vector<uint8_t>& bytes, const pack::FileHeader& h)
{
    std::memcpy(bytes.data(), &h, sizeof h);
}

// Index of the table entry with `tag`, or nullopt.
inline std::optional<uint32_t> entryIndex(const std::vector<uint8_t>& bytes, uint32_t tag)
{
    const pack::FileHeader h = headerOf(bytes);
    for (uint32_t i = 0; i < h.sectionCount; ++i) {
        pack::SectionEntry e;
        std::memcpy(&e, bytes.data() + sizeof h + i * sizeof e, sizeof e);
        if (e.tag == tag)
            return i;
    }
    return std::nullopt;
}

inline pack::SectionEntry entryAt(const std::vector<uint8_t>& bytes, uint32_t i)
{
    pack::SectionEntry e;
    std::memcpy(&e, bytes.data() + sizeof(pack::FileHeader) + i * sizeof e, sizeof e);
    return e;
}

inline void setEntry(std::vector<uint8_t>& bytes, uint32_t i, const pack::SectionEntry& e)
{
    std::memcpy(bytes.data() + sizeof(pack::FileHeader) + i * sizeof e, &e, sizeof e);
}

inline pack::SectionEntry entryFor(const std::vector<uint8_t>& bytes, uint32_t tag)
{
    const auto i = entryIndex(bytes, tag);
    EXPECT_TRUE(i.has_value()) << "no section " << pack::tagName(tag);
    return entryAt(bytes, i.value_or(0));
}

// Reads / writes element `i` of section `tag` as a T (a record or a plain value).
template <typename T>
T readElement(const std::vector<uint8_t>& bytes, uint32_t tag, uint64_t i, size_t byteOffset = 0)
{
    const pack::SectionEntry e = entryFor(bytes, tag);
    T value;
    std::memcpy(&value, bytes.data() + e.offset + i * e.stride + byteOffset, sizeof value);
    return value;
}

template <typename T>
void writeElement(std::vector<uint8_t>& bytes, uint32_t tag, uint64_t i, const T& value, size_t byteOffset = 0)
{
    const pack::SectionEntry e = entryFor(bytes, tag);
    std::memcpy(bytes.data() + e.offset + i * e.stride + byteOffset, &value, sizeof value);
}

// The name the rejection helpers read packs as.
inline const std::string kTestPackName = "test.lfdpack";

// The reader's rejection of `bytes` read as `name`: the PackError message, checked to be one
// line that starts "<name>: " (a line break in the name shows as a space); "" with a test
// failure when the pack was accepted.
inline std::string packRejection(const std::vector<uint8_t>& bytes, const std::string& name = kTestPackName)
{
    try {
        readPackFromMemory(bytes.data(), bytes.size(), name);
    } catch (const PackError& e) {
        const std::string what = e.what();
        std::string shownName = name;
        std::replace(shownName.begin(), shownName.end(), '\n', ' ');
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind(shownName + ": ", 0), 0u) << what;
        return what;
    }
    ADD_FAILURE() << "pack of " << bytes.size() << " bytes was accepted";
    return "";
}

// Expects the reader to reject `bytes` with a one-line message that contains `needle`.
inline void expectPackRejected(const std::vector<uint8_t>& bytes, const std::string& needle)
{
    const std::string what = packRejection(bytes);
    EXPECT_NE(what.find(needle), std::string::npos) << "message: " << what << "\nexpected: " << needle;
}

} // namespace lfd::test
