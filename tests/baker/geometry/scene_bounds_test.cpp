// Scene-bounds stage: node animation sampling, bounds over animation keys, per-mesh
// world scale. Expected values are worked out by hand in the comments.
#include "bake_log.h"
#include "gltf_import.h"
#include "scene_bounds.h"
#include "lfd/scene_animation.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace {

// One unit right triangle (0,0,0) (1,0,0) (0,1,0) as mesh 0.
lfd::Scene unitTriangleScene()
{
    lfd::Scene s;
    s.vertices.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    s.vertices.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    s.indices = {0, 1, 2};
    s.primitives = {{0, 3, lfd::kNone}};
    s.meshes = {{"tri", 0, 1}};
    return s;
}

lfd::Node meshNode(glm::vec3 translation, int32_t mesh = 0, int32_t parent = lfd::kNone)
{
    lfd::Node n;
    n.mesh = mesh;
    n.parent = parent;
    n.translation = translation;
    return n;
}

lfd::AnimationChannel channel(uint32_t node, lfd::AnimationPath path, lfd::Interpolation interpolation,
                              std::vector<float> times, std::vector<glm::vec4> values)
{
    lfd::AnimationChannel c;
    c.node = node;
    c.path = path;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

glm::vec4 xyzw(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

} // namespace

TEST(SceneBounds, TranslatedTriangleOverAnimationKeys)
{
    // Node at (10,0,0), animated linearly to (20,0,0) over one second. The triangle
    // sweeps x in [10, 21], y in [0, 1]: AABB (10,0,0)-(21,1,0), centre (15.5,0.5,0).
    // Farthest vertices from the centre: (10,0), (10,1), (21,0) at distance
    // sqrt(5.5^2 + 0.5^2) = sqrt(30.5).
    lfd::Scene s = unitTriangleScene();
    s.nodes = {meshNode({10, 0, 0})};
    s.animations = {{"move",
                     {channel(0, lfd::AnimationPath::Translation, lfd::Interpolation::Linear, {0.0f, 1.0f},
                              {{10, 0, 0, 0}, {20, 0, 0, 0}})}}};
    const lfd::SceneBounds b = lfd::bake::computeBounds(s);
    expectVec(b.min, {10, 0, 0});
    expectVec(b.max, {21, 1, 0});
    expectVec(b.center, {15.5f, 0.5f, 0});
    EXPECT_NEAR(b.radius, std::sqrt(30.5f), 1e-5f);
}

TEST(SceneBounds, RestPoseIsIncludedAndInstancesAreAll)
{
    // The same mesh under two nodes at x = -5 and x = +5; the second is animated upwards
    // but its rest pose (y = 0) lies outside the keys (y = 2..3).
    lfd::Scene s = unitTriangleScene();
    s.nodes = {meshNode({-5, 0, 0}), meshNode({5, 0, 0})};
    s.animations = {{"lift",
                     {channel(1, lfd::AnimationPath::Translation, lfd::Interpolation::Linear, {0.0f, 1.0f},
                              {{5, 2, 0, 0}, {5, 3, 0, 0}})}}};
    const lfd::SceneBounds b = lfd::bake::computeBounds(s);
    expectVec(b.min, {-5, 0, 0});
    expectVec(b.max, {6, 4, 0});
}

TEST(SceneBounds, RadiusUpTo1e18IsAcceptedBeyondIsABakeError)
{
    // Later stages square lengths in float (overflow from about 1.8e19): 1e18 is the limit.
    lfd::Scene s = unitTriangleScene();
    s.vertices.positions[1] = {1.9e18f, 0, 0};
    s.nodes = {meshNode({0, 0, 0})};
    const lfd::SceneBounds b = lfd::bake::computeBounds(s);
    EXPECT_FLOAT_EQ(b.center.x, 9.5e17f);
    EXPECT_FLOAT_EQ(b.radius, 9.5e17f);

    s.vertices.positions[1] = {1e22f, 0, 0};
    try {
        lfd::bake::computeBounds(s);
        ADD_FAILURE() << "accepted";
    } catch (const lfd::bake::BakeError& e) {
        EXPECT_NE(std::string(e.what()).find("exceeds 1e18 units"), std::string::npos) << e.what();
    }
}

TEST(SceneBounds, TransformOverflowingFloatIsABakeError)
{
    lfd::Scene s = unitTriangleScene();
    s.vertices.positions[1] = {1e20f, 0, 0};
    s.nodes = {meshNode({0, 0, 0})};
    s.nodes[0].scale = glm::vec3(1e30f);
    EXPECT_THROW(lfd::bake::computeBounds(s), lfd::bake::BakeError);
}

TEST(SceneBounds, EmptySceneHasZeroBounds)
{
    lfd::Scene s = unitTriangleScene();
    const lfd::SceneBounds none = lfd::bake::computeBounds(s); // no node instances the mesh
    EXPECT_EQ(none.min, glm::vec3(0));
    EXPECT_EQ(none.max, glm::vec3(0));
    EXPECT_EQ(none.radius, 0.0f);
    EXPECT_EQ(lfd::bake::computeBounds(lfd::Scene{}).radius, 0.0f);
}

TEST(SceneBounds, LinearInterpolatesStepHoldsAndBothClamp)
{
    lfd::Scene s = unitTriangleScene();
    s.nodes = {meshNode({0, 0, 0}), meshNode({0, 0, 0})};
    s.animations = {{"a",
                     {channel(0, lfd::AnimationPath::Translation, lfd::Interpolation::Linear, {1.0f, 3.0f},
                              {{10, 0, 0, 0}, {20, 0, 0, 0}}),
                      channel(1, lfd::AnimationPath::Scale, lfd::Interpolation::Step, {1.0f, 3.0f},
                              {{2, 2, 2, 0}, {4, 4, 4, 0}})}}};
    using lfd::nodeWorldMatrices;
    expectVec(origin(nodeWorldMatrices(s, 2.0f)[0]), {15, 0, 0});
    expectVec(origin(nodeWorldMatrices(s, 1.5f)[0]), {12.5f, 0, 0});
    expectVec(origin(nodeWorldMatrices(s, 0.0f)[0]), {10, 0, 0}); // clamped before the first key
    expectVec(origin(nodeWorldMatrices(s, 9.0f)[0]), {20, 0, 0}); // and after the last

    EXPECT_FLOAT_EQ(nodeWorldMatrices(s, 2.9f)[1][0][0], 2.0f); // STEP holds the previous key
    EXPECT_FLOAT_EQ(nodeWorldMatrices(s, 3.0f)[1][0][0], 4.0f);
    EXPECT_FLOAT_EQ(nodeWorldMatrices(s, 0.0f)[1][0][0], 2.0f);
}

TEST(SceneBounds, SlerpHalfwayThroughQuarterTurnIsEighthTurn)
{
    lfd::Scene s = unitTriangleScene();
    s.nodes = {meshNode({0, 0, 0})};
    const glm::quat q0(1, 0, 0, 0);
    const glm::quat q90 = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    for (const glm::quat& end : {q90, -q90}) { // -q is the same rotation: shortest path either way
        s.animations = {{"spin",
                         {channel(0, lfd::AnimationPath::Rotation, lfd::Interpolation::Linear, {0.0f, 1.0f},
                                  {xyzw(q0), xyzw(end)})}}};
        const glm::mat4 m = lfd::nodeWorldMatrices(s, 0.5f)[0];
        const glm::vec3 x = glm::vec3(m * glm::vec4(1, 0, 0, 0));
        EXPECT_NEAR(glm::degrees(std::atan2(x.y, x.x)), 45.0f, 1e-3f);
    }
}

TEST(SceneBounds, HierarchyComposesParentTimesChild)
{
    // Parent rotated 90 deg about z at (0,0,1); child at (1,0,0) in the parent's frame,
    // so the child's origin is at (0,1,1).
    lfd::Scene s = unitTriangleScene();
    lfd::Node parent = meshNode({0, 0, 1}, lfd::kNone);
    parent.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    s.nodes = {parent, meshNode({1, 0, 0}, 0, 0)};
    expectVec(origin(lfd::nodeWorldMatrices(s, 0.0f)[1]), {0, 1, 1});
    const lfd::SceneBounds b = lfd::bake::computeBounds(s);
    expectVec(b.min, {-1, 1, 1}); // triangle (0,1,1) (0,2,1) (-1,1,1)
    expectVec(b.max, {0, 2, 1});
}

TEST(SceneBounds, MeshMaxWorldScale)
{
    lfd::Scene s = unitTriangleScene();
    s.meshes.push_back({"unused", 0, 1});
    lfd::Node n = meshNode({7, 0, 0});
    n.scale = {2, 3, 1};
    s.nodes = {n};
    std::vector<float> scale = lfd::bake::meshMaxWorldScale(s);
    ASSERT_EQ(scale.size(), 2u);
    EXPECT_FLOAT_EQ(scale[0], 3.0f);
    EXPECT_EQ(scale[1], 0.0f);

    // Under a parent scaled by 2 and animated to scale 5 on x: max column length 2 * 5 = 10.
    lfd::Node parent = meshNode({0, 0, 0}, lfd::kNone);
    parent.scale = {2, 2, 2};
    n.parent = 0;
    s.nodes = {parent, n};
    s.animations = {{"grow",
                     {channel(1, lfd::AnimationPath::Scale, lfd::Interpolation::Linear, {0.0f, 1.0f},
                              {{1, 1, 1, 0}, {5, 1, 1, 0}})}}};
    scale = lfd::bake::meshMaxWorldScale(s);
    EXPECT_FLOAT_EQ(scale[0], 10.0f);
}

TEST(SceneBounds, CesiumMilkTruckSphereContainsEveryAnimatedPose)
{
    const fs::path file = fs::path(LFD_SHARED_SCENES) / "CesiumMilkTruck/CesiumMilkTruck.gltf";
    if (!fs::exists(file))
        LFD_SKIP_OR_FAIL(file << " absent: third-party scene test skipped");
    const lfd::Scene s = lfd::bake::importGltf(file, {}).scene;
    const lfd::SceneBounds b = lfd::bake::computeBounds(s);
    ASSERT_GT(b.radius, 0.0f);

    // Random times between keys: every vertex stays inside the AABB and sphere up to a
    // small tolerance (bounds are exact at the sampled times; the spinning wheels sweep
    // only slightly outside between samples).
    float duration = 0.0f;
    for (const lfd::Animation& a : s.animations)
        for (const lfd::AnimationChannel& c : a.channels)
            duration = std::max(duration, c.times.back());
    ASSERT_GT(duration, 0.0f);
    const float tolerance = 1e-3f * b.radius;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> when(0.0f, duration);
    for (int i = 0; i < 20; ++i) {
        const std::vector<glm::mat4> world = lfd::nodeWorldMatrices(s, when(rng));
        for (size_t n = 0; n < s.nodes.size(); ++n) {
            if (s.nodes[n].mesh < 0)
                continue;
            const lfd::Mesh& m = s.meshes[size_t(s.nodes[n].mesh)];
            for (uint32_t p = m.firstPrimitive; p < m.firstPrimitive + m.primitiveCount; ++p)
                for (uint32_t k = 0; k < s.primitives[p].indexCount; ++k) {
                    const glm::vec3 q = glm::vec3(
                        world[n] * glm::vec4(s.vertices.positions[s.indices[s.primitives[p].firstIndex + k]], 1));
                    ASSERT_LE(glm::length(q - b.center), b.radius + tolerance);
                    ASSERT_TRUE(glm::all(glm::greaterThanEqual(q, b.min - tolerance)));
                    ASSERT_TRUE(glm::all(glm::lessThanEqual(q, b.max + tolerance)));
                }
        }
    }
}
