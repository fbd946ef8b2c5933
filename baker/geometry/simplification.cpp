// Simplification stage (simplification.h; issue 40): meshoptimizer's edge-collapse
// simplifier (Garland-Heckbert quadrics) bounded by a geometric error in view pixels.
//
// Threads (issue 9, parallel.h): primitives are simplified side by side, each reading the
// scene and writing its triangles into its own slot; the index buffer is then rebuilt in
// primitive order and unused vertices dropped in vertex order, exactly as a serial run
// would. meshopt_simplify itself is deterministic, so the pack is the same bytes for any
// thread count.
#include "simplification.h"

#include "deformers.h"
#include "parallel.h"
#include "scene_bounds.h"
#include "vertex_streams_each.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>

namespace lfd::bake {
namespace {

// An index not assigned yet (a vertex not mapped, a primitive no mesh owns).
constexpr uint32_t kNoIndex = std::numeric_limits<uint32_t>::max();

// meshoptimizer's error (the square root of the collapse's quadric error: distance to
// the planes of the faces merged so far) underestimates how far the input's vertices end
// up from the simplified surface: on the test heightfields the measured vertical distance
// reached 2.3 times it (simplification_test.cpp). So meshoptimizer is given this share of
// the bound, and its error is reported divided by it: an input vertex then stays within
// the bound, and the report does not understate.
constexpr double kQuadricShare = 0.4;

// What meshoptimizer sees of one welded vertex: every attribute the pack stores, so that
// only vertices equal in all of them are welded (absent streams read as zeros).
struct WeldKey {
    float position[3];
    float normal[3];
    float tangent[4];
    float uv[2];
};
static_assert(sizeof(WeldKey) == 12 * sizeof(float));

struct PrimitiveResult {
    bool changed = false;
    std::vector<uint32_t> indices; // scene vertices; set when changed
    double errorObject = 0.0;      // meshoptimizer's largest error, object units
    size_t lockedSeamVertices = 0;
};

// The primitive's vertices numbered locally, in first-use order.
struct LocalVertices {
    std::vector<uint32_t> sceneVertex; // local -> scene vertex
    std::vector<uint32_t> local;       // the primitive's indices, local numbering
};

LocalVertices numberLocally(const uint32_t* in, size_t n)
{
    LocalVertices r;
    const auto [lo, hi] = std::minmax_element(in, in + n);
    std::vector<uint32_t> localOf(size_t(*hi - *lo) + 1, kNoIndex);
    r.local.resize(n);
    for (size_t i = 0; i < n; ++i) {
        uint32_t& l = localOf[in[i] - *lo];
        if (l == kNoIndex) {
            l = uint32_t(r.sceneVertex.size());
            r.sceneVertex.push_back(in[i]);
        }
        r.local[i] = l;
    }
    return r;
}

// Vertices equal in every attribute, welded (a triangle soup becomes connected).
struct WeldedVertices {
    size_t count = 0;
    std::vector<uint32_t> representative; // welded -> scene vertex (the first local one)
    std::vector<float> positions;         // welded -> xyz
};

// Welds the local vertices and renumbers `local` to the welded ones.
WeldedVertices weld(const VertexStreams& v, const std::vector<uint32_t>& sceneVertex, std::vector<uint32_t>& local)
{
    // note: adding +0.0f turns -0.0f into +0.0f, so positions that compare equal weld.
    std::vector<WeldKey> keys(sceneVertex.size(), WeldKey{});
    for (size_t l = 0; l < sceneVertex.size(); ++l) {
        const uint32_t s = sceneVertex[l];
        WeldKey& k = keys[l];
        for (int c = 0; c < 3; ++c)
            k.position[c] = v.positions[s][c] + 0.0f;
        if (!v.normals.empty())
            for (int c = 0; c < 3; ++c)
                k.normal[c] = v.normals[s][c];
        if (!v.tangents.empty())
            for (int c = 0; c < 4; ++c)
                k.tangent[c] = v.tangents[s][c];
        if (!v.uvs.empty())
            for (int c = 0; c < 2; ++c)
                k.uv[c] = v.uvs[s][c];
    }
    std::vector<uint32_t> weldOf(sceneVertex.size());
    WeldedVertices w;
    w.count = meshopt_generateVertexRemap(weldOf.data(), local.data(), local.size(), keys.data(), keys.size(),
                                          sizeof(WeldKey));
    w.representative.assign(w.count, kNoIndex);
    w.positions.resize(w.count * 3);
    for (size_t l = 0; l < sceneVertex.size(); ++l) {
        const uint32_t i = weldOf[l];
        if (w.representative[i] == kNoIndex) {
            w.representative[i] = sceneVertex[l];
            std::copy(keys[l].position, keys[l].position + 3, w.positions.begin() + ptrdiff_t(i) * 3);
        }
    }
    for (uint32_t& i : local)
        i = weldOf[i];
    return w;
}

// Seams: welded vertices sharing a position carry different attributes. Each copy after
// the first moves by its own count of float ulps in x, so meshoptimizer no longer
// joins the two sides: the seam becomes two borders, which LockBorder keeps in place.
// (meshopt_simplify 0.18 would otherwise collapse along seams, moving seam vertices,
// and has no per-vertex lock.) The shift only affects the quadrics, by ~1e-7 relative;
// the output uses the scene's own vertices. Returns the seam vertices so locked.
size_t separateSeams(std::vector<float>& positions, size_t welded)
{
    std::vector<uint32_t> positionOf(welded);
    const size_t distinct =
        meshopt_generateVertexRemap(positionOf.data(), nullptr, welded, positions.data(), welded, 3 * sizeof(float));
    std::vector<uint32_t> copies(distinct, 0);
    for (size_t w = 0; w < welded; ++w)
        ++copies[positionOf[w]];
    std::vector<uint32_t> seen(distinct, 0);
    size_t locked = 0;
    for (size_t w = 0; w < welded; ++w) {
        const uint32_t p = positionOf[w];
        if (copies[p] < 2)
            continue;
        ++locked;
        float& x = positions[w * 3];
        for (uint32_t k = 0; k < seen[p]; ++k)
            x = std::nextafter(x, std::numeric_limits<float>::infinity());
        ++seen[p];
    }
    return locked;
}

// One primitive, on its own (its borders, material boundaries included, stay).
PrimitiveResult simplifyPrimitive(const Scene& scene, const Primitive& prim, double maxErrorObject)
{
    PrimitiveResult result;
    const size_t n = prim.indexCount;
    if (n < 6)
        return result; // one triangle: nothing to merge
    LocalVertices vertices = numberLocally(scene.indices.data() + prim.firstIndex, n);
    WeldedVertices welded = weld(scene.vertices, vertices.sceneVertex, vertices.local);
    result.lockedSeamVertices = separateSeams(welded.positions, welded.count);

    // meshoptimizer's error is relative to the mesh extent (meshopt_simplifyScale).
    const float extent = meshopt_simplifyScale(welded.positions.data(), welded.count, 3 * sizeof(float));
    if (!(extent > 0.0f) || !std::isfinite(extent))
        return result;
    const auto relative = float(kQuadricShare * maxErrorObject / double(extent));
    std::vector<uint32_t> out(n);
    float error = 0.0f;
    const size_t kept = meshopt_simplify(out.data(), vertices.local.data(), n, welded.positions.data(), welded.count,
                                         3 * sizeof(float), 0, relative, meshopt_SimplifyLockBorder, &error);
    if (kept >= n)
        return result; // nothing merged: the primitive stays exactly as it was
    out.resize(kept);
    for (uint32_t& i : out)
        i = welded.representative[i];
    result.changed = true;
    result.indices = std::move(out);
    result.errorObject = double(error) * double(extent) / kQuadricShare;
    return result;
}

// New index buffer: primitives in index order, simplified ones replaced; triangles
// outside any primitive are carried over unchanged (as tessellation's rebuild does).
void rebuildIndexBuffer(Scene& scene, std::vector<PrimitiveResult>& results)
{
    std::vector<uint32_t> order(scene.primitives.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return scene.primitives[a].firstIndex < scene.primitives[b].firstIndex;
    });
    std::vector<uint32_t> indices;
    indices.reserve(scene.indices.size());
    uint32_t cursor = 0; // next old index not yet copied
    for (uint32_t p : order) {
        Primitive& prim = scene.primitives[p];
        if (prim.firstIndex > cursor)
            indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.begin() + prim.firstIndex);
        const uint32_t end = prim.firstIndex + prim.indexCount;
        const auto first = uint32_t(indices.size());
        if (results[p].changed)
            indices.insert(indices.end(), results[p].indices.begin(), results[p].indices.end());
        else if (end > cursor) // a primitive overlapping one already copied keeps its own triangles
            indices.insert(indices.end(), scene.indices.begin() + prim.firstIndex, scene.indices.begin() + end);
        cursor = std::max(cursor, end);
        prim.firstIndex = first;
        prim.indexCount = uint32_t(indices.size()) - first;
        std::vector<uint32_t>().swap(results[p].indices);
    }
    indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.end());
    scene.indices = std::move(indices);
}

// Drops the vertices in `candidates` that no triangle uses any more; the others keep their
// order (so deformers' ranges stay contiguous and are only renumbered).
void dropUnusedVertices(Scene& scene, const std::vector<uint8_t>& candidates)
{
    const size_t n = scene.vertices.size();
    std::vector<uint8_t> used(n, 0);
    for (uint32_t i : scene.indices)
        used[i] = 1;
    std::vector<uint32_t> newIndex(n, kNoIndex);
    uint32_t next = 0;
    for (size_t i = 0; i < n; ++i)
        if (used[i] || !candidates[i])
            newIndex[i] = next++;
    if (next == n)
        return;
    for (uint32_t& i : scene.indices)
        i = newIndex[i];
    forEachStream(scene.vertices, [&](auto& stream, size_t slots) {
        if (stream.empty() || slots == 0)
            return;
        for (size_t i = 0; i < n; ++i)
            if (newIndex[i] != kNoIndex && newIndex[i] != i)
                for (size_t s = 0; s < slots; ++s)
                    stream[size_t(newIndex[i]) * slots + s] = stream[i * slots + s];
        stream.resize(size_t(next) * slots);
    });
    assignDeformerVertices(scene); // deformers' first vertices moved down
}

} // namespace

SimplificationStats simplifyMeshes(Scene& scene, const std::vector<double>& maxErrorObject,
                                   const std::vector<double>& pxPerObject, const Log& log, unsigned threads)
{
    if (maxErrorObject.size() != scene.meshes.size() || pxPerObject.size() != scene.meshes.size())
        throw BakeError("simplification: bound list does not match the mesh count");
    SimplificationStats stats;
    stats.trianglesIn = scene.triangleCount();
    stats.verticesIn = scene.vertices.size();

    std::vector<uint8_t> deformed(scene.meshes.size(), 0);
    for (const Deformer& d : scene.deformers)
        if (d.node < scene.nodes.size() && scene.nodes[d.node].mesh >= 0)
            deformed[size_t(scene.nodes[d.node].mesh)] = 1;

    // Work items: the primitives of every mesh with a bound; the mesh owning each.
    std::vector<uint32_t> items, ownerOf(scene.primitives.size(), kNoIndex);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        if (!usableBound(maxErrorObject[m]) || deformed[m])
            continue;
        const Mesh& mesh = scene.meshes[m];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p)
            if (ownerOf[p] == kNoIndex) {
                ownerOf[p] = uint32_t(m);
                items.push_back(p);
            }
    }
    std::vector<PrimitiveResult> results(scene.primitives.size());
    parallelFor(items.size(), threads, [&](size_t i) {
        const uint32_t p = items[i];
        results[p] = simplifyPrimitive(scene, scene.primitives[p], maxErrorObject[ownerOf[p]]);
    });

    // Per-mesh report lines (before the index buffer is rebuilt: counts come from it).
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        SimplifiedMesh line;
        line.name = mesh.name.empty() ? "mesh " + std::to_string(m) : mesh.name;
        bool drawn = usableBound(maxErrorObject[m]);
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            const PrimitiveResult& r = results[p];
            line.trianglesIn += scene.primitives[p].indexCount / 3;
            line.trianglesOut += (r.changed ? r.indices.size() : scene.primitives[p].indexCount) / 3;
            line.maxErrorPx = std::max(line.maxErrorPx, r.errorObject * pxPerObject[m]);
            stats.lockedSeamVertices += r.lockedSeamVertices;
        }
        if (!drawn)
            continue;
        if (deformed[m])
            line.leftWhole = "skinned/morphed: left whole";
        stats.maxErrorPx = std::max(stats.maxErrorPx, line.maxErrorPx);
        stats.meshes.push_back(line);
    }

    std::vector<uint8_t> candidates(scene.vertices.size(), 0);
    bool anyChanged = false;
    for (uint32_t p : items)
        if (results[p].changed) {
            anyChanged = true;
            const Primitive& prim = scene.primitives[p];
            for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; ++i)
                candidates[scene.indices[i]] = 1;
        }
    if (anyChanged) {
        rebuildIndexBuffer(scene, results);
        dropUnusedVertices(scene, candidates);
        scene.triangleStats.clear(); // no longer lines up with the triangles
    }
    stats.trianglesOut = scene.triangleCount();
    stats.verticesOut = scene.vertices.size();
    log.info("simplification: " + std::to_string(stats.trianglesIn) + " -> " + std::to_string(stats.trianglesOut) +
             " triangles, " + std::to_string(stats.verticesIn) + " -> " + std::to_string(stats.verticesOut) +
             " vertices");
    return stats;
}

SimplificationStats simplifyScene(Scene& scene, double errorPx, double viewPixelWorld, const Log& log,
                                  unsigned threads)
{
    if (!(errorPx > 0.0) || !std::isfinite(errorPx)) {
        SimplificationStats off;
        off.trianglesIn = off.trianglesOut = scene.triangleCount();
        off.verticesIn = off.verticesOut = scene.vertices.size();
        return off;
    }
    if (!(viewPixelWorld > 0.0) || !std::isfinite(viewPixelWorld))
        throw BakeError("simplification: the view pixel size must be positive, got " + std::to_string(viewPixelWorld));
    // Meshes are in object space and may be instanced at several scales: the largest
    // scale (the largest on-screen size) decides, as for the tessellation bound.
    const std::vector<float> scale = meshMaxWorldScale(scene);
    std::vector<double> maxErrorObject(scene.meshes.size(), 0.0), pxPerObject(scene.meshes.size(), 0.0);
    for (size_t m = 0; m < scale.size() && m < scene.meshes.size(); ++m)
        if (std::isfinite(scale[m]) && scale[m] > 0.0f) { // unused meshes: untouched
            maxErrorObject[m] = errorPx * viewPixelWorld / double(scale[m]);
            pxPerObject[m] = double(scale[m]) / viewPixelWorld;
        }
    SimplificationStats stats = simplifyMeshes(scene, maxErrorObject, pxPerObject, log, threads);
    stats.boundPx = errorPx;
    return stats;
}

} // namespace lfd::bake
