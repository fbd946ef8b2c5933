// Deformed instances: every node instance of a skinned or morphed mesh poses its own
// vertices (the player writes them over the mesh's streams), so it needs a mesh no other
// node shares and one contiguous vertex range (lfd::Deformer).
#include "deformers.h"

#include "bake_log.h"
#include "vertex_streams_each.h"

#include <algorithm>
#include <numeric>

namespace lfd::bake {
namespace {

// The vertices mesh m's primitives use, ascending, each once.
std::vector<uint32_t> meshVertexList(const Scene& scene, uint32_t m)
{
    std::vector<uint32_t> list;
    const Mesh& mesh = scene.meshes[m];
    for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
        const Primitive& prim = scene.primitives[p];
        list.insert(list.end(), scene.indices.begin() + prim.firstIndex,
                    scene.indices.begin() + prim.firstIndex + prim.indexCount);
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    return list;
}

// Appends a copy of mesh m (its primitives, indices, statistics and vertices); returns its index.
int32_t duplicateMesh(Scene& scene, uint32_t m, const std::string& file)
{
    const std::vector<uint32_t> vertices = meshVertexList(scene, m);
    const size_t base = scene.vertices.size();
    if (base + vertices.size() > UINT32_MAX)
        throw BakeError(file + ": more than 2^32 vertices after giving each deformed instance its own mesh");
    std::vector<uint32_t> remap(base, UINT32_MAX);
    for (size_t i = 0; i < vertices.size(); ++i)
        remap[vertices[i]] = uint32_t(base + i);
    forEachStream(scene.vertices, [&](auto& stream, size_t slots) {
        if (stream.empty() || slots == 0)
            return;
        for (uint32_t v : vertices)
            for (size_t s = 0; s < slots; ++s)
                stream.push_back(stream[v * slots + s]);
    });
    Mesh copy = scene.meshes[m];
    copy.name += " (instance)";
    copy.firstPrimitive = uint32_t(scene.primitives.size());
    for (uint32_t p = 0; p < scene.meshes[m].primitiveCount; ++p) {
        Primitive prim = scene.primitives[scene.meshes[m].firstPrimitive + p];
        const uint32_t first = prim.firstIndex;
        prim.firstIndex = uint32_t(scene.indices.size());
        for (uint32_t i = first; i < first + prim.indexCount; ++i)
            scene.indices.push_back(remap[scene.indices[i]]);
        if (!scene.triangleStats.empty())
            for (uint32_t t = first / 3; t < (first + prim.indexCount) / 3; ++t)
                scene.triangleStats.push_back(scene.triangleStats[t]);
        scene.primitives.push_back(prim);
    }
    scene.meshes.push_back(copy);
    return int32_t(scene.meshes.size() - 1);
}

} // namespace

void isolateDeformedMeshes(Scene& scene, const std::string& file)
{
    std::vector<uint32_t> users(scene.meshes.size(), 0);
    for (const Node& node : scene.nodes)
        if (node.mesh != kNone)
            ++users[size_t(node.mesh)];
    for (const Deformer& d : scene.deformers) {
        Node& node = scene.nodes[d.node];
        if (users[size_t(node.mesh)] > 1) {
            --users[size_t(node.mesh)];
            node.mesh = duplicateMesh(scene, uint32_t(node.mesh), file);
        }
    }
}

void assignDeformerVertices(Scene& scene)
{
    if (scene.deformers.empty())
        return;
    // New order: vertices of no deformer first (as they were), then each deformer's.
    const size_t n = scene.vertices.size();
    std::vector<uint32_t> owner(n, UINT32_MAX);
    std::vector<std::vector<uint32_t>> lists;
    for (size_t d = 0; d < scene.deformers.size(); ++d) {
        lists.push_back(meshVertexList(scene, uint32_t(scene.nodes[scene.deformers[d].node].mesh)));
        for (uint32_t v : lists.back())
            owner[v] = uint32_t(d);
    }
    std::vector<uint32_t> order; // new vertex -> old vertex
    order.reserve(n);
    for (uint32_t v = 0; v < n; ++v)
        if (owner[v] == UINT32_MAX)
            order.push_back(v);
    for (size_t d = 0; d < lists.size(); ++d) {
        scene.deformers[d].firstVertex = uint32_t(order.size());
        scene.deformers[d].vertexCount = uint32_t(lists[d].size());
        order.insert(order.end(), lists[d].begin(), lists[d].end());
    }
    std::vector<uint32_t> newIndex(n);
    for (size_t i = 0; i < n; ++i)
        newIndex[order[i]] = uint32_t(i);
    for (uint32_t& i : scene.indices)
        i = newIndex[i];
    forEachStream(scene.vertices, [&](auto& stream, size_t slots) {
        if (stream.empty() || slots == 0)
            return;
        auto old = stream;
        for (size_t i = 0; i < n; ++i)
            for (size_t s = 0; s < slots; ++s)
                stream[i * slots + s] = old[order[i] * slots + s];
    });
}

} // namespace lfd::bake
