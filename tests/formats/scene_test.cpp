// Scene helpers: stored vs drawn triangle counts (node instancing) and stream masks.
#include "lfd/scene.h"

#include <gtest/gtest.h>

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

} // namespace
