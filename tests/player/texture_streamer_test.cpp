// Streaming (docs/player/streaming.md): a mapped pack uploaded chunk by chunk renders exactly
// what the eager upload renders once resident; levels arrive coarsest first and the
// sampled levels follow what is resident; the GPU memory plan drops top mips to fit a
// budget or GL_MAX_TEXTURE_SIZE and refuses geometry that cannot fit.
#include "gl_test_support.h"
#include "test_scenes.h"

#include "player_session.h"

#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

class TextureStreamerTest : public GlTest {};

DisplayProfile streamerProfile() { return withViews(prototypeDisplayProfile(), 4, 32, 24); }

fs::path writeScene(const std::string& name, const Scene& scene)
{
    const fs::path path = fs::temp_directory_path() / ("lfd_streamer_" + std::to_string(::getpid()) + "_" + name);
    writePack(path, scene);
    return path;
}

GLint baseLevel(unsigned texture)
{
    GLint level = -1;
    glGetTextureParameteriv(texture, GL_TEXTURE_BASE_LEVEL, &level);
    return level;
}

TEST_F(TextureStreamerTest, StreamedUploadRendersTheSameViewsAsEagerOnceResident)
{
    const fs::path path = writeScene("same.lfdpack", cubeAndSphereScene());
    player::PlayOptions options;
    player::PlayerSession eager(options, streamerProfile(), readPack(path), "same.lfdpack");
    eager.renderFrame(0.0);
    const player::FrameOutputs want = eager.readOutputs(0);

    options.streamChunkBytes = 4096; // many chunks, partial levels
    player::PlayerSession streamed(options, streamerProfile(), std::make_shared<MappedPack>(path), "same.lfdpack");
    ASSERT_NE(streamed.streamer(), nullptr);
    streamed.streamer()->untilResident();
    EXPECT_TRUE(streamed.streamer()->resident());
    EXPECT_EQ(streamed.streamer()->uploadedBytes(), streamed.streamer()->totalBytes());
    EXPECT_EQ(streamed.scene().gpuBytes(), eager.scene().gpuBytes());
    streamed.renderFrame(0.0);
    const player::FrameOutputs got = streamed.readOutputs(0);
    ASSERT_EQ(got.views.size(), want.views.size());
    for (size_t v = 0; v < want.views.size(); ++v)
        EXPECT_TRUE(got.views[v] == want.views[v]) << "view " << v;
    fs::remove(path);
}

TEST_F(TextureStreamerTest, LevelsArriveCoarsestFirstAndTheBaseLevelFollowsThem)
{
    const fs::path path = writeScene("order.lfdpack", cubeAndSphereScene());
    player::PlayOptions options;
    options.streamChunkBytes = 4096;
    player::PlayerSession session(options, streamerProfile(), std::make_shared<MappedPack>(path), "order.lfdpack");
    player::TextureStreamer& streamer = *session.streamer();
    const player::GpuScene& scene = session.scene();
    ASSERT_FALSE(scene.cpu().textures.empty());
    const unsigned texture = scene.texture(0);
    const GLint levels = GLint(scene.textureLayout(0).levels);
    ASSERT_GT(levels, 3);

    // Nothing resident: the clamp already points at the coarsest level.
    EXPECT_EQ(baseLevel(texture), levels - 1);
    EXPECT_FALSE(streamer.renderable());
    streamer.untilRenderable();
    EXPECT_EQ(streamer.residentLevels(0), 1u);
    EXPECT_EQ(baseLevel(texture), levels - 1);

    // With only the 1x1 level resident the views are those of a pack whose texture is that
    // 1x1 level alone: nothing finer (not yet uploaded, undefined) is sampled.
    session.renderFrame(0.0);
    const player::FrameOutputs coarse = session.readOutputs(0);
    Scene onlyCoarsest = cubeAndSphereScene();
    Texture& t = onlyCoarsest.textures[0];
    t.texels = std::vector<uint8_t>(t.texels.end() - 4, t.texels.end());
    t.width = t.height = 1;
    t.mips = {MipLevel{1, 1, 0, 4}};
    player::PlayerSession reference(options, streamerProfile(), onlyCoarsest, "coarsest");
    reference.renderFrame(0.0);
    const player::FrameOutputs want = reference.readOutputs(0);
    ASSERT_EQ(coarse.views.size(), want.views.size());
    for (size_t v = 0; v < want.views.size(); ++v)
        EXPECT_TRUE(coarse.views[v] == want.views[v]) << "view " << v;

    // Step chunk by chunk: the base level only goes down, by one level per finished level.
    GLint previous = baseLevel(texture);
    while (!streamer.resident()) {
        streamer.step(1);
        const GLint now = baseLevel(texture);
        EXPECT_LE(now, previous);
        EXPECT_EQ(now, levels - GLint(streamer.residentLevels(0)));
        previous = now;
    }
    EXPECT_EQ(baseLevel(texture), 0);
    fs::remove(path);
}

TEST_F(TextureStreamerTest, CorruptTexelsFailTheUploadWithOneLineNamingTheFile)
{
    std::vector<uint8_t> bytes = writePackToMemory(cubeAndSphereScene());
    pack::FileHeader header{};
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.sectionCount; ++i) {
        pack::SectionEntry e{};
        std::memcpy(&e, bytes.data() + sizeof header + i * sizeof e, sizeof e);
        if (e.tag == pack::kTagTexels)
            bytes[size_t(e.offset + 7)] ^= 0x10;
    }
    const fs::path path = fs::temp_directory_path() / ("lfd_streamer_" + std::to_string(::getpid()) + "_bad.lfdpack");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    player::PlayOptions options;
    player::PlayerSession session(options, streamerProfile(), std::make_shared<MappedPack>(path), "bad.lfdpack");
    try {
        session.streamer()->untilResident();
        FAIL() << "corrupt texels accepted";
    } catch (const PackError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
    fs::remove(path);
}

TEST(GpuMemoryPlan, BudgetDropsTopMipsWithAWarningAndRefusesGeometryThatCannotFit)
{
    const Scene scene = cubeAndSphereScene();
    const uint64_t geometry = player::geometryGpuBytes(scene);
    const uint64_t textures = player::textureLevelBytes(scene.textures[0], 0);

    const player::GpuMemoryPlan all = player::planGpuMemory(scene, "s.lfdpack", std::nullopt, 16384);
    EXPECT_EQ(all.droppedLevels[0], 0u);
    EXPECT_TRUE(all.warnings.empty());

    // Room for the geometry and a quarter of the texture: the top level goes.
    const player::GpuMemoryPlan tight = player::planGpuMemory(scene, "s.lfdpack", geometry + textures / 4 + 64, 16384);
    EXPECT_GE(tight.droppedLevels[0], 1u);
    EXPECT_LE(tight.geometryBytes + tight.textureBytes, geometry + textures / 4 + 64);
    ASSERT_EQ(tight.warnings.size(), 1u);
    EXPECT_NE(tight.warnings[0].find(scene.textures[0].name), std::string::npos) << tight.warnings[0];
    EXPECT_NE(tight.warnings[0].find("budget"), std::string::npos) << tight.warnings[0];

    try {
        player::planGpuMemory(scene, "s.lfdpack", geometry / 2, 16384);
        FAIL() << "geometry over budget accepted";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("s.lfdpack"), std::string::npos) << what;
        EXPECT_NE(what.find("geometry needs"), std::string::npos) << what;
        EXPECT_NE(what.find("MiB"), std::string::npos) << what;
    }
}

TEST(GpuMemoryPlan, TexturesOverTheMaxTextureSizeLoseTopMips)
{
    const Scene scene = cubeAndSphereScene(); // a 128x128 texture
    const player::GpuMemoryPlan plan = player::planGpuMemory(scene, "s.lfdpack", std::nullopt, 32);
    EXPECT_EQ(plan.droppedLevels[0], 2u); // 128, 64 dropped; 32 is the new level 0
    ASSERT_EQ(plan.warnings.size(), 1u);
    EXPECT_NE(plan.warnings[0].find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << plan.warnings[0];
    EXPECT_NE(plan.warnings[0].find(scene.textures[0].name), std::string::npos) << plan.warnings[0];
}

TEST_F(TextureStreamerTest, PlannedDropsShapeTheGpuTextureEagerAndStreamed)
{
    const Scene scene = cubeAndSphereScene();
    const player::GpuMemoryPlan plan = player::planGpuMemory(scene, "s.lfdpack", std::nullopt, 32);
    player::GpuSceneOptions eagerOptions;
    eagerOptions.plan = &plan;
    const player::GpuScene eager(scene, eagerOptions);
    GLint width = 0;
    glGetTextureLevelParameteriv(eager.texture(0), 0, GL_TEXTURE_WIDTH, &width);
    EXPECT_EQ(width, 32);
    EXPECT_EQ(eager.textureLayout(0).firstPackLevel, 2u);

    // Streamed with the same drops: the same texels arrive at the same GL levels.
    const fs::path path = writeScene("drops.lfdpack", scene);
    auto mapped = std::make_shared<MappedPack>(path);
    player::GpuSceneOptions streamedOptions = eagerOptions;
    streamedOptions.streamed = true;
    player::GpuScene streamed(mapped->scene(), streamedOptions);
    player::TextureStreamer(streamed, mapped, 4096).untilResident();
    for (GLint level = 0; level < GLint(eager.textureLayout(0).levels); ++level) {
        GLint w = 0, h = 0;
        glGetTextureLevelParameteriv(eager.texture(0), level, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(eager.texture(0), level, GL_TEXTURE_HEIGHT, &h);
        std::vector<uint8_t> a(size_t(w) * size_t(h) * 4), b(a.size());
        glGetTextureImage(eager.texture(0), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(a.size()), a.data());
        glGetTextureImage(streamed.texture(0), level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(b.size()), b.data());
        EXPECT_EQ(a, b) << "level " << level;
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    fs::remove(path);
}

TEST_F(TextureStreamerTest, SessionWithAZeroBudgetRefusesThePack)
{
    const fs::path path = writeScene("zero.lfdpack", cubeAndSphereScene());
    player::PlayOptions options;
    options.gpuMemoryBudgetMiB = 0;
    try {
        player::PlayerSession session(options, streamerProfile(), std::make_shared<MappedPack>(path), "zero.lfdpack");
        FAIL() << "pack accepted with a zero budget";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("zero.lfdpack"), std::string::npos) << e.what();
    }
    fs::remove(path);
}

} // namespace
} // namespace lfd::test
