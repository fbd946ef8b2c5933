// Skins, morph targets and weight channels in a pack (formats/README.md "Deformation"):
// round trip of every field, the sections present only when used, the rules the reader
// enforces, and the CPU posing (lfd/scene_pose.h) the baker and the player share.
#include "pack_test_scenes.h"
#include "skinned_test_scene.h"

#include "lfd/scene_animation.h"
#include "lfd/scene_pose.h"

#include <gtest/gtest.h>

namespace lfd::test {
namespace {

// The arm scene with what a pack needs besides (statistics per triangle).
Scene packableArm()
{
    Scene s = skinnedArmScene();
    s.triangleStats.assign(s.triangleCount(), TriangleStats{});
    return s;
}

TEST(PackDeformation, RoundTripKeepsSkinsDeformersMorphsAndWeightChannels)
{
    const Scene scene = packableArm();
    const std::vector<uint8_t> bytes = writePackToMemory(scene);
    const Scene back = readPackFromMemory(bytes.data(), bytes.size(), "arm.lfdpack");
    expectSameScene(scene, back);
    const DeformationStreams& a = scene.vertices.deform;
    const DeformationStreams& b = back.vertices.deform;
    EXPECT_EQ(a.joints, b.joints);
    EXPECT_EQ(a.weights, b.weights);
    EXPECT_EQ(b.morphTargets, 1u);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_TRUE(b.tangents.empty());
    ASSERT_EQ(back.skins.size(), 1u);
    EXPECT_EQ(back.skins[0].name, "arm skin");
    EXPECT_EQ(back.skins[0].joints, scene.skins[0].joints);
    EXPECT_EQ(back.skins[0].inverseBindMatrices, scene.skins[0].inverseBindMatrices);
    ASSERT_EQ(back.deformers.size(), 1u);
    EXPECT_EQ(back.deformers[0].node, 5u);
    EXPECT_EQ(back.deformers[0].skin, 0);
    EXPECT_EQ(back.deformers[0].firstVertex, 4u);
    EXPECT_EQ(back.deformers[0].vertexCount, scene.deformers[0].vertexCount);
    EXPECT_EQ(back.deformers[0].weights, std::vector<float>{0.25f});
    EXPECT_EQ(back.animations[0].channels[2].path, AnimationPath::Weights);
    // A weights channel makes ACHN version 2; the deformation sections are all present.
    EXPECT_EQ(entryFor(bytes, pack::kTagChannels).version, pack::kChannelsWeightsVersion);
    for (uint32_t tag : {pack::kTagJoints, pack::kTagWeights, pack::kTagMorphPositions, pack::kTagMorphNormals,
                         pack::kTagSkins, pack::kTagSkinJoints, pack::kTagDeformers, pack::kTagDeformerWeights})
        EXPECT_TRUE(entryIndex(bytes, tag).has_value()) << pack::tagName(tag);
    EXPECT_FALSE(entryIndex(bytes, pack::kTagMorphTangents).has_value());
}

TEST(PackDeformation, StaticScenesStoreNoDeformationAndKeepChannelsVersion1)
{
    const std::vector<uint8_t> bytes = writePackToMemory(makeFullScene());
    EXPECT_EQ(entryFor(bytes, pack::kTagChannels).version, pack::kSectionVersion);
    for (uint32_t tag : {pack::kTagJoints, pack::kTagWeights, pack::kTagMorphPositions, pack::kTagSkins,
                         pack::kTagDeformers, pack::kTagDeformerWeights})
        EXPECT_FALSE(entryIndex(bytes, tag).has_value()) << pack::tagName(tag);
}

TEST(PackDeformation, ReaderRefusesBrokenDeformation)
{
    // Raw sections, so records can be patched in place.
    std::vector<uint8_t> bytes = writePackToMemory(packableArm(), {}, PackWriteOptions{.compress = false});
    // A version-1 reader's view of a weights channel: refused by name.
    std::vector<uint8_t> v1 = bytes;
    pack::SectionEntry e = entryFor(v1, pack::kTagChannels);
    e.version = 1;
    setEntry(v1, *entryIndex(v1, pack::kTagChannels), e);
    pack::resealPack(v1);
    expectPackRejected(v1, "weights channel in a version-1 'ACHN' section");
    // A joint index past the skin's joints.
    std::vector<uint8_t> joint = bytes;
    writeElement(joint, pack::kTagJoints, 10, glm::uvec4(7, 0, 0, 0));
    pack::resealPack(joint);
    expectPackRejected(joint, "names a joint past the skin's 3");
    // A deformer whose vertices run past the streams.
    std::vector<uint8_t> range = bytes;
    writeElement<uint32_t>(range, pack::kTagDeformers, 0, 1000, offsetof(pack::DeformerRecord, vertexCount));
    pack::resealPack(range);
    expectPackRejected(range, "lie outside the vertex streams");
}

TEST(PackDeformation, WriterRefusesWhatTheReaderWould)
{
    Scene s = packableArm();
    s.deformers[0].weights.clear();
    EXPECT_THROW(writePackToMemory(s), PackError);
    s = packableArm();
    s.skins[0].joints[1] = 99;
    EXPECT_THROW(writePackToMemory(s), PackError);
}

// Bind pose, weights 0: the arm is where it is stored, whatever its node's transform
// (glTF 3.7.3: the skinned node's transform is ignored; lfd poses into its object space,
// and sceneFromNode * posed is the skinned position).
TEST(ScenePose, BindPoseLeavesTheArmWhereItIsStored)
{
    Scene s = skinnedArmScene();
    s.animations.clear();
    s.deformers[0].weights = {0.0f};
    const std::vector<glm::mat4> world = nodeWorldMatrices(s, 0.0f);
    VertexStreams posed = s.vertices;
    poseVertices(s, poseInputs(s, 0.0f, world), posed);
    for (size_t v = 4; v < s.vertices.size(); ++v) {
        const glm::vec3 scenePos = glm::vec3(world[5] * glm::vec4(posed.positions[v], 1.0f));
        EXPECT_NEAR(glm::length(scenePos - s.vertices.positions[v]), 0.0f, 1e-5f) << v;
        EXPECT_NEAR(glm::length(posed.normals[v] - s.vertices.normals[v]), 0.0f, 1e-5f) << v;
    }
}

// At t = 1 the elbow is bent by 1.2 rad: the hand end of the arm rotates about the elbow
// (x = 1), the upper arm stays and carries the full bulge (weight 1).
TEST(ScenePose, BentElbowRotatesTheForearmAndTheBulgeFollowsItsWeight)
{
    const Scene s = skinnedArmScene();
    const std::vector<glm::mat4> world = nodeWorldMatrices(s, 1.0f);
    VertexStreams posed = s.vertices;
    poseVertices(s, poseInputs(s, 1.0f, world), posed);
    auto scenePos = [&](size_t v) { return glm::vec3(world[5] * glm::vec4(posed.positions[v], 1.0f)); };
    // Vertex at x = 0.5 (column 5 of 21, upper edge): shoulder only, bulge weight 1.
    const size_t upper = 4 + 2 * 5 + 1;
    EXPECT_NEAR(glm::length(scenePos(upper) - (s.vertices.positions[upper] + s.vertices.deform.positions[upper])), 0.0f,
                1e-5f);
    // Vertex at x = 1.5 (column 15, lower edge): elbow only, rotated by 1.2 rad about (1, 0).
    const size_t fore = 4 + 2 * 15;
    const glm::vec3 rest = s.vertices.positions[fore];
    const glm::vec2 d(rest.x - 1.0f, rest.y);
    const glm::vec2 rotated(std::cos(1.2f) * d.x - std::sin(1.2f) * d.y, std::sin(1.2f) * d.x + std::cos(1.2f) * d.y);
    EXPECT_NEAR(glm::length(scenePos(fore) - glm::vec3(1.0f + rotated.x, rotated.y, 0.0f)), 0.0f, 1e-5f);
    // The static floor is untouched.
    for (size_t v = 0; v < 4; ++v)
        EXPECT_EQ(posed.positions[v], s.vertices.positions[v]);
}

} // namespace
} // namespace lfd::test
