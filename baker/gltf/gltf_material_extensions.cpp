// KHR_texture_transform and KHR_materials_unlit, read from tinygltf's extension values
// (see gltf_material_extensions.h).
#include "gltf_material_extensions.h"

namespace lfd::bake::gltf {
namespace {

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name)
{
    const auto it = extensions.find(name);
    return it != extensions.end() && it->second.IsObject() ? &it->second : nullptr;
}

// An array of two numbers, or `fallback` where the property is absent.
glm::vec2 vec2Property(const tinygltf::Value& object, const char* key, glm::vec2 fallback)
{
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        return fallback;
    return {float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble())};
}

// KHR_texture_transform of one texture info: offset (default [0, 0]), rotation (radians,
// default 0), scale (default [1, 1]) and the texCoord override.
void readTextureTransform(const tinygltf::ExtensionMap& extensions, MaterialTextureInfo& info)
{
    const tinygltf::Value* ext = extension(extensions, "KHR_texture_transform");
    if (ext == nullptr)
        return;
    const tinygltf::Value& rotation = ext->Get("rotation");
    info.transform.present = true;
    info.transform.offset = vec2Property(*ext, "offset", glm::vec2(0.0f));
    info.transform.rotation = rotation.IsNumber() ? float(rotation.GetNumberAsDouble()) : 0.0f;
    info.transform.scale = vec2Property(*ext, "scale", glm::vec2(1.0f));
    if (const tinygltf::Value& texCoord = ext->Get("texCoord"); texCoord.IsNumber())
        info.texCoord = texCoord.GetNumberAsInt();
}

template <class Info>
MaterialTextureInfo textureInfo(TextureInfoKind kind, const char* path, bool srgb, const Info& in)
{
    MaterialTextureInfo info;
    info.kind = kind;
    info.path = path;
    info.srgb = srgb;
    info.index = in.index;
    info.texCoord = in.texCoord;
    readTextureTransform(in.extensions, info);
    return info;
}

} // namespace

std::array<MaterialTextureInfo, kTextureInfoCount> materialTextureInfos(const tinygltf::Material& m)
{
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    return {textureInfo(TextureInfoKind::BaseColor, "pbrMetallicRoughness.baseColorTexture", true,
                        pbr.baseColorTexture),
            textureInfo(TextureInfoKind::MetallicRoughness, "pbrMetallicRoughness.metallicRoughnessTexture", false,
                        pbr.metallicRoughnessTexture),
            textureInfo(TextureInfoKind::Normal, "normalTexture", false, m.normalTexture),
            textureInfo(TextureInfoKind::Occlusion, "occlusionTexture", false, m.occlusionTexture),
            textureInfo(TextureInfoKind::Emissive, "emissiveTexture", true, m.emissiveTexture)};
}

bool isUnlit(const tinygltf::Material& material)
{
    return extension(material.extensions, "KHR_materials_unlit") != nullptr;
}

} // namespace lfd::bake::gltf
