// resolvableTextureSize: textures are reduced only while their texels still outnumber
// detail^2 x the finest view pixels that can land on every triangle using them.
#include "texture_budget.h"

#include <gtest/gtest.h>

namespace {

using lfd::bake::resolvableTextureSize;

// A unit quad (two triangles, uv = position) in mesh 0, textured by texture 0 through
// material 0; texture 1 exists but no material uses it.
lfd::Scene texturedUnitQuad()
{
    lfd::Scene s;
    s.vertices.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    s.vertices.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    s.vertices.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.indices = {0, 1, 2, 0, 2, 3};
    s.primitives = {{0, 6, 0}};
    s.meshes = {{"quad", 0, 1}};
    lfd::Material m;
    m.baseColorTexture = 0;
    s.materials = {m};
    s.textures.resize(2);
    lfd::Node n;
    n.mesh = 0;
    s.nodes = {n};
    return s;
}

TEST(TextureBudget, ReducesToWhatTheFinestPixelsCanResolve)
{
    const lfd::Scene s = texturedUnitQuad();
    // Hand-worked: each triangle has area 0.5 and viewPixelWorld 0.01 puts at most
    // 0.5 / 1e-4 = 5000 pixels on it; detail 2 asks for 4 x 5000 = 20000 texels per
    // triangle, i.e. a fraction 20000 / (0.5 * 1024^2) = 0.0381 of the source. Halving:
    // 512^2 keeps 0.25, 256^2 keeps 0.0625 >= 0.0381, 128^2 would keep 0.0156 < 0.0381.
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(256, 256));
    // detail 1 needs a quarter of that: 0.0095 -> 128^2 keeps 0.0156, 64^2 0.0039 is too few.
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {1.0f}, 1.0), glm::uvec2(128, 128));
    // Non-square sources keep their aspect: 1024x256 -> fraction 20000/(0.5*262144) = 0.153
    // -> 512x128 keeps 0.25, 256x64 0.0625 is too few.
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 256}, 0.01, {1.0f}, 2.0), glm::uvec2(512, 128));
}

TEST(TextureBudget, InstanceScaleNeedsMoreTexels)
{
    const lfd::Scene s = texturedUnitQuad();
    // A node scale of 2 quadruples the world area, so four times the pixels: fraction
    // 0.153 of 1024^2 -> 512^2 (0.25) and no further.
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {2.0f}, 2.0), glm::uvec2(512, 512));
}

TEST(TextureBudget, NeverEnlargesAndKeepsWhatIsNeeded)
{
    const lfd::Scene s = texturedUnitQuad();
    // Pixels 10x finer than the texture: the full source is needed.
    EXPECT_EQ(resolvableTextureSize(s, 0, {64, 64}, 0.001, {1.0f}, 2.0), glm::uvec2(64, 64));
    // An unused texture, a mesh no node draws, or no uvs: nothing to decide, keep it.
    EXPECT_EQ(resolvableTextureSize(s, 1, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(1024, 1024));
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {0.0f}, 2.0), glm::uvec2(1024, 1024));
    lfd::Scene noUv = s;
    noUv.vertices.uvs.clear();
    EXPECT_EQ(resolvableTextureSize(noUv, 0, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(1024, 1024));
}

TEST(TextureBudget, TinyTrianglesCanReduceToOneTexel)
{
    lfd::Scene s = texturedUnitQuad();
    for (glm::vec3& p : s.vertices.positions)
        p *= 1e-4f; // the quad covers a fraction of a pixel
    EXPECT_EQ(resolvableTextureSize(s, 0, {256, 128}, 0.01, {1.0f}, 2.0), glm::uvec2(1, 1));
}

// KHR_texture_transform: the texture's texels per triangle are counted in its own uv
// space, so a tiled texture needs fewer of them. Hand-worked on the unit quad: scale
// (2, 2) puts 4x the texels on each triangle, so the fraction needed at detail 2 drops
// from 0.0381 to 0.0095 -> 128^2 (0.0156), as detail 1 did without the transform.
TEST(TextureBudget, TiledTextureNeedsFewerTexels)
{
    lfd::Scene s = texturedUnitQuad();
    s.materials[0].textureTransforms[0] = lfd::TextureTransform::fromOffsetRotationScale({0.5f, 0.0f}, 0.0f, {2.0f, 2.0f});
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(128, 128));
}

// The same as the uvs transformed by hand, for transforms that enlarge, shrink, rotate
// and mirror.
TEST(TextureBudget, TransformMatchesUvsTransformedByHand)
{
    for (const lfd::TextureTransform& transform :
         {lfd::TextureTransform::fromOffsetRotationScale({0.25f, 0.5f}, 0.6f, {3.0f, 1.5f}),
          lfd::TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, -1.0f, {0.3f, -0.4f}),
          lfd::TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 2.0f, {1.0f, 1.0f})}) {
        lfd::Scene viaMaterial = texturedUnitQuad();
        viaMaterial.materials[0].textureTransforms[0] = transform;
        lfd::Scene byHand = texturedUnitQuad();
        for (glm::vec2& uv : byHand.vertices.uvs)
            uv = transform.apply(uv);
        for (const double pixel : {0.01, 0.003, 0.0005})
            EXPECT_EQ(resolvableTextureSize(viaMaterial, 0, {1024, 512}, pixel, {1.0f}, 2.0),
                      resolvableTextureSize(byHand, 0, {1024, 512}, pixel, {1.0f}, 2.0))
                << pixel;
    }
}

// A texture sampled by two slots needs what the sparser use needs: the base colour tiled
// 4x in area, the occlusion slot untransformed -> the untransformed size (256^2).
TEST(TextureBudget, TextureInTwoSlotsFollowsTheSlotWithFewestTexels)
{
    lfd::Scene s = texturedUnitQuad();
    s.materials[0].occlusionTexture = 0;
    s.materials[0].textureTransforms[0] = lfd::TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {2.0f, 2.0f});
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(256, 256));
    s.materials[0].textureTransforms[3] = lfd::TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {4.0f, 1.0f});
    EXPECT_EQ(resolvableTextureSize(s, 0, {1024, 1024}, 0.01, {1.0f}, 2.0), glm::uvec2(128, 128));
}

} // namespace
