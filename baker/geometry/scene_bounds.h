// The bounds stage: scene-space bounds over the rest pose and every animation key.
#pragma once

#include "lfd/scene.h"

#include <cmath>
#include <vector>

namespace lfd::bake {

// Bounds over the rest pose and every animation key time (node transforms come from
// lfd::nodeWorldMatrices in formats/, shared with the player).
SceneBounds computeBounds(const Scene& scene);
// Largest linear scale each mesh receives from any node instance at any animation key
// (max column length of the world matrix); 0 for meshes no node uses.
std::vector<float> meshMaxWorldScale(const Scene& scene);
// Whether a per-mesh bound in object units (a view pixel's size divided by the mesh's
// meshMaxWorldScale) applies: finite and positive. The tessellation and simplification
// stages give a mesh no node draws (scale 0) an infinite or zero bound, and leave it as is.
inline bool usableBound(double bound) { return std::isfinite(bound) && bound > 0.0; }

} // namespace lfd::bake
