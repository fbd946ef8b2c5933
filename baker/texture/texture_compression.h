// Block compression of baked textures (docs/baker/texture-compression.md).
//
// Every texture is baked to RGBA8 with its full mip chain first (mip_chain.h: sRGB colour
// filtered in linear light), then each level is compressed on its own, so the mips of a
// compressed texture are the compressed mips of the exact chain. The format follows what
// the scene's materials read from the texture:
//   colour (baseColor, emissive)     BC1, or BC3 when a non-opaque material reads alpha
//                                    and the alpha is not all 255
//   normal map                       BC5 (x, y; the shader rebuilds z)
//   one channel (occlusion R, or a   BC4 of that channel (the sampler replicates it)
//     roughness-only G / metallic-only B)
//   two or three data channels       BC1 (occlusion-roughness-metallic packed)
//   a normal map also read as data   RGBA8 (no single block format fits both)
// Encoder: libsquish (cluster fit on levels up to 1 MP, range fit above; BC4/BC5 through
// its DXT5 alpha-block encoder). Blocks are independent, so bands of block rows are
// compressed in parallel and the bytes do not depend on the thread count.
#pragma once

#include "lfd/scene.h"
#include "parallel.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::bake {

enum class TextureCompression { None, Bc };

// What the materials read from a texture (bit set).
enum TextureUse : uint32_t {
    kUseColour = 1u << 0, // RGB as colour
    kUseAlpha = 1u << 1,  // A (baseColor of a MASK or BLEND material)
    kUseNormal = 1u << 2, // tangent-space normal (x, y, z)
    kUseRed = 1u << 3,    // occlusion
    kUseGreen = 1u << 4,  // roughness
    kUseBlue = 1u << 5,   // metallic
};

// One bit set per texture of `scene` (0 for a texture no material references).
std::vector<uint32_t> textureUses(const Scene& scene);

// The format for a texture read as `uses`; `opaqueAlpha`: every level-0 alpha is 255.
TextureFormat chooseTextureFormat(uint32_t uses, bool opaqueAlpha);
bool opaqueAlpha(const Texture& rgba8);

struct CompressedTextureReport {
    TextureFormat format = TextureFormat::Rgba8;
    uint64_t bytes = 0;  // the whole compressed chain
    double psnr = 0.0;   // level 0 against its RGBA8 source, over the channels read (dB; inf if exact)
};

// Every level of an RGBA8 texture compressed into `format` (a block format), laid out as
// textureMipChain(width, height, format); `psnr`, if given, receives level 0's PSNR.
std::vector<uint8_t> compressChain(const Texture& rgba8, TextureFormat format, uint32_t uses, ThreadBudget& threads,
                                   double* psnr = nullptr);

// Compresses every level of an RGBA8 texture into `format` in place (texels and mips
// replaced). RGBA8 leaves it as it is. `uses` picks BC4's channel and the PSNR channels.
CompressedTextureReport compressTexture(Texture& texture, TextureFormat format, uint32_t uses, ThreadBudget& threads);

// The bake's compression of one baked RGBA8 texture read as `uses`: kept RGBA8 with
// TextureCompression::None, otherwise compressed into chooseTextureFormat's format.
CompressedTextureReport compressForUses(Texture& texture, uint32_t uses, TextureCompression compression,
                                        ThreadBudget& threads);

} // namespace lfd::bake
