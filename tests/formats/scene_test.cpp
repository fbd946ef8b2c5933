// Scene helpers: stored vs drawn triangle counts (node instancing), stream masks, texture
// transforms and material extension flags.
#include "lfd/scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(Scene, DrawnTrianglesCountEveryInstance)
{
    lfd::Scene s;
    s.vertices.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    s.indices = {0, 1, 2, 1, 3, 2, 0, 1, 3};
    s.primitives = {{0, 6, lfd::kNone}, {6, 3, lfd::kNone}};
    s.meshes = {{"two", 0, 1}, {"one", 1, 1}};
    lfd::Node a, b, c, group;
    a.mesh = 0; // 2 triangles
    b.mesh = 0; // 2 more: the same mesh again
    c.mesh = 1; // 1 triangle
    s.nodes = {group, a, b, c};
    EXPECT_EQ(s.triangleCount(), 3u);
    EXPECT_EQ(s.drawnTriangleCount(), 5u);
    s.nodes.resize(1); // a node without a mesh draws nothing
    EXPECT_EQ(s.drawnTriangleCount(), 0u);
}

TEST(Scene, StreamMaskListsOnlyStoredStreams)
{
    lfd::VertexStreams v;
    v.positions = {{0, 0, 0}};
    EXPECT_EQ(v.mask(), uint32_t(lfd::kStreamPosition));
    v.uvs = {{0, 0}};
    EXPECT_EQ(v.mask(), uint32_t(lfd::kStreamPosition | lfd::kStreamUv));
}

// KHR_texture_transform's matrix: translation * rotation * scale with the rotation rows
// [[cos r, sin r], [-sin r, cos r]] (the extension specification's GLSL).
TEST(Scene, TextureTransformFromOffsetRotationScale)
{
    const float r = 0.7f;
    const lfd::TextureTransform t = lfd::TextureTransform::fromOffsetRotationScale({0.5f, -0.25f}, r, {2.0f, 3.0f});
    const glm::vec2 uv(0.3f, 0.9f);
    const glm::vec2 scaled(uv.x * 2.0f, uv.y * 3.0f);
    const glm::vec2 expected(std::cos(r) * scaled.x + std::sin(r) * scaled.y + 0.5f,
                             -std::sin(r) * scaled.x + std::cos(r) * scaled.y - 0.25f);
    EXPECT_NEAR(t.apply(uv).x, expected.x, 1e-6f);
    EXPECT_NEAR(t.apply(uv).y, expected.y, 1e-6f);
    EXPECT_NEAR(t.areaScale(), 6.0f, 1e-5f);
    EXPECT_FALSE(t.identity());
    EXPECT_NEAR(lfd::TextureTransform::fromOffsetRotationScale({0, 0}, 1.0f, {-1.0f, 0.5f}).areaScale(), 0.5f, 1e-6f);
    EXPECT_TRUE(lfd::TextureTransform::fromOffsetRotationScale({0, 0}, 0.0f, {1, 1}).identity());
}

TEST(Scene, MaterialNeedsExtensionsWhenUnlitOrTransformed)
{
    lfd::Material m;
    EXPECT_FALSE(m.hasExtensions());
    m.textureTransforms[4].offset = {0.0f, 0.5f};
    EXPECT_TRUE(m.hasExtensions());
    m.textureTransforms[4] = {};
    m.unlit = true;
    EXPECT_TRUE(m.hasExtensions());
}

} // namespace
