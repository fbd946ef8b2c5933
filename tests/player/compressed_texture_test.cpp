// Block-compressed textures (docs/baker/texture-compression.md): every renderer samples a
// BC1/BC4/BC5 texture like the RGBA8 chain it was compressed from (within the codec's
// error, not bit-exact), BC5 normal maps get their z rebuilt (a wrong z would flip the
// shading), streamed block levels - uploaded in partial chunks of block rows - render
// exactly like the eager upload, and the GPU holds the compressed bytes.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "gpu_memory_budget.h"
#include "player_session.h"
#include "renderer_registry.h"
#include "texture_compression.h"

#include "lfd/pack.h"
#include "lfd/pack_mapped.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

class CompressedTextureTest : public GlTest {};

DisplayProfile textureProfile() { return withViews(prototypeDisplayProfile(), 4, 64, 48); }

// A level-0 pattern with a box-filtered chain (byte averages, as the checker does).
Texture patternTexture(uint32_t size, bool srgb, const std::function<glm::u8vec4(uint32_t, uint32_t)>& texel)
{
    Texture tex;
    tex.name = "pattern";
    tex.width = tex.height = tex.sourceWidth = tex.sourceHeight = size;
    tex.srgb = srgb;
    tex.mips = textureMipChain(size, size, TextureFormat::Rgba8);
    tex.texels.resize(size_t(textureChainBytes(size, size, TextureFormat::Rgba8)));
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const glm::u8vec4 c = texel(x, y);
            std::copy(&c[0], &c[0] + 4, &tex.texels[(size_t(y) * size + x) * 4]);
        }
    for (size_t l = 1; l < tex.mips.size(); ++l) {
        const MipLevel& up = tex.mips[l - 1];
        const MipLevel& mip = tex.mips[l];
        for (uint32_t y = 0; y < mip.height; ++y)
            for (uint32_t x = 0; x < mip.width; ++x)
                for (uint32_t c = 0; c < 4; ++c) {
                    uint32_t sum = 0;
                    for (uint32_t k = 0; k < 4; ++k)
                        sum += tex.texels[size_t(up.offset) +
                                          ((size_t(y) * 2 + k / 2) * up.width + x * 2 + k % 2) * 4 + c];
                    tex.texels[size_t(mip.offset) + (size_t(y) * mip.width + x) * 4 + c] = uint8_t((sum + 2) / 4);
                }
    }
    return tex;
}

// cubeAndSphereScene with a fully textured cube: smooth colour (BC1), a bumpy normal map
// (BC5), roughness-metallic (BC1) and occlusion (BC4).
Scene materialScene()
{
    Scene scene = cubeAndSphereScene();
    const float pi = 3.14159265f;
    scene.textures = {
        patternTexture(64, true,
                       [](uint32_t x, uint32_t y) { return glm::u8vec4(60 + x * 2, 200 - y * 2, 90 + (x + y), 255); }),
        patternTexture(64, false,
                       [pi](uint32_t x, uint32_t y) {
                           // Bumps: tilt x and y by up to ~35 degrees.
                           const float nx = 0.55f * std::sin(2 * pi * float(x) / 16.0f);
                           const float ny = 0.55f * std::cos(2 * pi * float(y) / 16.0f);
                           const float nz = std::sqrt(std::max(0.0f, 1.0f - nx * nx - ny * ny));
                           auto b = [](float v) { return uint8_t(std::lround((v * 0.5f + 0.5f) * 255.0f)); };
                           return glm::u8vec4(b(nx), b(ny), b(nz), 255);
                       }),
        patternTexture(64, false,
                       [](uint32_t x, uint32_t y) { return glm::u8vec4(255, 60 + y * 2, x * 3, 255); }),
        patternTexture(64, false, [](uint32_t x, uint32_t y) { return glm::u8vec4(150 + (x ^ y), 0, 0, 255); }),
    };
    Material& cube = scene.materials[0];
    cube.baseColorTexture = 0;
    cube.normalTexture = 1;
    cube.metallicRoughnessTexture = 2;
    cube.occlusionTexture = 3;
    cube.metallicFactor = 1.0f;
    finishScene(scene);
    return scene;
}

Scene blockCompressed(Scene scene)
{
    const std::vector<uint32_t> uses = bake::textureUses(scene);
    ThreadBudget threads(1);
    for (size_t t = 0; t < scene.textures.size(); ++t)
        bake::compressForUses(scene.textures[t], uses[t], bake::TextureCompression::Bc, threads); // as bake() does
    return scene;
}

player::FrameOutputs render(const std::string& renderer, const Scene& scene)
{
    player::PlayOptions options;
    options.renderer = renderer;
    // gstd at 1x and 4 samples: the texture comparison needs its sampling path, not its
    // convergence (its defaults took 4.5 s a frame on llvmpipe here, this about 1.3 s).
    options.rendererOptions = quickGstdOptions();
    player::PlayerSession session(options, textureProfile(), scene, "compressed");
    session.renderFrame(0.0);
    return session.readOutputs(0);
}

double viewsRmse(const player::FrameOutputs& a, const player::FrameOutputs& b)
{
    double sum = 0.0;
    size_t n = 0;
    for (size_t v = 0; v < a.views.size(); ++v)
        for (size_t i = 0; i < a.views[v].size(); ++i) {
            if (i % 4 == 3)
                continue;
            const double d = double(a.views[v][i]) - double(b.views[v][i]);
            sum += d * d;
            ++n;
        }
    return std::sqrt(sum / double(std::max<size_t>(n, 1)));
}

TEST_F(CompressedTextureTest, TheBakerPicksAFormatByWhatTheMaterialsRead)
{
    const Scene scene = blockCompressed(materialScene());
    EXPECT_EQ(scene.textures[0].format, TextureFormat::Bc1); // opaque colour
    EXPECT_EQ(scene.textures[1].format, TextureFormat::Bc5); // normal map
    EXPECT_EQ(scene.textures[2].format, TextureFormat::Bc1); // roughness + metallic
    EXPECT_EQ(scene.textures[3].format, TextureFormat::Bc4); // occlusion alone
}

TEST_F(CompressedTextureTest, EveryRendererSamplesBlockTexturesLikeTheRgba8Source)
{
    const Scene rgba8 = materialScene();
    const Scene blocks = blockCompressed(rgba8);
    // The normal map decoded without the z rebuild (z = 0 after the BC5 swizzle):
    // what a missing LFD_MATERIAL_NORMAL_TWO_CHANNEL would draw.
    Scene flatZ = blocks;
    flatZ.textures[1] = rgba8.textures[1];
    for (size_t i = 2; i < flatZ.textures[1].texels.size(); i += 4)
        flatZ.textures[1].texels[i] = 128;
    for (const char* renderer : {"mvr", "mvr-layered", "lfdpr", "gstd"}) {
        SCOPED_TRACE(renderer);
        const player::FrameOutputs want = render(renderer, rgba8);
        const player::FrameOutputs got = render(renderer, blocks);
        const double error = viewsRmse(want, got);
        EXPECT_LT(error, 2.5) << "block textures must sample like their source";
        EXPECT_GT(error, 0.0) << "the block textures were not used";
        EXPECT_GT(viewsRmse(want, render(renderer, flatZ)), 2.0 * error)
            << "a normal map with a wrong z must be further off than BC5's error";
    }
}

TEST_F(CompressedTextureTest, GpuHoldsTheCompressedBytes)
{
    const Scene rgba8 = materialScene();
    const Scene blocks = blockCompressed(rgba8);
    player::PlayOptions options;
    player::PlayerSession a(options, textureProfile(), rgba8, "rgba8");
    player::PlayerSession b(options, textureProfile(), blocks, "blocks");
    uint64_t rgbaBytes = 0, blockBytes = 0;
    for (size_t t = 0; t < rgba8.textures.size(); ++t) {
        rgbaBytes += rgba8.textures[t].texels.size();
        blockBytes += blocks.textures[t].texels.size();
    }
    EXPECT_EQ(a.scene().gpuBytes() - b.scene().gpuBytes(), rgbaBytes - blockBytes);
    EXPECT_LE(blockBytes * 4, rgbaBytes);
    GLint compressed = 0;
    glGetTextureLevelParameteriv(b.scene().texture(1), 0, GL_TEXTURE_COMPRESSED, &compressed);
    EXPECT_EQ(compressed, GL_TRUE);
    GLint format = 0;
    glGetTextureLevelParameteriv(b.scene().texture(1), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    EXPECT_EQ(format, GL_COMPRESSED_RG_RGTC2);
}

// The GPU memory budget counts the compressed levels: a budget the RGBA8 chains would
// overflow holds the block chains whole, and dropping a top level frees its block bytes.
TEST(CompressedTextureBudget, PlanCountsCompressedBytes)
{
    const Scene blocks = blockCompressed(materialScene());
    uint64_t texels = 0;
    for (const Texture& t : blocks.textures)
        texels += t.texels.size();
    const player::GpuMemoryPlan whole = player::planGpuMemory(blocks, "blocks", std::nullopt, 16384);
    EXPECT_EQ(whole.textureBytes, texels);
    const player::GpuMemoryPlan tight =
        player::planGpuMemory(blocks, "blocks", whole.geometryBytes + texels - 1, 16384);
    EXPECT_LT(tight.textureBytes, texels);
    uint64_t dropped = 0;
    for (size_t t = 0; t < blocks.textures.size(); ++t)
        for (uint32_t l = 0; l < tight.droppedLevels[t]; ++l)
            dropped += blocks.textures[t].mips[l].size;
    EXPECT_EQ(tight.textureBytes, texels - dropped);
}

TEST_F(CompressedTextureTest, StreamedBlockRowsRenderLikeTheEagerUpload)
{
    const fs::path path =
        fs::temp_directory_path() / ("lfd_compressed_" + std::to_string(::getpid()) + ".lfdpack");
    writePack(path, blockCompressed(materialScene()));
    {
        // The smooth test textures' blocks repeat: zstd levels, inflated while streaming.
        const MappedPack mapped(path);
        bool anyZstd = false;
        for (uint32_t t = 0; t < mapped.textures().size(); ++t)
            anyZstd = anyZstd || mapped.levelsZstd(t);
        EXPECT_TRUE(anyZstd);
    }
    player::PlayOptions options;
    player::PlayerSession eager(options, textureProfile(), readPack(path), "eager");
    eager.renderFrame(0.0);
    const player::FrameOutputs want = eager.readOutputs(0);
    options.streamChunkBytes = 4096; // a 64-wide BC5 level is 256 bytes per block row: partial levels
    player::PlayerSession streamed(options, textureProfile(), std::make_shared<MappedPack>(path), "streamed");
    streamed.streamer()->untilResident();
    EXPECT_EQ(streamed.scene().gpuBytes(), eager.scene().gpuBytes());
    streamed.renderFrame(0.0);
    const player::FrameOutputs got = streamed.readOutputs(0);
    ASSERT_EQ(got.views.size(), want.views.size());
    for (size_t v = 0; v < want.views.size(); ++v)
        EXPECT_TRUE(got.views[v] == want.views[v]) << "view " << v;
    fs::remove(path);
}

} // namespace
} // namespace lfd::test
