// Rigid node animation, shared by the baker (bounds over animation) and the player
// (per-frame transforms): glTF semantics, LINEAR (lerp / shortest-path slerp) and STEP,
// clamped outside each channel's key range.
#pragma once

#include "lfd/scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace lfd {

// sceneFromNode for every node at `time` seconds (parents before children).
std::vector<glm::mat4> nodeWorldMatrices(const Scene& scene, float time);

// Morph weights of every deformer at `time` (deformer d's at [d * morphTargets, +
// morphTargets)): Deformer::weights, overridden by the Weights channels on its node.
// glTF 3.11: weights interpolate linearly per component (no renormalisation).
std::vector<float> morphWeights(const Scene& scene, float time);

// Length of the longest animation (max last key time over channels), 0 without animation.
float animationDuration(const Scene& scene);

} // namespace lfd
