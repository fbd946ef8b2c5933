// Texel layouts of the texture formats a pack stores (lfd/scene.h TextureFormat).
#include "lfd/scene.h"

#include <algorithm>
#include <bit>

namespace lfd {

const char* textureFormatName(TextureFormat format)
{
    switch (format) {
    case TextureFormat::Rgba8: return "RGBA8";
    case TextureFormat::Bc1: return "BC1";
    case TextureFormat::Bc3: return "BC3";
    case TextureFormat::Bc4: return "BC4";
    case TextureFormat::Bc5: return "BC5";
    }
    return "unknown";
}

bool isBlockCompressed(TextureFormat format) { return format != TextureFormat::Rgba8; }

uint64_t textureLevelBytes(TextureFormat format, uint32_t width, uint32_t height)
{
    if (format == TextureFormat::Rgba8)
        return uint64_t(width) * height * 4;
    const uint64_t blocks = uint64_t((width + 3) / 4) * ((height + 3) / 4);
    const uint64_t blockBytes = (format == TextureFormat::Bc1 || format == TextureFormat::Bc4) ? 8 : 16;
    return blocks * blockBytes;
}

std::vector<MipLevel> textureMipChain(uint32_t width, uint32_t height, TextureFormat format)
{
    // floor(log2(max(w, h))) + 1 levels end at 1x1.
    std::vector<MipLevel> levels(std::bit_width(std::max({width, height, 1u})));
    uint64_t offset = 0;
    for (uint32_t l = 0; l < levels.size(); ++l) {
        MipLevel& level = levels[l];
        level.width = std::max(1u, width >> l);
        level.height = std::max(1u, height >> l);
        level.offset = offset;
        level.size = textureLevelBytes(format, level.width, level.height);
        offset += level.size;
    }
    return levels;
}

uint64_t textureChainBytes(uint32_t width, uint32_t height, TextureFormat format)
{
    uint64_t total = 0;
    for (const MipLevel& level : textureMipChain(width, height, format))
        total += level.size;
    return total;
}

} // namespace lfd
