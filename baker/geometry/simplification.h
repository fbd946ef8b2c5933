// Simplification stage (issue 40): "model no more than the scene needs", the other half of
// the tessellation bound. Where tessellation splits triangles longer than the display can
// show in one piece, this stage merges triangles finer than it resolves, so that scanned,
// photogrammetry and CAD meshes do not make every renderer pay for detail no view pixel
// shows. The error bound is in view pixels of the baked-for display, measured exactly as
// the tessellation bound is (minViewPixelWorld, framing.h: a view pixel's footprint at the
// scene's nearest point), so one display profile decides both. lfd-bake runs it before
// tessellation: merge what is too small, then split what is too long.
#pragma once

#include "bake_log.h"
#include "lfd/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lfd::bake {

struct SimplifiedMesh {
    std::string name;
    size_t trianglesIn = 0;
    size_t trianglesOut = 0;
    double maxErrorPx = 0.0; // largest geometric error of its primitives, view pixels
    // Why the mesh was left whole (empty when it was simplified): skinned/morphed meshes,
    // which meshoptimizer 0.18 cannot simplify with their weights and targets.
    std::string leftWhole;
};

struct SimplificationStats {
    double boundPx = 0.0; // the bound asked for; 0: the stage was off
    size_t trianglesIn = 0;
    size_t trianglesOut = 0;
    size_t verticesIn = 0;
    size_t verticesOut = 0;
    double maxErrorPx = 0.0;
    // Vertices kept in place because they lie on an attribute seam (one position, several
    // uv/normal/tangent values) or a border (mesh border, or a material boundary: every
    // primitive is simplified on its own).
    size_t lockedSeamVertices = 0;
    std::vector<SimplifiedMesh> meshes; // every mesh some node draws, in mesh order
};

// Simplifies every mesh some node draws to within `errorPx` view pixels, where one view
// pixel is `viewPixelWorld` scene units (minViewPixelWorld of the framing). Instanced
// meshes are simplified once, for their largest on-screen size (meshMaxWorldScale).
// errorPx <= 0 leaves the scene as it is. `threads` as for tessellateScene; the result is
// the same for any thread count.
SimplificationStats simplifyScene(Scene& scene, double errorPx, double viewPixelWorld, const Log& log,
                                  unsigned threads = 0);

// The core with per-mesh bounds in object units given directly (tests, tools):
// maxErrorObject[m] <= 0, NaN or infinite leaves mesh m whole; pxPerObject[m] converts
// its object-space errors to the view pixels reported (1 reports object units). Both
// vectors must have scene.meshes.size() entries.
//
// Per primitive (so material boundaries stay where they are): vertices equal in every
// attribute are welded, so a triangle soup simplifies like the indexed mesh it is; the
// welded mesh goes to meshopt_simplify with meshopt_SimplifyLockBorder and no triangle
// target, only the error bound. Seams are kept exactly: every vertex whose position is
// shared by welded vertices with other attributes is presented to meshoptimizer at a
// position one or more float ulps away, which splits the seam into two borders that
// meshopt_SimplifyLockBorder then keeps (0.18 has no per-vertex lock). Output triangles
// use the input's own vertices (a subset: no new positions, uvs or normals); vertices no
// triangle uses any more are dropped, the others keep their order. Skinned and morphed
// meshes are left whole with a note. Triangle statistics are cleared (computed later on
// the simplified mesh).
SimplificationStats simplifyMeshes(Scene& scene, const std::vector<double>& maxErrorObject,
                                   const std::vector<double>& pxPerObject, const Log& log, unsigned threads = 0);

} // namespace lfd::bake
