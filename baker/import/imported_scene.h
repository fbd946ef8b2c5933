// The import stage's result, whatever the input (gltf_import.h, rgbd_import.h): the scene
// and where each texture's pixels come from.
#pragma once

#include "lfd/scene.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::bake {

// Where a texture's pixels come from: an image file, or bytes embedded in the glTF
// (bufferView or data URI). Decoding is deferred to bakeTexture so that only one
// texture is decoded at a time.
struct TextureSource {
    std::string name;                 // for messages
    std::filesystem::path file;       // set for external images
    std::vector<uint8_t> encoded;     // set for embedded images (PNG/JPEG bytes)
    std::string mimeType;
    bool srgb = false;                // used as baseColor/emissive
};

struct ImportedScene {
    Scene scene;                        // textures[] carry name + srgb only
    std::vector<TextureSource> textureSources; // parallel to scene.textures
    std::vector<std::string> warnings;  // also sent to Log::warn
    size_t sourceTriangles = 0;
    // Files read besides the textures' (textureSources[].file): the glTF and its buffers.
    std::vector<std::filesystem::path> filesRead;
};


} // namespace lfd::bake
