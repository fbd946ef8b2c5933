// Skinning and morph targets on the CPU (glTF 2.0 sections 3.7.2.2 and 3.7.3): the
// baker's poses for bounds and edge lengths, the player's reference for its GPU pass.
#include "lfd/scene_pose.h"

#include "lfd/scene_animation.h"

#include <algorithm>
#include <cmath>

namespace lfd {
namespace {

// The inverse transpose of m up to a positive factor (the cofactor matrix, its sign
// fixed by the determinant's): normals stay normal under non-uniform joint scales.
glm::mat3 normalMatrix(const glm::mat3& m)
{
    const glm::mat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    return glm::determinant(m) < 0.0f ? -cofactor : cofactor;
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback)
{
    const float length = glm::length(v);
    return length > 1e-20f && std::isfinite(length) ? v / length : fallback;
}

// The blended skin matrix of vertex v (3.7.3.3: sum of weight * jointMatrix), identity
// for a deformer without skin.
glm::mat4 skinMatrix(const Scene& scene, const PoseInputs& inputs, size_t deformer, size_t v)
{
    const Deformer& d = scene.deformers[deformer];
    const DeformationStreams& s = scene.vertices.deform;
    if (d.skin == kNone || !s.skinned())
        return glm::mat4(1.0f);
    const size_t jointCount = scene.skins[size_t(d.skin)].joints.size();
    glm::mat4 m(0.0f);
    for (int k = 0; k < 4; ++k) {
        const uint32_t j = s.joints[v][k];
        if (s.weights[v][k] != 0.0f && j < jointCount)
            m += s.weights[v][k] * inputs.jointMatrices[inputs.firstJoint[deformer] + j];
    }
    return m;
}

// Rest position plus the weighted morph deltas (3.7.2.2), in bind space.
glm::vec3 morphed(const std::vector<glm::vec3>& base, const std::vector<glm::vec3>& deltas, const float* weights,
                  uint32_t targets, size_t v)
{
    glm::vec3 p = base[v];
    if (!deltas.empty())
        for (uint32_t t = 0; t < targets; ++t)
            p += weights[t] * deltas[v * targets + t];
    return p;
}

} // namespace

PoseInputs poseInputs(const Scene& scene, float time, const std::vector<glm::mat4>& sceneFromNode)
{
    PoseInputs inputs;
    inputs.morphWeights = morphWeights(scene, time);
    for (const Deformer& d : scene.deformers) {
        inputs.firstJoint.push_back(uint32_t(inputs.jointMatrices.size()));
        if (d.skin == kNone)
            continue;
        const Skin& skin = scene.skins[size_t(d.skin)];
        const glm::mat4 nodeFromScene = glm::inverse(sceneFromNode[d.node]);
        for (size_t j = 0; j < skin.joints.size(); ++j)
            inputs.jointMatrices.push_back(nodeFromScene * sceneFromNode[skin.joints[j]] * skin.inverseBindMatrices[j]);
    }
    return inputs;
}

void poseVertices(const Scene& rest, const PoseInputs& inputs, VertexStreams& posed)
{
    const VertexStreams& v = rest.vertices;
    const DeformationStreams& s = v.deform;
    for (size_t d = 0; d < rest.deformers.size(); ++d) {
        const Deformer& deformer = rest.deformers[d];
        const float* weights = inputs.morphWeights.data() + d * s.morphTargets;
        for (size_t i = deformer.firstVertex; i < size_t(deformer.firstVertex) + deformer.vertexCount; ++i) {
            const glm::mat4 m = skinMatrix(rest, inputs, d, i);
            posed.positions[i] = glm::vec3(m * glm::vec4(morphed(v.positions, s.positions, weights, s.morphTargets, i), 1.0f));
            if (!v.normals.empty()) {
                const glm::vec3 n = morphed(v.normals, s.normals, weights, s.morphTargets, i);
                posed.normals[i] = normalizedOr(normalMatrix(glm::mat3(m)) * n, v.normals[i]);
            }
            if (!v.tangents.empty()) {
                glm::vec3 tangent = glm::vec3(v.tangents[i]);
                if (!s.tangents.empty())
                    for (uint32_t k = 0; k < s.morphTargets; ++k)
                        tangent += weights[k] * s.tangents[i * s.morphTargets + k];
                posed.tangents[i] = glm::vec4(normalizedOr(glm::mat3(m) * tangent, glm::vec3(v.tangents[i])), v.tangents[i].w);
            }
        }
    }
}

std::vector<glm::vec3> posedPositions(const Scene& scene, const PoseInputs& inputs, size_t deformer)
{
    const Deformer& d = scene.deformers[deformer];
    const DeformationStreams& s = scene.vertices.deform;
    const float* weights = inputs.morphWeights.data() + deformer * s.morphTargets;
    std::vector<glm::vec3> out(d.vertexCount);
    for (size_t i = 0; i < d.vertexCount; ++i) {
        const size_t v = d.firstVertex + i;
        const glm::vec3 p = morphed(scene.vertices.positions, s.positions, weights, s.morphTargets, v);
        out[i] = glm::vec3(skinMatrix(scene, inputs, deformer, v) * glm::vec4(p, 1.0f));
    }
    return out;
}

float maxJointScale(const Scene& scene, const PoseInputs& inputs, size_t deformer)
{
    const Deformer& d = scene.deformers[deformer];
    if (d.skin == kNone)
        return 1.0f;
    float scale = 0.0f;
    const size_t count = scene.skins[size_t(d.skin)].joints.size();
    for (size_t j = 0; j < count; ++j)
        for (int c = 0; c < 3; ++c)
            scale = std::max(scale, glm::length(glm::vec3(inputs.jointMatrices[inputs.firstJoint[deformer] + j][c])));
    return scale;
}

} // namespace lfd
