// Rigid node animation (glTF 2.0 semantics), shared by baker and player.
#include "lfd/scene_animation.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace lfd {
namespace {

struct LocalTrs {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
};

glm::quat quatFromXyzw(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

// Value of one channel at `time`: clamped outside the key range; STEP holds the previous
// key; LINEAR lerps (T/S) or takes the shortest-path slerp (R), as glTF specifies.
glm::vec4 sampleChannel(const AnimationChannel& channel, float time)
{
    const std::vector<float>& t = channel.times;
    if (time <= t.front())
        return channel.values.front();
    if (time >= t.back())
        return channel.values.back();
    // First key strictly greater than time; the segment is [i-1, i].
    const size_t i = size_t(std::upper_bound(t.begin(), t.end(), time) - t.begin());
    const glm::vec4& a = channel.values[i - 1];
    const glm::vec4& b = channel.values[i];
    if (channel.interpolation == Interpolation::Step)
        return a;
    const float u = (time - t[i - 1]) / (t[i] - t[i - 1]);
    if (channel.path == AnimationPath::Rotation) {
        const glm::quat q = glm::slerp(quatFromXyzw(a), quatFromXyzw(b), u); // glm takes the short path
        return glm::vec4(q.x, q.y, q.z, q.w);
    }
    return glm::mix(a, b, u);
}

} // namespace

std::vector<glm::mat4> nodeWorldMatrices(const Scene& scene, float time)
{
    std::vector<LocalTrs> local(scene.nodes.size());
    for (size_t n = 0; n < scene.nodes.size(); ++n)
        local[n] = {scene.nodes[n].translation, scene.nodes[n].rotation, scene.nodes[n].scale};

    for (const Animation& animation : scene.animations) {
        for (const AnimationChannel& channel : animation.channels) {
            if (channel.node >= local.size() || channel.times.empty())
                continue; // validated packs never get here; imported scenes are checked too
            const glm::vec4 v = sampleChannel(channel, time);
            switch (channel.path) {
            case AnimationPath::Translation: local[channel.node].translation = glm::vec3(v); break;
            case AnimationPath::Rotation: local[channel.node].rotation = glm::normalize(quatFromXyzw(v)); break;
            case AnimationPath::Scale: local[channel.node].scale = glm::vec3(v); break;
            case AnimationPath::Weights: break; // morphWeights
            }
        }
    }

    // Parents precede children (a Scene invariant), so one forward pass composes
    // sceneFromNode = sceneFromParent * T * R * S.
    std::vector<glm::mat4> sceneFromNode(scene.nodes.size());
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
        const LocalTrs& l = local[n];
        const glm::mat4 parentFromNode = glm::translate(glm::mat4(1.0f), l.translation) *
                                         glm::mat4_cast(l.rotation) *
                                         glm::scale(glm::mat4(1.0f), l.scale);
        const int32_t parent = scene.nodes[n].parent;
        sceneFromNode[n] = (parent >= 0 && size_t(parent) < n) ? sceneFromNode[size_t(parent)] * parentFromNode
                                                               : parentFromNode;
    }
    return sceneFromNode;
}

std::vector<float> morphWeights(const Scene& scene, float time)
{
    const size_t targets = scene.vertices.deform.morphTargets;
    std::vector<float> weights(scene.deformers.size() * targets, 0.0f);
    std::vector<int32_t> deformerOf(scene.nodes.size(), kNone);
    for (size_t d = 0; d < scene.deformers.size(); ++d) {
        const Deformer& deformer = scene.deformers[d];
        if (deformer.node < deformerOf.size())
            deformerOf[deformer.node] = int32_t(d);
        std::copy_n(deformer.weights.begin(), std::min(targets, deformer.weights.size()),
                    weights.begin() + std::ptrdiff_t(d * targets));
    }
    for (const Animation& animation : scene.animations)
        for (const AnimationChannel& channel : animation.channels) {
            if (channel.path != AnimationPath::Weights || channel.node >= deformerOf.size() ||
                deformerOf[channel.node] == kNone || channel.times.empty())
                continue;
            const glm::vec4 v = sampleChannel(channel, time);
            const size_t base = size_t(deformerOf[channel.node]) * targets;
            for (uint32_t k = 0; k < 4 && channel.weightOffset + k < targets; ++k)
                weights[base + channel.weightOffset + k] = v[glm::length_t(k)];
        }
    return weights;
}

float animationDuration(const Scene& scene)
{
    float duration = 0.0f;
    for (const Animation& animation : scene.animations)
        for (const AnimationChannel& channel : animation.channels)
            if (!channel.times.empty())
                duration = std::max(duration, channel.times.back());
    return duration;
}

} // namespace lfd
