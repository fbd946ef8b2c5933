// Extra entry points of tessellation.cpp beyond the stage declared in bake.h: the
// splitting core with per-mesh bounds given directly (tests, tools), and an OpenMesh
// topology check used to verify that tessellation left closed meshes closed.
#pragma once

#include "bake.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lfd::bake {

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
