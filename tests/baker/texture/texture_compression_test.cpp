// Block compression (baker/texture/texture_compression.h): the format follows what the materials
// read, each level's blocks decode close to the RGBA8 level they came from (BC4 and BC5
// keep the channels they are for), and the bytes do not depend on the thread count.
#include "texture_compression.h"

#include "mip_chain.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lfd::bake {
namespace {

Texture gradientTexture(uint32_t width, uint32_t height, bool srgb)
{
    Texture t;
    t.width = width;
    t.height = height;
    t.srgb = srgb;
    t.mips = mip::chainLayout(width, height);
    t.texels.resize(mip::chainBytes(t.mips));
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            uint8_t* p = t.texels.data() + (size_t(y) * width + x) * 4;
            p[0] = uint8_t(x * 255 / std::max(1u, width - 1));
            p[1] = uint8_t(y * 255 / std::max(1u, height - 1));
            p[2] = uint8_t((x * 7 + y * 3) & 0xff);
            p[3] = uint8_t(x < width / 2 ? 255 : 40);
        }
    mip::buildChain(t.texels.data(), t.mips, srgb, 1u);
    return t;
}

TEST(TextureCompression, FormatFollowsWhatTheMaterialsRead)
{
    EXPECT_EQ(chooseTextureFormat(kUseColour, true), TextureFormat::Bc1);
    EXPECT_EQ(chooseTextureFormat(kUseColour | kUseAlpha, true), TextureFormat::Bc1); // alpha all 255
    EXPECT_EQ(chooseTextureFormat(kUseColour | kUseAlpha, false), TextureFormat::Bc3);
    EXPECT_EQ(chooseTextureFormat(kUseColour, false), TextureFormat::Bc1); // alpha nobody reads
    EXPECT_EQ(chooseTextureFormat(kUseNormal, true), TextureFormat::Bc5);
    EXPECT_EQ(chooseTextureFormat(kUseNormal | kUseRed, true), TextureFormat::Rgba8);
    EXPECT_EQ(chooseTextureFormat(kUseRed, true), TextureFormat::Bc4);
    EXPECT_EQ(chooseTextureFormat(kUseGreen, true), TextureFormat::Bc4);
    EXPECT_EQ(chooseTextureFormat(kUseGreen | kUseBlue, true), TextureFormat::Bc1);
    EXPECT_EQ(chooseTextureFormat(kUseRed | kUseGreen | kUseBlue, true), TextureFormat::Bc1);
}

TEST(TextureCompression, UsesComeFromEveryMaterialSlot)
{
    Scene scene;
    scene.textures.resize(5);
    Material a;
    a.baseColorTexture = 0;
    a.alphaMode = AlphaMode::Mask;
    a.normalTexture = 1;
    a.metallicRoughnessTexture = 2;
    a.occlusionTexture = 2; // packed ORM
    Material b;
    b.emissiveTexture = 3;
    scene.materials = {a, b};
    const std::vector<uint32_t> uses = textureUses(scene);
    EXPECT_EQ(uses[0], kUseColour | kUseAlpha);
    EXPECT_EQ(uses[1], uint32_t(kUseNormal));
    EXPECT_EQ(uses[2], kUseRed | kUseGreen | kUseBlue);
    EXPECT_EQ(uses[3], uint32_t(kUseColour));
    EXPECT_EQ(uses[4], 0u);
}

TEST(TextureCompression, EveryLevelIsCompressedAndDecodesCloseToItsSource)
{
    for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Bc5}) {
        SCOPED_TRACE(textureFormatName(format));
        Texture t = gradientTexture(64, 40, false);
        const uint32_t uses = format == TextureFormat::Bc5 ? kUseNormal : kUseColour | kUseAlpha;
        ThreadBudget threads(1);
        const CompressedTextureReport r = compressTexture(t, format, uses, threads);
        EXPECT_EQ(t.format, format);
        EXPECT_EQ(r.format, format);
        EXPECT_EQ(t.mips, textureMipChain(64, 40, format));
        EXPECT_EQ(t.texels.size(), textureChainBytes(64, 40, format));
        EXPECT_EQ(r.bytes, t.texels.size());
        EXPECT_GT(r.psnr, 30.0); // smooth gradients compress well
        EXPECT_TRUE(std::isfinite(r.psnr));
    }
}

// BC4 keeps the one channel the materials read, wherever it lies in the source.
TEST(TextureCompression, Bc4KeepsTheChannelThatIsRead)
{
    for (uint32_t use : {uint32_t(kUseRed), uint32_t(kUseGreen), uint32_t(kUseBlue)}) {
        Texture t = gradientTexture(32, 32, false);
        ThreadBudget threads(1);
        const CompressedTextureReport r = compressTexture(t, TextureFormat::Bc4, use, threads);
        EXPECT_GT(r.psnr, 30.0) << "use " << use;
    }
    // Reading G but compressing from R would lose the vertical gradient.
    Texture t = gradientTexture(32, 32, false);
    Texture red = t;
    ThreadBudget threads(1);
    compressTexture(t, TextureFormat::Bc4, kUseGreen, threads);
    compressTexture(red, TextureFormat::Bc4, kUseRed, threads);
    EXPECT_NE(t.texels, red.texels);
}

TEST(TextureCompression, SameBytesForEveryThreadCount)
{
    const Texture source = gradientTexture(256, 96, true);
    Texture one = source, two = source;
    ThreadBudget serial(1), parallel(2);
    compressTexture(one, TextureFormat::Bc1, kUseColour, serial);
    compressTexture(two, TextureFormat::Bc1, kUseColour, parallel);
    EXPECT_EQ(one.texels, two.texels);
}

TEST(TextureCompression, Rgba8AndAlreadyCompressedTexturesAreLeftAsTheyAre)
{
    Texture t = gradientTexture(8, 8, true);
    const std::vector<uint8_t> before = t.texels;
    ThreadBudget threads(1);
    const CompressedTextureReport r = compressTexture(t, TextureFormat::Rgba8, kUseColour, threads);
    EXPECT_EQ(t.texels, before);
    EXPECT_EQ(r.format, TextureFormat::Rgba8);
    EXPECT_TRUE(std::isinf(r.psnr));
    compressTexture(t, TextureFormat::Bc1, kUseColour, threads);
    const std::vector<uint8_t> blocks = t.texels;
    compressTexture(t, TextureFormat::Bc3, kUseColour, threads); // already BC1: untouched
    EXPECT_EQ(t.texels, blocks);
    EXPECT_EQ(t.format, TextureFormat::Bc1);
}

TEST(TextureCompression, OpaqueAlphaLooksAtLevelZero)
{
    Texture t = gradientTexture(8, 8, true);
    EXPECT_FALSE(opaqueAlpha(t));
    for (size_t i = 3; i < t.texels.size(); i += 4)
        t.texels[i] = 255;
    EXPECT_TRUE(opaqueAlpha(t));
}

} // namespace
} // namespace lfd::bake
