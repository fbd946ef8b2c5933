// Paper eqs. texelCount (n_tex = max_t A_ts * X_t * Y_t) and lfd_UVSize (size_uv =
// A_ws / n_tex), plus A_ts / A_ws, on hand-worked triangles.

#include "bake_log.h"
#include "triangle_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace lfd::bake {
namespace {

TEST(TriangleStats, RightTriangleTwoTextures)
{
    // A_ws = 0.5 * |(2,0,0) x (0,1,0)| = 0.5 * 2 = 1
    // A_ts = 0.5 * |(0.5,0) x (0,0.5)| = 0.5 * 0.25 = 0.125
    // n_tex = max(0.125 * 256 * 256, 0.125 * 1024 * 512) = max(8192, 65536) = 65536
    // size_uv = 1 / 65536, A_ts / A_ws = 0.125
    const TriangleStats s = triangleStats({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0}, {0.5f, 0},
                                          {0, 0.5f}, {{{256, 256}}, {{1024, 512}}});
    EXPECT_FLOAT_EQ(s.areaWorld, 1.0f);
    EXPECT_FLOAT_EQ(s.areaTexture, 0.125f);
    EXPECT_FLOAT_EQ(s.texelCount, 65536.0f);
    EXPECT_FLOAT_EQ(s.sizeUv, 1.0f / 65536.0f);
    EXPECT_FLOAT_EQ(s.texPerWorld, 0.125f);
    EXPECT_EQ(s.flags, uint32_t(kTriangleTextured));
}

TEST(TriangleStats, TextureOrderDoesNotMatter)
{
    const TriangleStats a = triangleStats({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0}, {0.5f, 0},
                                          {0, 0.5f}, {{{1024, 512}}, {{256, 256}}});
    EXPECT_FLOAT_EQ(a.texelCount, 65536.0f);
}

TEST(TriangleStats, UntexturedTriangleHasOnlyWorldArea)
{
    // A_ws = 0.5 * |(3,0,0) x (0,4,0)| = 6; no textures -> no texture statistics.
    const TriangleStats s =
        triangleStats({0, 0, 0}, {3, 0, 0}, {0, 4, 0}, {0, 0}, {1, 0}, {0, 1}, {});
    EXPECT_FLOAT_EQ(s.areaWorld, 6.0f);
    EXPECT_EQ(s.areaTexture, 0.0f);
    EXPECT_EQ(s.texelCount, 0.0f);
    EXPECT_EQ(s.sizeUv, 0.0f);
    EXPECT_EQ(s.texPerWorld, 0.0f);
    EXPECT_EQ(s.flags, 0u);
}

TEST(TriangleStats, DegenerateTriangleHasZeroStats)
{
    // Collinear corners: A_ws = 0. The uv triangle still has A_ts = 0.5, n_tex = 0.5 * 16 * 16.
    const TriangleStats s =
        triangleStats({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0}, {1, 0}, {0, 1}, {{{16, 16}}});
    EXPECT_EQ(s.flags, uint32_t(kTriangleTextured | kTriangleDegenerate));
    EXPECT_EQ(s.areaWorld, 0.0f);
    EXPECT_EQ(s.sizeUv, 0.0f);
    EXPECT_EQ(s.texPerWorld, 0.0f);
    EXPECT_FLOAT_EQ(s.areaTexture, 0.5f);
    EXPECT_FLOAT_EQ(s.texelCount, 128.0f);
    EXPECT_TRUE(std::isfinite(s.sizeUv) && std::isfinite(s.texPerWorld));

    // Coincident corners, untextured.
    const TriangleStats p =
        triangleStats({1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {0, 0}, {0, 0}, {0, 0}, {});
    EXPECT_EQ(p.flags, uint32_t(kTriangleDegenerate));
    EXPECT_EQ(p.areaWorld, 0.0f);
}

TEST(TriangleStats, UvDegenerateTriangleIsOneTexel)
{
    // All uvs equal: A_ts = 0, n_tex = 0; the triangle shows one texel's colour, so it is
    // treated as one texel: size_uv = A_ws / 1 = 0.5 * |(1,0,0) x (0,1,0)| = 0.5.
    const TriangleStats s = triangleStats({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3f, 0.7f},
                                          {0.3f, 0.7f}, {0.3f, 0.7f}, {{{512, 512}}});
    EXPECT_EQ(s.flags, uint32_t(kTriangleTextured));
    EXPECT_FLOAT_EQ(s.areaWorld, 0.5f);
    EXPECT_EQ(s.areaTexture, 0.0f);
    EXPECT_EQ(s.texelCount, 0.0f);
    EXPECT_FLOAT_EQ(s.sizeUv, 0.5f);
    EXPECT_EQ(s.texPerWorld, 0.0f);
}

TEST(TriangleStats, SubTexelTriangleClampsToOneTexel)
{
    // A_ts = 0.5 * (1/512)^2 = 1/524288; n_tex = 65536 / 524288 = 0.125 < 1 -> size_uv = A_ws.
    const float d = 1.0f / 512.0f;
    const TriangleStats s =
        triangleStats({0, 0, 0}, {0, 0, 2}, {0, 2, 0}, {0, 0}, {d, 0}, {0, d}, {{{256, 256}}});
    EXPECT_FLOAT_EQ(s.texelCount, 0.125f);
    EXPECT_FLOAT_EQ(s.areaWorld, 2.0f);
    EXPECT_FLOAT_EQ(s.sizeUv, 2.0f);
    EXPECT_FLOAT_EQ(s.texPerWorld, (1.0f / 524288.0f) / 2.0f);
}

TEST(TriangleStats, TiltedTriangleIn3D)
{
    // Corners on the three axes: edges (-1,1,0) and (-1,0,1), cross = (1,1,1),
    // A_ws = 0.5 * sqrt(3) = 0.8660254. A_ts = 0.5 (unit right triangle in uv).
    // n_tex = 0.5 * 64 * 32 = 1024; size_uv = 0.8660254 / 1024; A_ts / A_ws = 0.5773503.
    const TriangleStats s =
        triangleStats({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0}, {1, 0}, {0, 1}, {{{64, 32}}});
    EXPECT_NEAR(s.areaWorld, 0.8660254f, 1e-6f);
    EXPECT_FLOAT_EQ(s.areaTexture, 0.5f);
    EXPECT_FLOAT_EQ(s.texelCount, 1024.0f);
    EXPECT_NEAR(s.sizeUv, 0.8660254f / 1024.0f, 1e-9f);
    EXPECT_NEAR(s.texPerWorld, 0.5773503f, 1e-6f);
    // Winding and uv orientation do not change areas.
    const TriangleStats r =
        triangleStats({1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 0}, {0, 1}, {1, 0}, {{{64, 32}}});
    EXPECT_FLOAT_EQ(r.areaWorld, s.areaWorld);
    EXPECT_FLOAT_EQ(r.areaTexture, s.areaTexture);
}

// Scene: three triangles. Primitive 0 (triangle 0) uses a material with base colour
// 256x256, normal map 1024x512, occlusion = the base colour texture again and an
// emissive texture whose size is unknown (0: skipped). Primitive 1 (triangle 1) has the
// default material. Triangle 2 lies outside every primitive.
Scene statsScene()
{
    Scene scene;
    scene.vertices.positions = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    scene.vertices.uvs = {{0, 0}, {0.5f, 0}, {0, 0.5f}};
    scene.indices = {0, 1, 2, 0, 1, 2, 0, 1, 2};
    scene.textures.resize(3);
    scene.textures[0].width = 256;
    scene.textures[0].height = 256;
    scene.textures[1].width = 1024;
    scene.textures[1].height = 512;
    Material material;
    material.baseColorTexture = 0;
    material.normalTexture = 1;
    material.occlusionTexture = 0;
    material.emissiveTexture = 2;
    scene.materials.push_back(material);
    scene.primitives.push_back({0, 3, 0});
    scene.primitives.push_back({3, 3, kNone});
    scene.meshes.push_back({"m", 0, 2});
    return scene;
}

TEST(TriangleStats, SceneUsesEachPrimitivesMaterial)
{
    Scene scene = statsScene();
    computeTriangleStats(scene);
    ASSERT_EQ(scene.triangleStats.size(), 3u);
    const TriangleStats& textured = scene.triangleStats[0];
    EXPECT_EQ(textured.flags, uint32_t(kTriangleTextured));
    EXPECT_FLOAT_EQ(textured.texelCount, 65536.0f); // see RightTriangleTwoTextures
    EXPECT_FLOAT_EQ(textured.sizeUv, 1.0f / 65536.0f);
    for (size_t t : {size_t(1), size_t(2)}) {
        EXPECT_EQ(scene.triangleStats[t].flags, 0u) << t;
        EXPECT_FLOAT_EQ(scene.triangleStats[t].areaWorld, 1.0f) << t;
        EXPECT_EQ(scene.triangleStats[t].sizeUv, 0.0f) << t;
    }
}

TEST(TriangleStats, SceneWithoutUvsIsUntextured)
{
    Scene scene = statsScene();
    scene.vertices.uvs.clear();
    computeTriangleStats(scene);
    ASSERT_EQ(scene.triangleStats.size(), 3u);
    EXPECT_EQ(scene.triangleStats[0].flags, 0u);
    EXPECT_EQ(scene.triangleStats[0].texelCount, 0.0f);
    EXPECT_FLOAT_EQ(scene.triangleStats[0].areaWorld, 1.0f);
}

TEST(TriangleStats, SceneWithUnsizedTexturesOnlyIsUntextured)
{
    Scene scene = statsScene();
    for (Texture& texture : scene.textures)
        texture.width = 0;
    computeTriangleStats(scene);
    EXPECT_EQ(scene.triangleStats[0].flags, 0u);
}

TEST(TriangleStats, BadSceneThrowsBakeError)
{
    Scene badMaterial = statsScene();
    badMaterial.primitives[1].material = 7;
    EXPECT_THROW(computeTriangleStats(badMaterial), BakeError);

    Scene badTexture = statsScene();
    badTexture.materials[0].normalTexture = 9;
    EXPECT_THROW(computeTriangleStats(badTexture), BakeError);

    Scene badIndex = statsScene();
    badIndex.indices[4] = 3;
    EXPECT_THROW(computeTriangleStats(badIndex), BakeError);

    Scene badRange = statsScene();
    badRange.primitives[1].indexCount = 9;
    EXPECT_THROW(computeTriangleStats(badRange), BakeError);
}

// KHR_texture_transform: A_ts of a texture is measured in its own uv space, TEXCOORD_0's
// area times the slot's area scale; areaTexture and texPerWorld stay in TEXCOORD_0's.
TEST(TriangleStats, SlotAreaScaleMultipliesTheTexelCount)
{
    // A_ts (TEXCOORD_0) = 0.125, A_ws = 1. Base colour 256^2 tiled with area scale 6:
    // 0.125 * 6 * 65536 = 49152; normal map 1024x512 scaled to a quarter of the area:
    // 0.125 * 0.25 * 524288 = 16384. n_tex = 49152.
    const TriangleStats s = triangleStats({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0}, {0.5f, 0}, {0, 0.5f},
                                          {{{256, 256}, 6.0}, {{1024, 512}, 0.25}});
    EXPECT_FLOAT_EQ(s.texelCount, 49152.0f);
    EXPECT_FLOAT_EQ(s.sizeUv, 1.0f / 49152.0f);
    EXPECT_FLOAT_EQ(s.areaTexture, 0.125f);
    EXPECT_FLOAT_EQ(s.texPerWorld, 0.125f);
}

// Triangles of assorted shapes and uvs, one primitive of material 0 whose base colour
// (256x128) and normal map (64x512) may carry texture transforms.
Scene transformScene()
{
    Scene scene;
    scene.vertices.positions = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 2, 0.5f}, {-1, 0.5f, 2}, {3, -1, 1}};
    scene.vertices.uvs = {{0, 0}, {0.5f, 0.1f}, {0.2f, 0.7f}, {0.9f, 0.4f}, {-0.3f, 1.2f}, {0.3f, -0.4f}};
    scene.indices = {0, 1, 2, 1, 3, 2, 2, 3, 4, 0, 5, 1, 4, 5, 3};
    scene.textures.resize(2);
    scene.textures[0].width = 256;
    scene.textures[0].height = 128;
    scene.textures[1].width = 64;
    scene.textures[1].height = 512;
    Material material;
    material.baseColorTexture = 0;
    scene.materials.push_back(material);
    scene.primitives.push_back({0, uint32_t(scene.indices.size()), 0});
    scene.meshes.push_back({"m", 0, 1});
    return scene;
}

void expectSameDensity(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.triangleStats.size(), b.triangleStats.size());
    for (size_t t = 0; t < a.triangleStats.size(); ++t) {
        SCOPED_TRACE("triangle " + std::to_string(t));
        const TriangleStats& x = a.triangleStats[t];
        const TriangleStats& y = b.triangleStats[t];
        // Agreement to the precision of float uvs (the hand-transformed ones are rounded).
        EXPECT_NEAR(x.texelCount, y.texelCount, 1e-5f * y.texelCount);
        EXPECT_NEAR(x.sizeUv, y.sizeUv, 1e-5f * y.sizeUv);
        EXPECT_EQ(x.areaWorld, y.areaWorld);
        EXPECT_EQ(x.flags, y.flags);
    }
}

// A material transform gives the statistics the same uvs transformed by hand give.
TEST(TriangleStats, TransformedSlotMatchesUvsTransformedByHand)
{
    const Scene plain = [] {
        Scene s = transformScene();
        computeTriangleStats(s);
        return s;
    }();
    for (const TextureTransform& transform :
         {TextureTransform::fromOffsetRotationScale({0.3f, -0.2f}, 0.7f, {3.0f, 2.0f}),
          TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, -2.5f, {0.25f, -0.5f}),
          TextureTransform::fromOffsetRotationScale({5.0f, 1.0f}, 0.0f, {1.0f, 1.0f})}) {
        Scene viaMaterial = transformScene();
        viaMaterial.materials[0].textureTransforms[uint32_t(TextureSlot::BaseColor)] = transform;
        computeTriangleStats(viaMaterial);
        Scene byHand = transformScene();
        for (glm::vec2& uv : byHand.vertices.uvs)
            uv = transform.apply(uv);
        computeTriangleStats(byHand);
        expectSameDensity(viaMaterial, byHand);
        // areaTexture and texPerWorld stay those of TEXCOORD_0.
        for (size_t t = 0; t < plain.triangleStats.size(); ++t) {
            EXPECT_EQ(viaMaterial.triangleStats[t].areaTexture, plain.triangleStats[t].areaTexture);
            EXPECT_EQ(viaMaterial.triangleStats[t].texPerWorld, plain.triangleStats[t].texPerWorld);
        }
    }
}

// Identity maps, and maps that keep areas (a pure offset, a rotation), change nothing.
TEST(TriangleStats, AreaPreservingTransformsKeepTheStatistics)
{
    Scene plain = transformScene();
    computeTriangleStats(plain);
    Scene identity = transformScene();
    identity.materials[0].textureTransforms[uint32_t(TextureSlot::BaseColor)] = TextureTransform{};
    computeTriangleStats(identity);
    for (size_t t = 0; t < plain.triangleStats.size(); ++t)
        EXPECT_EQ(std::memcmp(&plain.triangleStats[t], &identity.triangleStats[t], sizeof(TriangleStats)), 0) << t;
    Scene offset = transformScene();
    offset.materials[0].textureTransforms[uint32_t(TextureSlot::BaseColor)].offset = {0.5f, -3.0f};
    computeTriangleStats(offset);
    for (size_t t = 0; t < plain.triangleStats.size(); ++t)
        EXPECT_EQ(std::memcmp(&plain.triangleStats[t], &offset.triangleStats[t], sizeof(TriangleStats)), 0) << t;
    Scene rotated = transformScene();
    rotated.materials[0].textureTransforms[uint32_t(TextureSlot::BaseColor)] =
        TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 1.1f, {1.0f, 1.0f});
    computeTriangleStats(rotated);
    expectSameDensity(rotated, plain);
}

// n_tex is the largest over the material's textures, each in its own slot's uv space: a
// texture in two slots counts with each slot's scale.
TEST(TriangleStats, LargestTexelCountOverSlotsAndTheirTransforms)
{
    Scene scene = transformScene();
    Material& m = scene.materials[0];
    m.normalTexture = 1;
    m.occlusionTexture = 0;
    m.textureTransforms[uint32_t(TextureSlot::BaseColor)] =
        TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {0.5f, 0.5f}); // 256x128 at 1/4
    m.textureTransforms[uint32_t(TextureSlot::Occlusion)] =
        TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {3.0f, 1.0f}); // 256x128 at 3
    m.textureTransforms[uint32_t(TextureSlot::Normal)] =
        TextureTransform::fromOffsetRotationScale({0.0f, 0.0f}, 0.0f, {2.0f, 1.0f}); // 64x512 at 2
    computeTriangleStats(scene);
    Scene plain = transformScene();
    computeTriangleStats(plain);
    // Texels per TEXCOORD_0 area: 32768 * 0.25, 32768 * 3 = 98304, 32768 * 2: the occlusion
    // slot's 98304 wins, three times the untransformed base colour's.
    for (size_t t = 0; t < plain.triangleStats.size(); ++t)
        EXPECT_NEAR(scene.triangleStats[t].texelCount, 3.0f * plain.triangleStats[t].texelCount,
                    1e-6f * scene.triangleStats[t].texelCount)
            << t;
}

} // namespace
} // namespace lfd::bake
