// The bounds stage: scene-space bounds over the rest pose and every animation key.
#pragma once

#include "lfd/scene.h"

#include <vector>

namespace lfd::bake {

// Bounds over the rest pose and every animation key time (node transforms come from
// lfd::nodeWorldMatrices in formats/, shared with the player).
SceneBounds computeBounds(const Scene& scene);
// Largest linear scale each mesh receives from any node instance at any animation key
// (max column length of the world matrix); 0 for meshes no node uses.
std::vector<float> meshMaxWorldScale(const Scene& scene);

} // namespace lfd::bake
