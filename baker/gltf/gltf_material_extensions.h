// The material extensions the baker reads (internal to the baker): KHR_texture_transform
// on a material's texture infos and KHR_materials_unlit (Khronos extension
// specifications). Their JSON is checked by gltf_validation.cpp before tinygltf parses
// the file, so these read values of the right types.
#pragma once

#include "lfd/scene.h"

#include <tiny_gltf.h>

#include <array>

namespace lfd::bake::gltf {

// One of a material's five texture infos as the baker uses it.
struct MaterialTextureInfo {
    TextureSlot slot = TextureSlot::BaseColor;
    const char* path = "";       // JSON path below the material ("pbrMetallicRoughness.baseColorTexture")
    bool srgb = false;           // colour data (baseColor, emissive), as opposed to linear data
    int index = -1;              // textures[] index; -1: the slot is empty
    // The TEXCOORD set sampled: KHR_texture_transform's texCoord, where given, overrides
    // the texture info's ("texCoord: Overrides the textureInfo texCoord value if supplied").
    int texCoord = 0;
    TextureTransform transform;  // KHR_texture_transform's offset, rotation and scale; identity without it
};

// The five texture infos of `material`, in TextureSlot order.
std::array<MaterialTextureInfo, kTextureSlotCount> materialTextureInfos(const tinygltf::Material& material);

// KHR_materials_unlit: the material carries the extension (an empty object).
bool isUnlit(const tinygltf::Material& material);

} // namespace lfd::bake::gltf
