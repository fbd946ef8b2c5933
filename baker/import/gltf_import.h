// glTF 2.0 -> lfd::Scene: the import stage for glTF input.
#pragma once

#include "bake_log.h"
#include "imported_scene.h"

#include <filesystem>

namespace lfd::bake {

// Reads .gltf (external .bin / images or data URIs) and .glb. Converts strips/fans to
// lists, de-indexes nothing (non-indexed primitives get an index buffer), keeps the node
// hierarchy (matrix nodes decomposed to TRS), animation channels (T/R/S and morph
// weights; LINEAR and STEP; CUBICSPLINE linearised with a warning), skins (JOINTS_0 /
// WEIGHTS_0 and further sets: the four largest influences, renormalised; inverse bind
// matrices) and morph targets (POSITION, NORMAL, TANGENT deltas): each node instance of a
// skinned or morphed mesh becomes a Deformer with a mesh of its own; KHR_texture_transform
// (Material::textureTransforms, texCoord overrides), KHR_materials_unlit and
// KHR_lights_punctual (a Light per node instance). Drops streams nothing uses. Draco- and
// meshopt-compressed geometry is decoded on up to `threads` threads (0: one per hardware
// thread). Errors (throw BakeError): unreadable/malformed file, streams that do not
// decode, required unsupported extensions, out-of-range accessors. Warnings name what is
// not supported: a skinned node whose mesh has no influences, morph attributes other than
// the three, more than four influences, non-triangle primitives, optional extensions.
ImportedScene importGltf(const std::filesystem::path& path, const Log& log, unsigned threads = 0);

} // namespace lfd::bake
