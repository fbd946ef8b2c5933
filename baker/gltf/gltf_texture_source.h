// Which image a glTF texture shows, with the image-format extensions (internal to the
// baker). EXT_texture_webp: `texture.extensions.EXT_texture_webp.source` names a WebP
// image, and the core `source`, when present, is the fallback for loaders without WebP;
// the baker decodes WebP (texture_webp.h), so it takes the WebP image, the one the author
// intended. KHR_texture_basisu: its KTX2 image is never taken (Debian 12 packages no
// decoder); the core `source` (PNG or JPEG) is. Specifications: the two extensions'
// READMEs, "glTF Schema Updates".
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

inline constexpr const char* kWebp = "EXT_texture_webp";
inline constexpr const char* kBasisu = "KHR_texture_basisu";

// The image texture `texture` (its JSON) shows, or nullopt when it has none the baker
// decodes (no index, or the schema check reported it).
std::optional<size_t> textureImage(const nlohmann::json& texture);
// The same for tinygltf's parse of the texture; -1 when it has none.
int textureImage(const tinygltf::Texture& texture);

// The image media types `document` may use: image/jpeg and image/png (section 3.8.4.4),
// image/webp where it uses EXT_texture_webp, image/ktx2 where it uses KHR_texture_basisu.
std::vector<std::string> imageMediaTypes(const nlohmann::json& document);
bool knownMediaType(const nlohmann::json& document, const std::string& type);
// The same as a list for messages ("image/jpeg, image/png").
std::string describeMediaTypes(const nlohmann::json& document);

} // namespace lfd::bake::gltf
