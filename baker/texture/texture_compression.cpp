// Block compression of baked RGBA8 chains (texture_compression.h).
#include "texture_compression.h"

#include <squish.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace lfd::bake {

namespace {

// Rows of blocks per parallel work item: ~64 KiB of source texels at 4096 wide.
constexpr uint32_t kBlockRowsPerBand = 4;

// BC4 is BC3's alpha block on its own, and BC5 two of them. Debian's libsquish 1.15
// declares kBc4/kBc5 but its Compress treats them as DXT1, so the channel goes through
// the DXT5 alpha encoder and the (constant, range-fit) colour half is dropped.
constexpr int kAlphaBlockFlags = squish::kDxt5 | squish::kColourRangeFit;
// Colour endpoints: cluster fit (squish's default, best of its fast fits) on levels up to
// kClusterFitTexels, range fit (endpoints from the block's principal axis, ~10x faster,
// ~2 dB less PSNR) on larger ones. The baker keeps textures about twice as fine as the
// finest view pixel (texture_budget.cpp), so the views sample mostly level 1 and below:
// the quality goes where it is seen, and the cluster-fit cost is bounded per texture
// (~1.4 MP) whatever its size (docs/baker/texture-compression.md has the measured EIA error).
constexpr uint64_t kClusterFitTexels = uint64_t(1) << 20;

int colourFit(const MipLevel& level)
{
    return uint64_t(level.width) * level.height <= kClusterFitTexels ? squish::kColourClusterFit
                                                                    : squish::kColourRangeFit;
}

void encodeAlphaBlock(const uint8_t block[64], int channel, uint8_t* out)
{
    uint8_t alpha[64] = {};
    for (int i = 0; i < 16; ++i)
        alpha[i * 4 + 3] = block[i * 4 + channel];
    uint8_t dxt5[16];
    squish::Compress(alpha, dxt5, kAlphaBlockFlags);
    std::memcpy(out, dxt5, 8);
}

// Decodes an alpha block into `channel` of 16 RGBA texels.
void decodeAlphaBlock(const uint8_t* in, int channel, uint8_t rgba[64])
{
    uint8_t dxt5[16] = {};
    std::memcpy(dxt5, in, 8);
    uint8_t decoded[64];
    squish::Decompress(decoded, dxt5, squish::kDxt5);
    for (int i = 0; i < 16; ++i)
        rgba[i * 4 + channel] = decoded[i * 4 + 3];
}

// The channel BC4 keeps: the one channel the materials read (R when several or none).
int bc4Channel(uint32_t uses)
{
    if ((uses & (kUseGreen | kUseBlue)) == kUseGreen && !(uses & kUseRed))
        return 1;
    if ((uses & (kUseGreen | kUseBlue)) == kUseBlue && !(uses & kUseRed))
        return 2;
    return 0;
}

// One 4x4 block (RGBA texels, channel already in place for BC4: R) into `format`.
void encodeBlock(const uint8_t block[64], TextureFormat format, int fit, uint8_t* out)
{
    switch (format) {
    case TextureFormat::Bc1: squish::Compress(block, out, squish::kDxt1 | fit); break;
    case TextureFormat::Bc3: squish::Compress(block, out, squish::kDxt5 | fit); break;
    case TextureFormat::Bc4: encodeAlphaBlock(block, 0, out); break;
    case TextureFormat::Bc5:
        encodeAlphaBlock(block, 0, out);
        encodeAlphaBlock(block, 1, out + 8);
        break;
    case TextureFormat::Rgba8: break;
    }
}

// The block as the GPU decodes it: BC4 into R, BC5 into R and G (other channels 0).
void decodeBlock(const uint8_t* in, TextureFormat format, uint8_t rgba[64])
{
    std::memset(rgba, 0, 64);
    switch (format) {
    case TextureFormat::Bc1: squish::Decompress(rgba, in, squish::kDxt1); break;
    case TextureFormat::Bc3: squish::Decompress(rgba, in, squish::kDxt5); break;
    case TextureFormat::Bc4: decodeAlphaBlock(in, 0, rgba); break;
    case TextureFormat::Bc5:
        decodeAlphaBlock(in, 0, rgba);
        decodeAlphaBlock(in + 8, 1, rgba);
        break;
    case TextureFormat::Rgba8: break;
    }
}

// The 4x4 block at (bx, by) of a level as squish reads it (RGBA, 16 texels), edge texels
// repeated past the level's border, the BC4 channel moved to R, and alpha forced to 255
// for BC1 (so squish never picks the 1-bit-alpha mode the RGB format does not have).
void gatherBlock(const uint8_t* level, const MipLevel& mip, uint32_t bx, uint32_t by, TextureFormat format,
                 int channel, uint8_t block[64])
{
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x) {
            const uint32_t sx = std::min(bx * 4 + x, mip.width - 1);
            const uint32_t sy = std::min(by * 4 + y, mip.height - 1);
            const uint8_t* src = level + (size_t(sy) * mip.width + sx) * 4;
            uint8_t* dst = block + (y * 4 + x) * 4;
            std::memcpy(dst, src, 4);
            if (format == TextureFormat::Bc4)
                dst[0] = src[channel];
            if (format == TextureFormat::Bc1)
                dst[3] = 255;
        }
}

void compressLevel(const uint8_t* level, const MipLevel& mip, TextureFormat format, int channel, uint8_t* out,
                   ThreadBudget& threads)
{
    const uint32_t blocksX = (mip.width + 3) / 4, blocksY = (mip.height + 3) / 4;
    const size_t blockBytes = size_t(textureLevelBytes(format, 4, 4));
    const int fit = colourFit(mip);
    const size_t bands = (blocksY + kBlockRowsPerBand - 1) / kBlockRowsPerBand;
    parallelFor(bands, threads, [&](size_t band) {
        uint8_t block[64];
        const uint32_t y0 = uint32_t(band) * kBlockRowsPerBand;
        const uint32_t y1 = std::min(blocksY, y0 + kBlockRowsPerBand);
        for (uint32_t by = y0; by < y1; ++by)
            for (uint32_t bx = 0; bx < blocksX; ++bx) {
                gatherBlock(level, mip, bx, by, format, channel, block);
                encodeBlock(block, format, fit, out + (size_t(by) * blocksX + bx) * blockBytes);
            }
    });
}

// PSNR of level 0's blocks decoded against the RGBA8 source, over the channels read.
double levelPsnr(const uint8_t* source, const MipLevel& mip, const uint8_t* blocks, TextureFormat format,
                 uint32_t uses, int channel)
{
    bool channels[4] = {false, false, false, false};
    if (format == TextureFormat::Bc4)
        channels[channel] = true;
    else if (format == TextureFormat::Bc5)
        channels[0] = channels[1] = true;
    else {
        channels[0] = (uses & (kUseColour | kUseRed)) || !uses;
        channels[1] = (uses & (kUseColour | kUseGreen)) || !uses;
        channels[2] = (uses & (kUseColour | kUseBlue)) || !uses;
        channels[3] = format == TextureFormat::Bc3;
    }
    const uint32_t blocksX = (mip.width + 3) / 4, blocksY = (mip.height + 3) / 4;
    const size_t blockBytes = size_t(textureLevelBytes(format, 4, 4));
    double sum = 0.0;
    uint64_t n = 0;
    uint8_t decoded[64];
    for (uint32_t by = 0; by < blocksY; ++by)
        for (uint32_t bx = 0; bx < blocksX; ++bx) {
            decodeBlock(blocks + (size_t(by) * blocksX + bx) * blockBytes, format, decoded);
            for (uint32_t y = 0; y < 4 && by * 4 + y < mip.height; ++y)
                for (uint32_t x = 0; x < 4 && bx * 4 + x < mip.width; ++x) {
                    const uint8_t* src = source + (size_t(by * 4 + y) * mip.width + bx * 4 + x) * 4;
                    const uint8_t* dec = decoded + (y * 4 + x) * 4;
                    for (int c = 0; c < 4; ++c) {
                        if (!channels[c])
                            continue;
                        // BC4 decodes its channel into R.
                        const int s = format == TextureFormat::Bc4 ? src[channel] : src[c];
                        const int d = format == TextureFormat::Bc4 ? dec[0] : dec[c];
                        sum += double(s - d) * double(s - d);
                        ++n;
                    }
                }
        }
    if (n == 0 || sum == 0.0)
        return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(255.0 * 255.0 / (sum / double(n)));
}

} // namespace

std::vector<uint32_t> textureUses(const Scene& scene)
{
    std::vector<uint32_t> uses(scene.textures.size(), 0);
    auto use = [&](int32_t texture, uint32_t bits) {
        if (texture >= 0 && size_t(texture) < uses.size())
            uses[size_t(texture)] |= bits;
    };
    for (const Material& m : scene.materials) {
        use(m.baseColorTexture, kUseColour | (m.alphaMode != AlphaMode::Opaque ? kUseAlpha : 0u));
        use(m.emissiveTexture, kUseColour);
        use(m.normalTexture, kUseNormal);
        use(m.metallicRoughnessTexture, kUseGreen | kUseBlue);
        use(m.occlusionTexture, kUseRed);
    }
    return uses;
}

TextureFormat chooseTextureFormat(uint32_t uses, bool opaque)
{
    if (uses & kUseNormal)
        return uses == kUseNormal ? TextureFormat::Bc5 : TextureFormat::Rgba8;
    if (uses & kUseColour)
        return (uses & kUseAlpha) && !opaque ? TextureFormat::Bc3 : TextureFormat::Bc1;
    const uint32_t data = uses & (kUseRed | kUseGreen | kUseBlue);
    if (data == kUseRed || data == kUseGreen || data == kUseBlue)
        return TextureFormat::Bc4;
    return TextureFormat::Bc1;
}

bool opaqueAlpha(const Texture& rgba8)
{
    if (rgba8.mips.empty())
        return true;
    const uint64_t bytes = rgba8.mips[0].size;
    for (uint64_t i = 3; i < bytes; i += 4)
        if (rgba8.texels[size_t(i)] != 255)
            return false;
    return true;
}

std::vector<uint8_t> compressChain(const Texture& rgba8, TextureFormat format, uint32_t uses, ThreadBudget& threads,
                                   double* psnr)
{
    const int channel = bc4Channel(uses);
    const std::vector<MipLevel> chain = textureMipChain(rgba8.width, rgba8.height, format);
    std::vector<uint8_t> blocks(size_t(chain.back().offset + chain.back().size));
    for (size_t l = 0; l < chain.size(); ++l)
        compressLevel(rgba8.texels.data() + rgba8.mips[l].offset, rgba8.mips[l], format, channel,
                      blocks.data() + chain[l].offset, threads);
    if (psnr)
        *psnr = levelPsnr(rgba8.texels.data(), rgba8.mips[0], blocks.data(), format, uses, channel);
    return blocks;
}

CompressedTextureReport compressTexture(Texture& texture, TextureFormat format, uint32_t uses, ThreadBudget& threads)
{
    CompressedTextureReport report;
    if (format == TextureFormat::Rgba8 || texture.format != TextureFormat::Rgba8) {
        report.format = texture.format;
        report.bytes = texture.texels.size();
        report.psnr = std::numeric_limits<double>::infinity();
        return report;
    }
    texture.texels = compressChain(texture, format, uses, threads, &report.psnr);
    texture.mips = textureMipChain(texture.width, texture.height, format);
    texture.format = format;
    report.format = format;
    report.bytes = texture.texels.size();
    return report;
}

CompressedTextureReport compressForUses(Texture& texture, uint32_t uses, TextureCompression compression,
                                        ThreadBudget& threads)
{
    const TextureFormat format = compression == TextureCompression::None ? TextureFormat::Rgba8
                                                                         : chooseTextureFormat(uses, opaqueAlpha(texture));
    return compressTexture(texture, format, uses, threads);
}

} // namespace lfd::bake
