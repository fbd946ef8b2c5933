// The texture stage: decode, reduce, mip chain, RGBA8.
#pragma once

#include "imported_scene.h"
#include "parallel.h"
#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace lfd::bake {

struct TextureBakeOptions {
    uint32_t maxSize = 16384;      // larger dimensions are reduced by powers of two
    unsigned threads = 0;          // for the mip chain's row bands (0: one per hardware thread)
    ThreadBudget* pool = nullptr;  // if set, the bands take their threads from it instead
};

// Reads only the image header: source size (for n_tex and reporting) before decoding.
glm::uvec2 probeTextureSize(const TextureSource& source);
// Size the texture will be stored at (power-of-two reductions until <= maxSize).
glm::uvec2 storedTextureSize(glm::uvec2 sourceSize, const TextureBakeOptions& options);

// Decodes, converts to RGBA8, reduces to the stored size, builds the full mip chain
// (box filter in linear light for sRGB textures, plain for data textures). Peak memory
// stays under about two full-size RGBA8 copies of the source. Throws BakeError.
Texture bakeTexture(const TextureSource& source, const TextureBakeOptions& options);

} // namespace lfd::bake
