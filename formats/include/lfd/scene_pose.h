// Skinning and morph targets (glTF 2.0 sections 3.7.2.2 and 3.7.3), shared by the baker
// (bounds and the tessellation bound over the poses an animation reaches) and the player
// (its reference for the GPU pose pass, shaders/pose_vertices.comp, which follows the
// same steps: morph deltas, then linear blend skinning).
#pragma once

#include "lfd/scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace lfd {

// What posing needs at one time, for every deformer of the scene.
struct PoseInputs {
    // Per deformer d, joints [firstJoint[d], + skin joint count): the matrix that takes a
    // bind-pose vertex into the deformer node's object space,
    //   nodeFromScene(deformer node) * sceneFromJoint * inverseBindMatrix
    // (the glTF tutorial's jointMatrix; the renderers then apply the node's own
    // sceneFromNode as for any mesh, so the node's transform cancels as 3.7.3 requires).
    std::vector<glm::mat4> jointMatrices;
    std::vector<uint32_t> firstJoint;
    // Per deformer d, weights [d * morphTargets, + morphTargets): the node's default
    // weights overridden by any animated ones (3.7.2.2).
    std::vector<float> morphWeights;
};

// Morph weights and joint matrices of every deformer at `time` seconds; sceneFromNode is
// nodeWorldMatrices(scene, time).
PoseInputs poseInputs(const Scene& scene, float time, const std::vector<glm::mat4>& sceneFromNode);

// Poses the deformers' vertices of `rest` into `posed` (which holds a copy of rest's
// positions, normals and tangents): p' = sum_j w_j M_j (p + sum_t w_t dp_t); normals by
// the inverse transpose of the blended matrix, tangents by the matrix, both
// renormalised, tangent w kept. Vertices outside every deformer are left as they are.
void poseVertices(const Scene& rest, const PoseInputs& inputs, VertexStreams& posed);

// One deformer's vertices at `time` in its node's object space (positions only).
std::vector<glm::vec3> posedPositions(const Scene& scene, const PoseInputs& inputs, size_t deformer);

// The largest length of a joint matrix's columns (its largest linear scale), 1 for a
// deformer without skin.
float maxJointScale(const Scene& scene, const PoseInputs& inputs, size_t deformer);

} // namespace lfd
