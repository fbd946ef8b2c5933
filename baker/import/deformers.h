// Skinned and morphed meshes in the scene: each deformer's mesh its own, its vertices one range.
#pragma once

#include "lfd/scene.h"

#include <string>

namespace lfd::bake {

// Gives every deformer's node a mesh no other node instances (copies of the mesh's
// primitives and vertices; `file` names the input in the error past 2^32 vertices).
void isolateDeformedMeshes(Scene& scene, const std::string& file);
// Reorders the vertices so each deformer's mesh is one contiguous range (vertices of no
// deformer first) and sets Deformer::firstVertex / vertexCount. Run after import and
// after tessellation (which appends new vertices at the end).
void assignDeformerVertices(Scene& scene);

} // namespace lfd::bake
