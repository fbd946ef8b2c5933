// The texture budget: the largest texture size the views can resolve.
#pragma once

#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lfd::bake {

// "Model no more than the scene needs": the largest size texture `textureIndex` needs so
// that its texels are no finer than `detail` times the finest view pixel that can land on
// any triangle using it (viewPixelWorld: conservative scene units per view pixel, see
// framing.h; meshScale: meshMaxWorldScale). Texture area is measured in the texture's own
// uv space (the sampling slot's texture transform applied: a tiled texture needs fewer
// texels). Returns sourceSize reduced by a power of two (never enlarged); triangles
// without texture area are ignored.
glm::uvec2 resolvableTextureSize(const Scene& scene, uint32_t textureIndex, glm::uvec2 sourceSize,
                                 double viewPixelWorld, const std::vector<float>& meshScale,
                                 double detail);

} // namespace lfd::bake
