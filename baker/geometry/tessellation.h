// The tessellation stage (tessellateScene), the splitting core with per-mesh bounds given
// directly (tests, tools), and an OpenMesh topology check used to verify that tessellation
// left closed meshes closed.
#pragma once

#include "bake_log.h"
#include "lfd/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lfd::bake {

struct TessellationStats {
    size_t trianglesIn = 0;
    size_t trianglesOut = 0;
    size_t trianglesSplit = 0;        // input triangles that were oversized
    double maxEdgeWorldBefore = 0.0;  // longest edge in scene units (after instance scale)
    double maxEdgeWorldAfter = 0.0;
    // Mean edge length after, scene units: over every output triangle's edges, and over
    // the edges of the pieces of split triangles only (how close to the bound cuts land).
    double meanEdgeWorldAfter = 0.0;
    double meanPieceEdgeWorld = 0.0;
    // New points lie on OpenSubdiv's bilinear surface of each welded mesh that has
    // triangles to split (bilinear_surface.h): meshes it took and meshes it refused, and
    // split triangles whose interior points were placed by barycentric weights of their
    // corners instead (a refused mesh, or a face Bfr gave no surface).
    size_t surfaceMeshes = 0;
    size_t surfaceMeshesRefused = 0;
    size_t surfaceFallbacks = 0;
};

// Cuts every triangle with a scene-space edge longer than maxEdgeWorld (edges are scaled
// per mesh by meshMaxWorldScale). Each edge is cut into ceil(length / bound) equal pieces
// by a rule that depends only on the (position-welded) edge itself, so neighbouring
// triangles - including across UV/normal seams - cut shared edges identically: no
// T-junctions. Oversized faces are filled by OpenSubdiv's Bfr::Tessellation for their
// edge rates, checked to keep every output edge within the bound (face_pattern.h); new
// points lie on OpenSubdiv's bilinear Bfr::Surface of the welded mesh.
// Attributes are interpolated from each face's own corners; normals/tangents
// re-normalised. Triangles within the bound are left untouched. Updates primitives'
// index ranges. Meshes are tessellated on up to `threads` threads at once (0: one per
// hardware thread); the result is the same for any thread count (parallel.h).
TessellationStats tessellateScene(Scene& scene, double maxEdgeWorld, const Log& log, unsigned threads = 0);

// tessellateScene without the scene graph: maxEdgeObject[m] is the bound for mesh m in
// its own object units (+infinity, NaN or <= 0 leaves the mesh untouched) and
// meshScale[m] the factor that converts its lengths to scene units (reported in
// TessellationStats only). Both vectors must have scene.meshes.size() entries. `threads`
// as for tessellateScene.
TessellationStats tessellateMeshes(Scene& scene, const std::vector<double>& maxEdgeObject,
                                   const std::vector<float>& meshScale, const Log& log, unsigned threads = 0);

// Topology of one mesh after welding vertices with bit-identical positions (UV/normal
// seams closed), built as an OpenMesh TriMesh.
struct MeshTopology {
    size_t weldedVertices = 0;
    size_t faces = 0;           // faces OpenMesh accepted
    size_t degenerateFaces = 0; // two corners weld to one vertex: skipped
    size_t rejectedFaces = 0;   // non-manifold or inconsistently oriented: OpenMesh refused
    size_t boundaryEdges = 0;   // edges with a face on one side only (holes, cracks, T-junctions)

    // Closed, consistently oriented 2-manifold: what a watertight input stays after
    // crack-free tessellation.
    bool closedManifold() const { return boundaryEdges == 0 && rejectedFaces == 0; }
};

MeshTopology meshTopology(const Scene& scene, uint32_t mesh);
size_t countBoundaryEdges(const Scene& scene, uint32_t mesh);

} // namespace lfd::bake
