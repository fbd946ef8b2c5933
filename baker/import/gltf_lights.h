// KHR_lights_punctual import (internal to the baker; Khronos extension specification):
// the document's lights, instanced by the nodes that name one. The JSON is checked by
// gltf_validation.cpp first (types, the type enum, spot cones, indices).
#pragma once

#include "lfd/scene.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// One lfd::Light for every node of the imported hierarchy that carries a light, in scene
// node order (`newIndex`: glTF node -> scene node, or kNone for a node outside the
// imported scene). A light on such a node is dropped with a warning appended to
// `warnings`. Values are clamped as the validation reported (colour to [0, 1], intensity
// >= 0, cone angles to [0, pi/2]; a range <= 0 means unlimited); one that is not finite as
// an f32 throws BakeError naming `file`.
std::vector<Light> convertLights(const tinygltf::Model& model, const std::vector<int32_t>& newIndex,
                                 const std::string& file, std::vector<std::string>& warnings);

} // namespace lfd::bake::gltf
