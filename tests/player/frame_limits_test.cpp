// The frame preflight (frame_limits.h) against fake driver limits, with hand-worked numbers.
#include "frame_limits.h"

#include <gtest/gtest.h>

using namespace lfd::player;

namespace {

// A roomy driver: nothing an 8K frame needs comes near these.
FrameLimits roomy()
{
    FrameLimits l;
    l.maxTextureSize = 32768;
    l.maxArrayTextureLayers = 2048;
    l.max3dTextureSize = 16384;
    l.maxTextureBufferTexels = uint64_t(1) << 32;
    l.maxShaderStorageBlockBytes = uint64_t(1) << 34;
    return l;
}

// The 65" panel-matched setting: 72 views of 960x480 on 7680x4320.
FrameShape panelMatched65()
{
    FrameShape s;
    s.views = 72;
    s.viewWidth = 960;
    s.viewHeight = 480;
    s.panelWidth = 7680;
    s.panelHeight = 4320;
    return s;
}

} // namespace

TEST(FrameLimits, NeedsHandWorked)
{
    FrameShape s = panelMatched65();
    // 72 * 960 * 480 = 33,177,600 = 7680 * 4320 view pixels; views 8 B each, EIA 4 B each.
    EXPECT_EQ(frameNeeds(s).totalBytes, 8u * 33177600u + 4u * 33177600u);
    s.viewBuffers = true;
    s.depthTargets = false; // lfdpr: no depth array beside the colours
    s.prefilter = PrefilterPlanes::Volume;
    const FrameNeeds n = frameNeeds(s);
    EXPECT_EQ(n.viewBufferTexels, 33177600u);
    EXPECT_EQ(n.viewBufferBytes, 8u * 33177600u);
    EXPECT_EQ(n.prefilterWidth, 2880u);
    // 4 B colours + 8 B view buffers + 6 B prefilter (3 widths of R16F) per view pixel.
    EXPECT_EQ(n.totalBytes, (4u + 8u + 6u + 4u) * 33177600ull);
    s.supersampleSize = 2; // --ss 2s: targets 1920x960 as well
    EXPECT_EQ(frameNeeds(s).renderWidth, 1920u);
    EXPECT_EQ(frameNeeds(s).viewBufferTexels, 4u * 33177600u);
}

TEST(FrameLimits, EightKFitsARoomyDriver)
{
    FrameShape s = panelMatched65();
    s.viewBuffers = true;
    s.prefilter = PrefilterPlanes::Volume;
    EXPECT_EQ(checkFrameLimits(s, roomy()), std::nullopt);
}

TEST(FrameLimits, TextureBufferTexels)
{
    FrameShape s = panelMatched65();
    s.viewBuffers = true;
    FrameLimits l = roomy();
    l.maxTextureBufferTexels = uint64_t(1) << 27; // 134,217,728 (llvmpipe)
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt); // 33,177,600 fit
    s.supersampleSize = 2;                           // 132,710,400: still fit
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt);
    s.views = 80; // 80 * 1920 * 960 = 147,456,000 > 2^27; ratio 0.91022, sqrt 0.95406 * 0.999 * 960 = 914.98; 80 * 1828 * 914 fits
    const std::optional<std::string> m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    EXPECT_EQ(*m, "GL_MAX_TEXTURE_BUFFER_SIZE: the lfdpr view buffers (80 views of 1920x960, texels) needs "
                  "147456000, the driver allows 134217728; --view-size 914x457 or --views 72 would fit");
    EXPECT_EQ(m->find('\n'), std::string::npos);
}

TEST(FrameLimits, ShaderStorageBlock)
{
    FrameShape s = panelMatched65();
    s.viewBuffers = true;
    FrameLimits l = roomy();
    l.maxShaderStorageBlockBytes = uint64_t(128) << 20; // 134,217,728 B < 8 * 33,177,600 = 265,420,800
    const std::optional<std::string> m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    // ratio 0.50568, sqrt 0.71111 * 0.999: 681x340; views floor(72 * 0.50568) = 36.
    EXPECT_EQ(*m, "GL_MAX_SHADER_STORAGE_BLOCK_SIZE: the lfdpr view buffers (72 views of 960x480, bytes) needs "
                  "265420800, the driver allows 134217728; --view-size 681x340 or --views 36 would fit");
    s.viewBufferBytesPerPixel = 4; // 32-bit atomics: 132,710,400 B fit
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt);
}

TEST(FrameLimits, PrefilterVolume)
{
    FrameShape s = panelMatched65();
    s.prefilter = PrefilterPlanes::Volume;
    FrameLimits l = roomy();
    l.max3dTextureSize = 2048; // 3 * 960 = 2880 > 2048; 960 * 2048 / 2880 = 682.67
    const std::optional<std::string> m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    EXPECT_EQ(*m, "GL_MAX_3D_TEXTURE_SIZE: the prefiltered planes of --aa view-spatial (3 view widths: 2880x480 x "
                  "72) needs 2880, the driver allows 2048; --view-size 682x341 or --aa none would fit");
    s.prefilter = PrefilterPlanes::Layered; // the array form uses GL_MAX_TEXTURE_SIZE: fits
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt);
}

TEST(FrameLimits, LayersAndTextureSize)
{
    FrameShape s = panelMatched65();
    FrameLimits l = roomy();
    l.maxArrayTextureLayers = 64;
    std::optional<std::string> m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    EXPECT_EQ(*m, "GL_MAX_ARRAY_TEXTURE_LAYERS: the view targets (72 views of 960x480) needs 72, the driver "
                  "allows 64; --views 64 would fit");
    l = roomy();
    l.maxTextureSize = 4096; // views fit, the 7680-wide EIA does not
    m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    EXPECT_NE(m->find("GL_MAX_TEXTURE_SIZE: the EIA (panel 7680x4320) needs 7680"), std::string::npos) << *m;
}

TEST(FrameLimits, GpuMemory)
{
    FrameShape s = panelMatched65(); // 12 B * 33,177,600 = 398,131,200 B = 0.37 GiB
    FrameLimits l = roomy();
    l.availableBytes = 398131200;
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt);
    // 232,243,200 B free: the views' 265,420,800 B must fit in 232,243,200 - 132,710,400
    // = 99,532,800 (ratio 0.375, sqrt 0.61237 * 0.999 -> 587x293, views 27).
    l.availableBytes = 232243200;
    const std::optional<std::string> m = checkFrameLimits(s, l);
    ASSERT_TRUE(m);
    EXPECT_EQ(*m, "GPU memory (GL_NVX_gpu_memory_info / GL_ATI_meminfo): the frame (72 views of 960x480) needs "
                  "0.37 GiB, the driver reports 0.22 GiB free; --view-size 587x293 or --views 27 would fit");
    l.availableBytes.reset(); // not reported: not checked
    EXPECT_EQ(checkFrameLimits(s, l), std::nullopt);
}
