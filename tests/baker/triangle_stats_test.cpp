// Paper eqs. texelCount (n_tex = max_t A_ts * X_t * Y_t) and lfd_UVSize (size_uv =
// A_ws / n_tex), plus A_ts / A_ws, on hand-worked triangles.

#include "bake.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lfd::bake {
namespace {

TEST(TriangleStats, RightTriangleTwoTextures)
{
    // A_ws = 0.5 * |(2,0,0) x (0,1,0)| = 0.5 * 2 = 1
    // A_ts = 0.5 * |(0.5,0) x (0,0.5)| = 0.5 * 0.25 = 0.125
    // n_tex = max(0.125 * 256 * 256, 0.125 * 1024 * 512) = max(8192, 65536) = 65536
    // size_uv = 1 / 65536, A_ts / A_ws = 0.125
    const TriangleStats s = triangleStats({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0}, {0.5f, 0},
                                          {0, 0.5f}, {{256, 256}, {1024, 512}});
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
                                          {0, 0.5f}, {{1024, 512}, {256, 256}});
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
        triangleStats({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0}, {1, 0}, {0, 1}, {{16, 16}});
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
                                          {0.3f, 0.7f}, {0.3f, 0.7f}, {{512, 512}});
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
        triangleStats({0, 0, 0}, {0, 0, 2}, {0, 2, 0}, {0, 0}, {d, 0}, {0, d}, {{256, 256}});
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
        triangleStats({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0}, {1, 0}, {0, 1}, {{64, 32}});
    EXPECT_NEAR(s.areaWorld, 0.8660254f, 1e-6f);
    EXPECT_FLOAT_EQ(s.areaTexture, 0.5f);
    EXPECT_FLOAT_EQ(s.texelCount, 1024.0f);
    EXPECT_NEAR(s.sizeUv, 0.8660254f / 1024.0f, 1e-9f);
    EXPECT_NEAR(s.texPerWorld, 0.5773503f, 1e-6f);
    // Winding and uv orientation do not change areas.
    const TriangleStats r =
        triangleStats({1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 0}, {0, 1}, {1, 0}, {{64, 32}});
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

} // namespace
} // namespace lfd::bake
