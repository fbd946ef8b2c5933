// Visiting every per-vertex stream of a scene, for the stages that reorder or drop
// vertices (deformers.cpp, simplification.cpp): a stream forgotten there would no longer
// line up with the positions.
#pragma once

#include "lfd/scene.h"

#include <cstddef>

namespace lfd::bake {

// Calls fn(stream, slots) for every per-vertex stream of `v`; `slots` is the entries per
// vertex (1, or DeformationStreams::morphTargets for the morph deltas, which may be 0).
template <class Fn>
void forEachStream(VertexStreams& v, Fn&& fn)
{
    const size_t k = v.deform.morphTargets;
    fn(v.positions, 1);
    fn(v.normals, 1);
    fn(v.tangents, 1);
    fn(v.uvs, 1);
    fn(v.deform.joints, 1);
    fn(v.deform.weights, 1);
    fn(v.deform.positions, k);
    fn(v.deform.normals, k);
    fn(v.deform.tangents, k);
}

} // namespace lfd::bake
