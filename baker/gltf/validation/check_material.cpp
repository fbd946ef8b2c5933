// Materials (glTF 2.0 sections 3.9, 5.19-5.22) with the material extensions the baker
// reads (KHR_texture_transform, KHR_materials_unlit, KHR_materials_emissive_strength):
// schema phase only. (A texture's TEXCOORD set on a primitive: check_mesh.cpp.)
#include "validation/checks.h"

#include <cstring>

namespace lfd::bake::gltf {
namespace {

// KHR_texture_transform (extension specification, "Properties"): offset and scale are
// two numbers, rotation a number, texCoord an index of a TEXCOORD set.
void textureTransform(ValidationContext& ctx, const json& t, const std::string& path)
{
    ctx.numbers(t, "offset", path, 2, kRead);
    ctx.numberMember(t, "rotation", path, kRead);
    ctx.numbers(t, "scale", path, 2, kRead);
    ctx.integer(t, "texCoord", path, kRead, false, 0);
    ctx.common(t, path);
}

// textureInfo / normalTextureInfo / occlusionTextureInfo (sections 5.22, 5.20, 5.21).
void textureInfo(ValidationContext& ctx, const json& m, const char* key, const std::string& path)
{
    const json* info = ctx.object(m, key, path, kRead);
    if (info == nullptr)
        return;
    const std::string p = at(path, key);
    if (std::strcmp(key, "normalTexture") == 0)
        ctx.number(*info, "scale", p, -1e308, 1e308);
    if (std::strcmp(key, "occlusionTexture") == 0)
        ctx.number(*info, "strength", p, 0.0, 1.0);
    ctx.integer(*info, "texCoord", p, kRead, false, 0);
    ctx.indexMember(*info, "index", p, "textures", kRead, true);
    ctx.common(*info, p);
    if (const json* transform = extensionObject(*info, "KHR_texture_transform"))
        textureTransform(ctx, *transform, at(at(p, "extensions"), "KHR_texture_transform"));
}

} // namespace

void checkMaterialSchema(ValidationContext& ctx, const json& m, const std::string& path)
{
    if (const json* pbr = ctx.object(m, "pbrMetallicRoughness", path, kRead)) {
        const std::string p = at(path, "pbrMetallicRoughness");
        ctx.factors(*pbr, "baseColorFactor", p, 4);
        textureInfo(ctx, *pbr, "baseColorTexture", p);
        ctx.number(*pbr, "metallicFactor", p, 0.0, 1.0);
        ctx.number(*pbr, "roughnessFactor", p, 0.0, 1.0);
        textureInfo(ctx, *pbr, "metallicRoughnessTexture", p);
        ctx.common(*pbr, p);
    }
    textureInfo(ctx, m, "normalTexture", path);
    textureInfo(ctx, m, "occlusionTexture", path);
    textureInfo(ctx, m, "emissiveTexture", path);
    ctx.factors(m, "emissiveFactor", path, 3);
    // An unknown alphaMode is replaced by the default (a warning: the bake goes on).
    ctx.enumString(m, "alphaMode", path, {"OPAQUE", "MASK", "BLEND"}, kIgnored, false, ": treated as OPAQUE");
    ctx.number(m, "alphaCutoff", path, 0.0, 1e308);
    ctx.boolean(m, "doubleSided", path, kRead);
    ctx.common(m, path);
    // KHR_materials_unlit has no properties (an object: common()); emissive strength:
    if (const json* ext = member(m, "extensions"); ext != nullptr && ext->is_object())
        if (const json* strength = member(*ext, "KHR_materials_emissive_strength");
            strength != nullptr && strength->is_object())
            ctx.number(*strength, "emissiveStrength", at(at(path, "extensions"), "KHR_materials_emissive_strength"),
                       0.0, 1e308);
}

} // namespace lfd::bake::gltf
