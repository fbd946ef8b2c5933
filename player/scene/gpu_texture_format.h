// How each pack texture format (lfd::TextureFormat) becomes a GL texture: the internal
// format (block formats upload as they are stored: S3TC for BC1/BC3, RGTC for BC4/BC5),
// the swizzle that makes every format read the same way in the shaders (BC4's one
// channel replicated to RGB, alpha 1 where the format has none), and uploads of whole
// rows (of texels or of 4x4 blocks), so the streamer can upload a level in chunks.
#pragma once

#include "lfd/scene.h"

#include <cstdint>

namespace lfd::player {

struct GlTextureFormat {
    unsigned internalFormat = 0;
    bool compressed = false;
    int swizzle[4] = {0, 0, 0, 0}; // GL_TEXTURE_SWIZZLE_RGBA
};

// Throws gl::GlError when the driver lacks the extension the format needs.
GlTextureFormat glTextureFormat(TextureFormat format, bool srgb);

// A level's texel rows come in units of this many rows (4 for the block formats).
uint32_t rowsPerUnit(TextureFormat format);
// Bytes of one unit of rows of a level `width` texels wide.
uint64_t unitRowBytes(TextureFormat format, uint32_t width);

// Uploads units [firstUnit, firstUnit + units) of `level` (width x height) from `data`.
void uploadLevelRows(unsigned texture, int level, TextureFormat format, const GlTextureFormat& gl, uint32_t width,
                     uint32_t height, uint32_t firstUnit, uint32_t units, const uint8_t* data);

} // namespace lfd::player
