// Skins and morph targets through the baker: Debian's simple_skin and AnimatedMorphCube
// import with their deformation (not in bind pose), the bounds contain every sampled pose,
// the tessellation bound holds at sampled poses (split triangles carry interpolated,
// renormalised influences and deltas), and an unsupported case warns by name.
#include "bake_log.h"
#include "imported_scene.h"
#include "gltf_import.h"
#include "scene_bounds.h"
#include "tessellation.h"
#include "gltf_deformation.h"

#include "skinned_test_scene.h"
#include "skip_or_fail.h"

#include "lfd/scene_animation.h"
#include "lfd/scene_pose.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lfd::test {
namespace {

const fs::path kAssimp = "/usr/share/assimp/models/glTF2";

bake::ImportedScene importFile(const fs::path& path) { return bake::importGltf(path, bake::Log{}); }

class SkinBake : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (!fs::is_directory(kAssimp))
            LFD_SKIP_OR_FAIL(kAssimp << " absent (install Debian package assimp-testmodels)");
    }
};

bool hasWarning(const bake::ImportedScene& s, const std::string& part)
{
    for (const std::string& w : s.warnings)
        if (w.find(part) != std::string::npos)
            return true;
    return false;
}

// Scene-space positions of every deformer's vertices at `time`.
std::vector<glm::vec3> posedScenePositions(const Scene& s, float time)
{
    const std::vector<glm::mat4> world = nodeWorldMatrices(s, time);
    const PoseInputs inputs = poseInputs(s, time, world);
    std::vector<glm::vec3> out;
    for (size_t d = 0; d < s.deformers.size(); ++d)
        for (const glm::vec3& p : posedPositions(s, inputs, d))
            out.push_back(glm::vec3(world[s.deformers[d].node] * glm::vec4(p, 1.0f)));
    return out;
}

void expectInsideBounds(const Scene& s, float time)
{
    for (const glm::vec3& p : posedScenePositions(s, time)) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, s.bounds.min - 1e-4f)) &&
                    glm::all(glm::lessThanEqual(p, s.bounds.max + 1e-4f)))
            << "t " << time << " point " << p.x << " " << p.y << " " << p.z;
    }
}

TEST_F(SkinBake, SimpleSkinImportsItsSkinAndAnimatesIt)
{
    bake::ImportedScene r = importFile(kAssimp / "simple_skin/simple_skin.gltf");
    Scene& s = r.scene;
    EXPECT_FALSE(hasWarning(r, "skinning ignored"));
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.skins[0].joints.size(), 2u);
    ASSERT_EQ(s.deformers.size(), 1u);
    EXPECT_EQ(s.deformers[0].skin, 0);
    EXPECT_EQ(s.vertices.deform.joints.size(), s.vertices.size());
    for (const glm::vec4& w : s.vertices.deform.weights)
        EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-5f);
    s.bounds = bake::computeBounds(s);
    // The joint rotates: the top of the strip moves between keys, and stays inside the bounds.
    const std::vector<glm::vec3> a = posedScenePositions(s, 0.0f), b = posedScenePositions(s, 1.5f);
    float moved = 0.0f;
    for (size_t i = 0; i < a.size(); ++i)
        moved = std::max(moved, glm::length(a[i] - b[i]));
    EXPECT_GT(moved, 0.2f);
    for (float t : {0.0f, 0.75f, 1.5f, 3.0f, 5.5f})
        expectInsideBounds(s, t);
}

TEST_F(SkinBake, AnimatedMorphCubeImportsTargetsAndWeightChannels)
{
    bake::ImportedScene r = importFile(kAssimp / "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    Scene& s = r.scene;
    EXPECT_FALSE(hasWarning(r, "morph targets: ignored"));
    EXPECT_EQ(s.vertices.deform.morphTargets, 2u);
    EXPECT_EQ(s.vertices.deform.positions.size(), 2 * s.vertices.size());
    EXPECT_EQ(s.vertices.deform.normals.size(), 2 * s.vertices.size());
    ASSERT_EQ(s.deformers.size(), 1u);
    EXPECT_EQ(s.deformers[0].skin, kNone);
    size_t weightChannels = 0;
    for (const Animation& a : s.animations)
        for (const AnimationChannel& c : a.channels)
            weightChannels += c.path == AnimationPath::Weights;
    EXPECT_EQ(weightChannels, 1u); // two targets: one channel of four weights
    s.bounds = bake::computeBounds(s);
    const float duration = animationDuration(s);
    const std::vector<glm::vec3> rest = posedScenePositions(s, 0.0f);
    float moved = 0.0f;
    for (float t = 0.0f; t <= duration; t += duration / 8.0f) {
        const std::vector<glm::vec3> p = posedScenePositions(s, t);
        for (size_t i = 0; i < p.size(); ++i)
            moved = std::max(moved, glm::length(p[i] - rest[i]));
        expectInsideBounds(s, t);
    }
    EXPECT_GT(moved, 1.0f); // the cube's faces move (scene scale 100)
}

// The longest scene-space edge of the deformed triangles at `time`.
float longestPosedEdge(const Scene& s, float time)
{
    const std::vector<glm::mat4> world = nodeWorldMatrices(s, time);
    VertexStreams posed = s.vertices;
    poseVertices(s, poseInputs(s, time, world), posed);
    float longest = 0.0f;
    const Deformer& d = s.deformers[0];
    for (size_t t = 0; t < s.triangleCount(); ++t)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = s.indices[3 * t + size_t(e)], b = s.indices[3 * t + size_t(e + 1) % 3];
            if (a < d.firstVertex)
                continue;
            const glm::mat4& m = world[d.node];
            longest = std::max(longest, glm::length(glm::vec3(m * glm::vec4(posed.positions[a], 1.0f)) -
                                                    glm::vec3(m * glm::vec4(posed.positions[b], 1.0f))));
        }
    return longest;
}

TEST(SkinTessellation, BoundHoldsAtSampledPoses)
{
    Scene s = skinnedArmScene(6); // long edges (0.4 along the arm)
    // Stretch the forearm: the hand joint scales x by 1.5 at t = 2.
    s.animations[0].channels.push_back(
        AnimationChannel{4, AnimationPath::Scale, Interpolation::Linear, {0.0f, 2.0f}, {{1, 1, 1, 0}, {1.5f, 1, 1, 0}}});
    const double bound = 0.05;
    const bake::TessellationStats stats = bake::tessellateScene(s, bound, bake::Log{}, 1);
    EXPECT_GT(stats.trianglesSplit, 0u);
    ASSERT_EQ(s.deformers.size(), 1u);
    EXPECT_EQ(s.deformers[0].firstVertex + s.deformers[0].vertexCount, s.vertices.size());
    EXPECT_EQ(s.vertices.deform.joints.size(), s.vertices.size());
    EXPECT_EQ(s.vertices.deform.positions.size(), s.vertices.size());
    for (size_t v = s.deformers[0].firstVertex; v < s.vertices.size(); ++v) {
        const glm::vec4 w = s.vertices.deform.weights[v];
        EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-5f) << v;
    }
    float worst = 0.0f;
    for (float t = 0.0f; t <= 2.0f; t += 0.05f)
        worst = std::max(worst, longestPosedEdge(s, t));
    EXPECT_LE(worst, bound * 1.001) << "longest posed edge over the sampled poses";
    EXPECT_GT(worst, bound * 0.5);
}

// A skinned node whose mesh has no JOINTS_0 / WEIGHTS_0: baked in bind pose, and the
// warning names the node, the mesh and what is missing.
TEST_F(SkinBake, SkinWithoutInfluencesWarnsByName)
{
    const fs::path source = kAssimp / "simple_skin/simple_skin.gltf";
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(source));
    doc["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
    doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
    const fs::path dir = fs::temp_directory_path() / ("lfd_skin_warn_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "skin.gltf") << doc.dump();
    const bake::ImportedScene r = bake::importGltf(dir / "skin.gltf", bake::Log{});
    fs::remove_all(dir);
    EXPECT_TRUE(hasWarning(r, "nodes[0] is skinned but meshes[0] has no JOINTS_0 / WEIGHTS_0"))
        << (r.warnings.empty() ? "" : r.warnings.front());
    EXPECT_TRUE(r.scene.deformers.empty());
}

} // namespace
} // namespace lfd::test

namespace lfd::test {
namespace {

// A primitive with two JOINTS_n / WEIGHTS_n sets (eight influences per vertex): the four
// largest are kept, renormalised to sum 1, and the warning names the primitive.
TEST(SkinInfluences, MoreThanFourKeepTheFourLargestRenormalised)
{
    tinygltf::Model model;
    const std::vector<float> joints0{0, 1, 2, 3}, joints1{4, 5, 6, 7};
    const std::vector<float> weights0{0.30f, 0.05f, 0.20f, 0.02f}, weights1{0.25f, 0.03f, 0.10f, 0.05f};
    tinygltf::Buffer buffer;
    for (const std::vector<float>* v : {&joints0, &joints1, &weights0, &weights1}) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(v->data());
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.data.size();
        view.byteLength = 16;
        buffer.data.insert(buffer.data.end(), bytes, bytes + 16);
        model.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = int(model.bufferViews.size() - 1);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = TINYGLTF_TYPE_VEC4;
        accessor.count = 1;
        model.accessors.push_back(accessor);
    }
    model.buffers.push_back(buffer);
    tinygltf::Primitive prim;
    prim.attributes = {{"JOINTS_0", 0}, {"JOINTS_1", 1}, {"WEIGHTS_0", 2}, {"WEIGHTS_1", 3}};
    const std::vector<uint32_t> source{0};
    const std::string label = "meshes[0].primitives[0]", file = "eight.gltf";
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
    std::vector<std::string> warnings;
    bake::gltf::readInfluences({model, prim, source, 1, label, file}, joints, weights,
                               [&](const std::string&, const std::string& m) { warnings.push_back(m); });
    ASSERT_EQ(joints.size(), 1u);
    EXPECT_EQ(joints[0], glm::uvec4(0, 4, 2, 6));           // 0.30, 0.25, 0.20, 0.10
    EXPECT_NEAR(weights[0].x, 0.30f / 0.85f, 1e-6f);
    EXPECT_NEAR(weights[0].x + weights[0].y + weights[0].z + weights[0].w, 1.0f, 1e-6f);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("meshes[0].primitives[0] has vertices with more than four joint influences"),
              std::string::npos)
        << warnings[0];
}

} // namespace
} // namespace lfd::test
