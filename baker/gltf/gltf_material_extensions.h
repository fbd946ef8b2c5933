// The material extensions the baker reads (internal to the baker): KHR_texture_transform
// on a material's texture infos and KHR_materials_unlit (Khronos extension
// specifications). Their JSON is checked by validation/check_material.cpp before tinygltf
// parses the file, so these read values of the right types. Plain glTF terms: the importer
// turns them into the scene's texture slots and transforms.
#pragma once

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <array>
#include <cstddef>

namespace lfd::bake::gltf {

// A material's five texture infos (glTF 2.0 section 5.19), in this order.
enum class TextureInfoKind { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive };
inline constexpr size_t kTextureInfoCount = 5;

// KHR_texture_transform's values ("Properties"), as the file gives them.
struct TextureInfoTransform {
    bool present = false;   // the texture info has the extension
    glm::vec2 offset{0.0f}; // default [0, 0]
    float rotation = 0.0f;  // radians, default 0
    glm::vec2 scale{1.0f};  // default [1, 1]
};

// One of a material's five texture infos as the baker uses it.
struct MaterialTextureInfo {
    TextureInfoKind kind = TextureInfoKind::BaseColor;
    const char* path = "";       // JSON path below the material ("pbrMetallicRoughness.baseColorTexture")
    bool srgb = false;           // colour data (baseColor, emissive), as opposed to linear data
    int index = -1;              // textures[] index; -1: the slot is empty
    // The TEXCOORD set sampled: KHR_texture_transform's texCoord, where given, overrides
    // the texture info's ("texCoord: Overrides the textureInfo texCoord value if supplied").
    int texCoord = 0;
    TextureInfoTransform transform; // KHR_texture_transform's offset, rotation and scale
};

// The five texture infos of `material`, in TextureInfoKind order.
std::array<MaterialTextureInfo, kTextureInfoCount> materialTextureInfos(const tinygltf::Material& material);

// KHR_materials_unlit: the material carries the extension (an empty object).
bool isUnlit(const tinygltf::Material& material);

} // namespace lfd::bake::gltf
