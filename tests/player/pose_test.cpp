// The pose pass (player/scene/scene_poser.h): the GPU pose against the CPU reference
// (lfd::poseVertices) - streams and per-triangle statistics - and whole frames of an
// animated skinned and morphed scene against the same geometry posed on the CPU and baked
// static, for mvr and lfdpr; the views change between frames with the turntable still.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "skinned_test_scene.h"
#include "test_scenes.h"

#include "bake.h"
#include "gltf_import.h"
#include "triangle_stats.h"
#include "gpu_scene.h"
#include "image_metrics.h"
#include "scene_bindings.h"

#include "lfd/pack.h"
#include "lfd/scene_animation.h"
#include "lfd/scene_pose.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace lfd::test {
namespace {

// The arm with a checker texture on it (so lfdpr's texture terms are exercised) and the
// baker's statistics and bounds.
Scene texturedArm()
{
    Scene s = skinnedArmScene(41);
    s.textures.push_back(checkerTexture(64, 8, {220, 180, 40, 255}, {40, 90, 200, 255}, true));
    Material m;
    m.baseColorTexture = 0;
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    m.doubleSided = true;
    s.materials.push_back(m);
    for (Primitive& p : s.primitives)
        p.material = 0;
    finishScene(s);
    return s;
}

// The same geometry posed on the CPU at `time` and baked static: no deformation, no
// weight channels, statistics of the posed triangles; the animated scene's bounds (so
// both are framed alike).
Scene posedStatic(const Scene& animated, float time)
{
    Scene s = animated;
    VertexStreams posed = s.vertices;
    poseVertices(s, poseInputs(s, time, nodeWorldMatrices(s, time)), posed);
    posed.deform = DeformationStreams{};
    s.vertices = std::move(posed);
    s.deformers.clear();
    s.skins.clear();
    for (Animation& a : s.animations)
        std::erase_if(a.channels, [](const AnimationChannel& c) { return c.path == AnimationPath::Weights; });
    bake::computeTriangleStats(s);
    return s;
}

template <class T>
std::vector<T> readBuffer(unsigned buffer, size_t count)
{
    std::vector<T> out(count);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(count * sizeof(T)), out.data());
    return out;
}

class PoseTest : public GlTest {};

TEST_F(PoseTest, GpuPoseMatchesTheCpuReference)
{
    const Scene scene = texturedArm();
    player::GpuScene gpu(scene);
    ASSERT_TRUE(gpu.deforms());
    for (float t : {0.0f, 0.4f, 1.0f, 1.7f}) {
        SCOPED_TRACE("t " + std::to_string(t));
        gpu.update(t);
        gpu.pose();
        const Scene reference = posedStatic(scene, t);
        namespace b = player::bindings;
        const auto positions = readBuffer<glm::vec3>(gpu.streamBuffer(b::kAttribPosition), scene.vertices.size());
        const auto normals = readBuffer<glm::vec3>(gpu.streamBuffer(b::kAttribNormal), scene.vertices.size());
        const auto stats = readBuffer<TriangleStats>(gpu.triangleStatsBuffer(), scene.triangleCount());
        float worstPosition = 0.0f, worstNormal = 0.0f, worstArea = 0.0f;
        for (size_t v = 0; v < positions.size(); ++v) {
            worstPosition = std::max(worstPosition, glm::length(positions[v] - reference.vertices.positions[v]));
            worstNormal = std::max(worstNormal, glm::length(normals[v] - reference.vertices.normals[v]));
        }
        for (size_t i = 0; i < stats.size(); ++i) {
            const TriangleStats& r = reference.triangleStats[i];
            worstArea = std::max(worstArea, std::abs(stats[i].areaWorld - r.areaWorld) / std::max(r.areaWorld, 1e-6f));
            EXPECT_EQ(stats[i].flags, r.flags) << i;
            EXPECT_NEAR(stats[i].texPerWorld, r.texPerWorld, 1e-3f * std::max(1.0f, r.texPerWorld)) << i;
        }
        EXPECT_LT(worstPosition, 1e-5f);
        EXPECT_LT(worstNormal, 1e-5f);
        EXPECT_LT(worstArea, 1e-4f);
    }
}

TEST_F(PoseTest, AnimatedFramesMatchTheCpuPosedStaticBakeForMvrAndLfdpr)
{
    const Scene scene = texturedArm();
    const DisplayProfile profile = smallProfile(4, 160, 120);
    for (const char* renderer : {"mvr", "lfdpr"}) {
        std::vector<metrics::Image> first;
        for (float t : {0.3f, 1.0f, 1.6f}) {
            SCOPED_TRACE(std::string(renderer) + " t " + std::to_string(t));
            RenderRequest request;
            request.time = t;
            request.eia = true;
            const RenderedFrame animated = renderFrame(renderer, scene, profile, request);
            const RenderedFrame reference = renderFrame(renderer, posedStatic(scene, t), profile, request);
            for (size_t v = 0; v < animated.views.size(); ++v)
                EXPECT_GE(metrics::ssim(reference.views[v], animated.views[v]), 0.999) << "view " << v;
            EXPECT_GE(metrics::ssim(reference.eia, animated.eia), 0.999) << "EIA";
            EXPECT_TRUE(animated.stageMs.count("pose") == 0 || animated.stageMs.at("pose") >= 0.0);
            if (first.empty())
                first = animated.views;
            else // the turntable is still: only the pose moves the views
                EXPECT_LT(metrics::ssim(first[0], animated.views[0]), 0.99);
        }
    }
}

// Debian's simple_skin (a skinned strip, one rotating joint) and AnimatedMorphCube (two
// morph targets, weights animated) animate on the GPU: their views change over time, and
// match their CPU-posed static bakes.
TEST_F(PoseTest, SimpleSkinAndAnimatedMorphCubeAnimate)
{
    const std::string assimp = "/usr/share/assimp/models/glTF2/";
    for (const char* file : {"simple_skin/simple_skin.gltf", "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"}) {
        SCOPED_TRACE(file);
        if (!std::filesystem::exists(assimp + file))
            GTEST_SKIP() << assimp + file << " absent (Debian assimp-testmodels)";
        Scene scene = bake::importGltf(assimp + file, bake::Log{}).scene;
        finishScene(scene);
        ASSERT_FALSE(scene.deformers.empty());
        const DisplayProfile profile = smallProfile(2, 160, 120);
        RenderRequest a, b;
        a.time = 0.25;
        b.time = 1.25;
        const RenderedFrame first = renderFrame("mvr", scene, profile, a);
        const RenderedFrame second = renderFrame("mvr", scene, profile, b);
        EXPECT_LT(metrics::ssim(first.views[0], second.views[0]), 0.99);
        const RenderedFrame reference = renderFrame("mvr", posedStatic(scene, 1.25f), profile, b);
        EXPECT_GE(metrics::ssim(reference.views[0], second.views[0]), 0.999);
    }
}

// The character sample (lfd-make-samples --scene character: a textured four-bone limb
// with an animated morph target), as the baker imports it: its views change between
// frames with the turntable still, and its EIA matches the CPU-posed static bake (SSIM
// >= 0.999) at several frames, for mvr and lfdpr.
TEST_F(PoseTest, CharacterSampleFramesMatchTheCpuPosedReference)
{
    const std::filesystem::path dir = testOutputDir("pose_character");
    const std::string tool = std::string(LFD_BINARY_DIR) + "/samples/lfd-make-samples";
    ASSERT_EQ(std::system(("'" + tool + "' '" + dir.string() + "' --scene character --quiet").c_str()), 0);
    // The public bake, with the geometry and textures as imported (no simplification, no
    // tessellation, full-size RGBA8 textures).
    bake::BakeOptions options;
    options.input = dir / "character" / "character.gltf";
    options.output = dir / "character.lfdpack";
    options.simplifyPx = 0.0;
    options.maxEdgePx = 1e6;
    options.keepFullTextures = true;
    options.textureCompression = bake::TextureCompression::None;
    bake::bake(options, bake::Log{});
    const Scene scene = readPack(options.output);
    const DisplayProfile profile = smallProfile(4, 192, 144);
    for (const char* renderer : {"mvr", "lfdpr"}) {
        metrics::Image firstView;
        for (float t : {0.25f, 0.75f, 1.5f}) {
            SCOPED_TRACE(std::string(renderer) + " t " + std::to_string(t));
            RenderRequest request;
            request.time = t;
            request.eia = true;
            const RenderedFrame animated = renderFrame(renderer, scene, profile, request);
            const RenderedFrame reference = renderFrame(renderer, posedStatic(scene, t), profile, request);
            const double eiaSsim = metrics::ssim(reference.eia, animated.eia);
            std::printf("character %s t %.2f: EIA SSIM against the CPU-posed bake %.5f\n", renderer, t, eiaSsim);
            EXPECT_GE(eiaSsim, 0.999);
            if (firstView.width == 0)
                firstView = animated.views[1];
            else
                EXPECT_LT(metrics::ssim(firstView, animated.views[1]), 0.99);
        }
    }
}

TEST_F(PoseTest, StaticScenesHaveNoPosePass)
{
    Scene scene = cubeAndSphereScene();
    player::GpuScene gpu(scene);
    EXPECT_FALSE(gpu.deforms());
}

} // namespace
} // namespace lfd::test
