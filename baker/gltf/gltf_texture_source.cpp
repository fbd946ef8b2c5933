// Which image a glTF texture shows (see gltf_texture_source.h).
#include "gltf_texture_source.h"

#include "gltf_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

namespace lfd::bake::gltf {
namespace {

using json = nlohmann::json;

bool uses(const json& document, const char* extension)
{
    const auto it = document.find("extensionsUsed");
    return it != document.end() && it->is_array() && std::find(it->begin(), it->end(), json(extension)) != it->end();
}

} // namespace

std::optional<size_t> textureImage(const json& texture)
{
    if (texture.is_object() && texture.contains("extensions") && texture["extensions"].is_object())
        if (auto webp = jsonIndex(texture["extensions"].value(kWebp, json()), "source"))
            return webp;
    return jsonIndex(texture, "source");
}

int textureImage(const tinygltf::Texture& texture)
{
    if (const auto it = texture.extensions.find(kWebp); it != texture.extensions.end()) {
        const tinygltf::Value& source = it->second.Get("source");
        if (source.IsNumber() && source.GetNumberAsInt() >= 0)
            return source.GetNumberAsInt();
    }
    return texture.source;
}

std::vector<std::string> imageMediaTypes(const json& document)
{
    std::vector<std::string> types = {"image/jpeg", "image/png"};
    if (uses(document, kWebp))
        types.push_back("image/webp");
    if (uses(document, kBasisu))
        types.push_back("image/ktx2");
    return types;
}

bool knownMediaType(const json& document, const std::string& type)
{
    const std::vector<std::string> types = imageMediaTypes(document);
    return std::find(types.begin(), types.end(), type) != types.end();
}

std::string describeMediaTypes(const json& document)
{
    std::string out;
    for (const std::string& type : imageMediaTypes(document))
        out += (out.empty() ? "" : ", ") + type;
    return out;
}

} // namespace lfd::bake::gltf
