// Tessellation stage: split triangles that would span more than the view-pixel bound.
//
// Paper section 5: large triangles were "tessellated ... to ensure that they spanned no
// more than a hundred pixels", because point rendering only beats rasterisation on small
// triangles. DESIGN.md section 4: only oversized triangles are split, attributes are
// interpolated, and the result has no cracks (no T-junctions).
//
// Crack-freeness: vertices are welded per mesh by exact position, so the two sides of
// a UV/normal seam see the same welded edge. Whether an edge is split, and where its
// midpoint lies, depends only on that welded edge (its canonical endpoint positions and
// the mesh bound), never on the triangle being split. Each side therefore subdivides a
// shared edge into the same dyadic segments with bit-identical positions. Attributes of a
// midpoint come from the triangle's own corners, so each side of a seam keeps its own
// uv/normal at the shared position.

#include "tessellation.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

namespace lfd::bake {
namespace {

constexpr uint32_t kInvalid = std::numeric_limits<uint32_t>::max();
// note: 2^28 triangles are 3 GiB of indices alone; a bound this fine means a broken
// display profile or framing, not a scene anyone can pack or render.
constexpr size_t kMaxOutputTriangles = size_t(1) << 28;
static_assert(kMaxOutputTriangles * 3 < std::numeric_limits<uint32_t>::max(),
              "indices of the output must fit uint32_t");
// Every split at least halves one edge; a stack this deep means float precision ran out.
constexpr uint32_t kMaxDepth = 96;
// Input triangles between two progress lines on very large meshes.
constexpr size_t kProgressInterval = size_t(1) << 20;

// ---- Small open-addressing hash map ---------------------------------------------------
// The weld and midpoint maps see millions of inserts on big meshes; linear probing over
// two flat arrays allocates once per growth instead of once per entry.

uint64_t mix64(uint64_t x)
{
    // splitmix64 finaliser
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

struct PositionKey {
    uint32_t x = 0, y = 0, z = 0;
    bool operator==(const PositionKey&) const = default;
};

// note: adding +0.0f turns -0.0f into +0.0f, so positions that compare equal as floats
// get equal keys.
glm::vec3 canonicalPosition(const glm::vec3& p) { return p + glm::vec3(0.0f); }

PositionKey positionKey(const glm::vec3& canonical)
{
    return {std::bit_cast<uint32_t>(canonical.x), std::bit_cast<uint32_t>(canonical.y),
            std::bit_cast<uint32_t>(canonical.z)};
}

uint64_t hashKey(const PositionKey& k) { return mix64((uint64_t(k.x) << 32 | k.y) ^ mix64(k.z)); }
uint64_t hashKey(uint64_t k) { return mix64(k); }

uint64_t pairKey(uint32_t a, uint32_t b)
{
    return uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

template <typename Key>
class FlatMap {
public:
    explicit FlatMap(size_t expected = 0) { allocate(capacityFor(expected)); }

    // The value stored for key; stores `value` first when the key is absent.
    uint32_t findOrInsert(const Key& key, uint32_t value)
    {
        if ((size_ + 1) * 2 > values_.size())
            allocateAndMove(values_.size() * 2);
        size_t i = hashKey(key) & mask_;
        while (values_[i] != kInvalid) {
            if (keys_[i] == key)
                return values_[i];
            i = (i + 1) & mask_;
        }
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        return value;
    }

private:
    static size_t capacityFor(size_t expected)
    {
        size_t capacity = 16;
        while (capacity < expected * 2)
            capacity *= 2;
        return capacity;
    }

    void allocate(size_t capacity)
    {
        keys_.assign(capacity, Key{});
        values_.assign(capacity, kInvalid);
        mask_ = capacity - 1;
        size_ = 0;
    }

    void allocateAndMove(size_t capacity)
    {
        std::vector<Key> oldKeys = std::move(keys_);
        std::vector<uint32_t> oldValues = std::move(values_);
        allocate(capacity);
        for (size_t i = 0; i < oldValues.size(); ++i)
            if (oldValues[i] != kInvalid)
                findOrInsert(oldKeys[i], oldValues[i]);
    }

    std::vector<Key> keys_;
    std::vector<uint32_t> values_; // kInvalid marks an empty slot
    size_t mask_ = 0;
    size_t size_ = 0;
};

double edgeLength2(const glm::vec3& a, const glm::vec3& b)
{
    const double dx = double(b.x) - double(a.x);
    const double dy = double(b.y) - double(a.y);
    const double dz = double(b.z) - double(a.z);
    return dx * dx + dy * dy + dz * dz;
}

// ---- Splitting one mesh ---------------------------------------------------------------

// Splits the triangles of one mesh against one bound (object units). Holds the weld and
// midpoint maps, which must live as long as any triangle of the mesh is being split.
class MeshSplitter {
public:
    // weldOf: per-vertex welded id for the whole vertex buffer; entries of this mesh's
    // vertices are (re)written by weld(), new vertices are appended.
    MeshSplitter(VertexStreams& vertices, std::vector<uint32_t>& weldOf, double bound,
                 size_t expectedVertices)
        : v_(vertices), weldOf_(weldOf), bound2_(bound * bound),
          weldByPosition_(expectedVertices), midpointOf_(expectedVertices / 2)
    {
        weldPosition_.reserve(expectedVertices);
    }

    void weld(uint32_t vertex) { weldOf_[vertex] = weldId(v_.positions[vertex]); }

    // Appends triangle (a, b, c), or the pieces it splits into, to out (3 indices each).
    // Returns whether it was split.
    bool split(uint32_t a, uint32_t b, uint32_t c, std::vector<uint32_t>& out);

    size_t unresolved() const { return unresolved_; }

private:
    struct Tri {
        std::array<uint32_t, 3> v;
        uint32_t depth;
    };

    uint32_t weldId(const glm::vec3& position)
    {
        const glm::vec3 p = canonicalPosition(position);
        const auto next = uint32_t(weldPosition_.size());
        const uint32_t id = weldByPosition_.findOrInsert(positionKey(p), next);
        if (id == next)
            weldPosition_.push_back(p);
        return id;
    }

    // The split rule: a function of the welded edge only, so every triangle sharing it
    // (on either side of a seam) decides the same way.
    bool splitsEdge(uint32_t wa, uint32_t wb) const
    {
        if (wa == wb)
            return false;
        const glm::vec3& pLo = weldPosition_[std::min(wa, wb)];
        const glm::vec3& pHi = weldPosition_[std::max(wa, wb)];
        const double length2 = edgeLength2(pLo, pHi);
        if (!std::isfinite(length2) || !(length2 > bound2_))
            return false;
        // note: an edge whose midpoint rounds onto an endpoint cannot be split further
        // (float precision); keeping it avoids both an endless loop and a zero-length edge.
        const glm::vec3 mid = 0.5f * (pLo + pHi);
        return std::isfinite(mid.x) && std::isfinite(mid.y) && std::isfinite(mid.z) &&
               mid != pLo && mid != pHi;
    }

    uint32_t midpoint(uint32_t va, uint32_t vb);

    VertexStreams& v_;
    std::vector<uint32_t>& weldOf_;
    double bound2_;
    std::vector<glm::vec3> weldPosition_; // canonical position per welded id
    FlatMap<PositionKey> weldByPosition_;
    FlatMap<uint64_t> midpointOf_; // vertex pair -> midpoint vertex
    std::vector<Tri> stack_;
    size_t unresolved_ = 0;
};

// Midpoint vertex of the edge between vertices va and vb. One vertex per vertex pair:
// triangles that share both corner vertices (same side of any seam) share the midpoint,
// so the index topology stays connected.
uint32_t MeshSplitter::midpoint(uint32_t va, uint32_t vb)
{
    if (v_.positions.size() >= kInvalid)
        throw BakeError("tessellation: more than 2^32 - 1 vertices; raise the edge bound");
    const auto next = uint32_t(v_.positions.size());
    const uint32_t found = midpointOf_.findOrInsert(pairKey(va, vb), next);
    if (found != next)
        return found;

    // Position from the canonical welded pair: bit-identical on both sides of a seam.
    const uint32_t lo = std::min(va, vb);
    const uint32_t hi = std::max(va, vb);
    const uint32_t wLo = std::min(weldOf_[va], weldOf_[vb]);
    const uint32_t wHi = std::max(weldOf_[va], weldOf_[vb]);
    const glm::vec3 position = 0.5f * (weldPosition_[wLo] + weldPosition_[wHi]);
    v_.positions.push_back(position);

    // Attributes from this triangle's own corners, re-normalised where they are
    // directions. Opposite normals sum to ~0: keep one corner's rather than divide by 0.
    if (!v_.normals.empty()) {
        const glm::vec3 nLo = v_.normals[lo];
        const glm::vec3 sum = nLo + v_.normals[hi];
        const float length = glm::length(sum);
        v_.normals.push_back(length > 1e-20f ? sum / length : nLo);
    }
    if (!v_.tangents.empty()) {
        const glm::vec4 tLo = v_.tangents[lo];
        const glm::vec3 sum = glm::vec3(tLo) + glm::vec3(v_.tangents[hi]);
        const float length = glm::length(sum);
        v_.tangents.emplace_back(length > 1e-20f ? sum / length : glm::vec3(tLo), tLo.w);
    }
    if (!v_.uvs.empty()) {
        const glm::vec2 uv = 0.5f * (v_.uvs[lo] + v_.uvs[hi]);
        v_.uvs.push_back(uv);
    }
    const uint32_t welded = weldId(position);
    weldOf_.push_back(welded);
    return next;
}

bool MeshSplitter::split(uint32_t a, uint32_t b, uint32_t c, std::vector<uint32_t>& out)
{
    bool wasSplit = false;
    stack_.clear();
    stack_.push_back({{a, b, c}, 0});
    while (!stack_.empty()) {
        const Tri t = stack_.back();
        stack_.pop_back();

        // Decide per edge; edge i runs from corner i to corner i + 1.
        std::array<bool, 3> s{};
        int splitCount = 0;
        for (int i = 0; i < 3; ++i) {
            s[i] = splitsEdge(weldOf_[t.v[i]], weldOf_[t.v[(i + 1) % 3]]);
            splitCount += s[i] ? 1 : 0;
        }
        if (splitCount == 0 || t.depth >= kMaxDepth) {
            if (splitCount != 0)
                ++unresolved_;
            out.insert(out.end(), t.v.begin(), t.v.end());
            continue;
        }
        wasSplit = true;

        std::array<uint32_t, 3> m{kInvalid, kInvalid, kInvalid};
        for (int i = 0; i < 3; ++i)
            if (s[i])
                m[i] = midpoint(t.v[i], t.v[(i + 1) % 3]);

        // Build the children (winding of the parent kept), then push them reversed so
        // they are emitted in the order listed.
        std::array<Tri, 4> child{};
        int childCount = 0;
        const uint32_t depth = t.depth + 1;
        auto add = [&](uint32_t x, uint32_t y, uint32_t z) { child[childCount++] = {{x, y, z}, depth}; };
        const auto& cv = t.v;
        if (splitCount == 3) {
            add(cv[0], m[0], m[2]);
            add(m[0], cv[1], m[1]);
            add(m[2], m[1], cv[2]);
            add(m[0], m[1], m[2]);
        } else if (splitCount == 1) {
            const int i = s[0] ? 0 : (s[1] ? 1 : 2);
            const uint32_t ci = cv[i], cj = cv[(i + 1) % 3], ck = cv[(i + 2) % 3];
            add(ci, m[i], ck);
            add(m[i], cj, ck);
        } else {
            // Rotate so that edges A-B and B-C are split and C-A is not.
            const int k = !s[0] ? 0 : (!s[1] ? 1 : 2); // the unsplit edge
            const int r = (k + 1) % 3;
            const uint32_t A = cv[r], B = cv[(r + 1) % 3], C = cv[(r + 2) % 3];
            const uint32_t mAB = m[r], mBC = m[(r + 1) % 3];
            add(mAB, B, mBC);
            // Quad A, mAB, mBC, C: cut along the shorter diagonal (better-shaped
            // triangles); ties go to A-mBC so the choice is deterministic.
            const auto& P = v_.positions;
            if (edgeLength2(P[A], P[mBC]) <= edgeLength2(P[mAB], P[C])) {
                add(A, mAB, mBC);
                add(A, mBC, C);
            } else {
                add(A, mAB, C);
                add(mAB, mBC, C);
            }
        }
        for (int i = childCount - 1; i >= 0; --i)
            stack_.push_back(child[i]);
    }
    return wasSplit;
}

// ---- Scene bookkeeping ----------------------------------------------------------------

std::string meshLabel(const Scene& scene, uint32_t mesh)
{
    const std::string& name = scene.meshes[mesh].name;
    return name.empty() ? "mesh " + std::to_string(mesh) : "mesh '" + name + "'";
}

// Throws on anything that would make the splitter read out of bounds.
void validateScene(const Scene& scene)
{
    const VertexStreams& v = scene.vertices;
    const size_t n = v.positions.size();
    if ((!v.normals.empty() && v.normals.size() != n) ||
        (!v.tangents.empty() && v.tangents.size() != n) || (!v.uvs.empty() && v.uvs.size() != n))
        throw BakeError("tessellation: vertex streams have different lengths");
    if (scene.indices.size() % 3 != 0)
        throw BakeError("tessellation: index count is not a multiple of 3");
    for (size_t p = 0; p < scene.primitives.size(); ++p) {
        const Primitive& prim = scene.primitives[p];
        if (prim.firstIndex % 3 != 0 || prim.indexCount % 3 != 0 ||
            uint64_t(prim.firstIndex) + prim.indexCount > scene.indices.size())
            throw BakeError("tessellation: primitive " + std::to_string(p) +
                            " has an invalid index range");
    }
    for (uint32_t index : scene.indices)
        if (index >= n)
            throw BakeError("tessellation: vertex index " + std::to_string(index) +
                            " out of range (" + std::to_string(n) + " vertices)");
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        if (uint64_t(mesh.firstPrimitive) + mesh.primitiveCount > scene.primitives.size())
            throw BakeError("tessellation: mesh " + std::to_string(m) +
                            " has an invalid primitive range");
    }
}

// Longest edge (object units) of one primitive's triangles.
double longestEdge(const Scene& scene, const uint32_t* indices, size_t indexCount)
{
    const auto& P = scene.vertices.positions;
    double longest2 = 0.0;
    for (size_t i = 0; i < indexCount; i += 3) {
        const glm::vec3& a = P[indices[i]];
        const glm::vec3& b = P[indices[i + 1]];
        const glm::vec3& c = P[indices[i + 2]];
        for (double l2 : {edgeLength2(a, b), edgeLength2(b, c), edgeLength2(c, a)})
            if (std::isfinite(l2))
                longest2 = std::max(longest2, l2);
    }
    return std::sqrt(longest2);
}

void truncateStreams(VertexStreams& v, size_t count)
{
    v.positions.resize(count);
    if (!v.normals.empty())
        v.normals.resize(count);
    if (!v.tangents.empty())
        v.tangents.resize(count);
    if (!v.uvs.empty())
        v.uvs.resize(count);
}

bool usableBound(double bound) { return std::isfinite(bound) && bound > 0.0; }

// Primitives sorted by firstIndex; throws if two non-empty ranges overlap (the index
// buffer is rebuilt range by range).
std::vector<uint32_t> primitivesInIndexOrder(const Scene& scene)
{
    std::vector<uint32_t> order(scene.primitives.size());
    for (uint32_t p = 0; p < order.size(); ++p)
        order[p] = p;
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return scene.primitives[a].firstIndex < scene.primitives[b].firstIndex;
    });
    uint32_t end = 0;
    for (uint32_t p : order) {
        const Primitive& prim = scene.primitives[p];
        if (prim.indexCount > 0 && prim.firstIndex < end)
            throw BakeError("tessellation: primitive " + std::to_string(p) +
                            " shares indices with another primitive");
        end = std::max(end, prim.firstIndex + prim.indexCount);
    }
    return order;
}

// Primitives split together (welded as one mesh) against one bound.
struct Group {
    std::vector<uint32_t> primitives;
    double bound = std::numeric_limits<double>::infinity(); // object units
    double scale = 0.0;                                     // object -> scene units
};

// Each primitive is split once, by the first mesh that lists it (its group). A group
// takes the finest bound and largest scale of any mesh listing one of its primitives, so
// one welded edge always meets one bound.
std::vector<Group> groupPrimitives(const Scene& scene, const std::vector<double>& maxEdgeObject,
                                   const std::vector<float>& meshScale)
{
    std::vector<Group> groups(scene.meshes.size());
    std::vector<uint32_t> groupOf(scene.primitives.size(), kInvalid);
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p)
            if (groupOf[p] == kInvalid) {
                groupOf[p] = m;
                groups[m].primitives.push_back(p);
            }
    }
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const double scale = std::isfinite(meshScale[m]) ? std::max(0.0, double(meshScale[m])) : 0.0;
        for (uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount; ++p) {
            Group& group = groups[groupOf[p]];
            if (usableBound(maxEdgeObject[m]))
                group.bound = std::min(group.bound, maxEdgeObject[m]);
            group.scale = std::max(group.scale, scale);
        }
    }
    return groups;
}

double groupLongestEdge(const Scene& scene, const Group& group)
{
    double longest = 0.0;
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        longest = std::max(longest, longestEdge(scene, scene.indices.data() + prim.firstIndex, prim.indexCount));
    }
    return longest;
}

// What splitting produced so far, across groups.
struct SplitResult {
    std::vector<std::vector<uint32_t>> indices; // per primitive; used where changed[p]
    std::vector<bool> changed;
    std::vector<uint32_t> weldOf; // scratch shared by the groups' splitters
    size_t trianglesOut = 0;
    size_t trianglesSplit = 0;
    size_t unresolved = 0;
};

// Splits the oversized triangles of one group, primitive by primitive.
void splitGroup(Scene& scene, const Group& group, const std::string& label, SplitResult& result,
                const Log& log)
{
    size_t groupTriangles = 0;
    for (uint32_t p : group.primitives)
        groupTriangles += scene.primitives[p].indexCount / 3;

    // Weld every vertex the group uses.
    if (result.weldOf.size() < scene.vertices.size())
        result.weldOf.resize(scene.vertices.size(), kInvalid);
    MeshSplitter splitter(scene.vertices, result.weldOf, group.bound, groupTriangles);
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; ++i)
            splitter.weld(scene.indices[i]);
    }

    // Split triangle by triangle; each primitive's pieces stay together and in order.
    size_t groupSplit = 0, groupOut = 0, done = 0;
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        std::vector<uint32_t>& out = result.indices[p];
        out.reserve(prim.indexCount + prim.indexCount / 2);
        bool primitiveChanged = false;
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; i += 3) {
            const size_t before = out.size();
            if (splitter.split(scene.indices[i], scene.indices[i + 1], scene.indices[i + 2], out)) {
                ++groupSplit;
                primitiveChanged = true;
                result.trianglesOut += (out.size() - before) / 3 - 1;
                if (result.trianglesOut > kMaxOutputTriangles)
                    throw BakeError("tessellation: " + label + " would exceed " +
                                    std::to_string(kMaxOutputTriangles) +
                                    " triangles at this edge bound; raise the bound");
            }
            if (++done % kProgressInterval == 0)
                log.info("tessellation: " + label + ": " + std::to_string(done) + " / " +
                         std::to_string(groupTriangles) + " triangles");
        }
        groupOut += out.size() / 3;
        result.changed[p] = primitiveChanged;
        if (!primitiveChanged)
            std::vector<uint32_t>().swap(out); // unchanged: the original range is kept
    }
    result.unresolved += splitter.unresolved();
    result.trianglesSplit += groupSplit;
    log.info("tessellation: " + label + ": " + std::to_string(groupTriangles) + " -> " +
             std::to_string(groupOut) + " triangles (" + std::to_string(groupSplit) + " split)");
}

// New index buffer: primitives in index order, changed ones replaced by their pieces;
// triangles outside any primitive are carried over unchanged.
void rebuildIndexBuffer(Scene& scene, const std::vector<uint32_t>& order, SplitResult& result)
{
    std::vector<uint32_t> indices;
    indices.reserve(result.trianglesOut * 3);
    uint32_t cursor = 0; // next old index not yet copied
    for (uint32_t p : order) {
        Primitive& prim = scene.primitives[p];
        if (prim.firstIndex > cursor)
            indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.begin() + prim.firstIndex);
        cursor = std::max(cursor, prim.firstIndex + prim.indexCount);
        const auto first = uint32_t(indices.size());
        if (result.changed[p])
            indices.insert(indices.end(), result.indices[p].begin(), result.indices[p].end());
        else
            indices.insert(indices.end(), scene.indices.begin() + prim.firstIndex,
                           scene.indices.begin() + prim.firstIndex + prim.indexCount);
        prim.firstIndex = first;
        prim.indexCount = uint32_t(indices.size()) - first;
        std::vector<uint32_t>().swap(result.indices[p]);
    }
    indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.end());
    scene.indices = std::move(indices);
}

} // namespace

TessellationStats tessellateMeshes(Scene& scene, const std::vector<double>& maxEdgeObject,
                                   const std::vector<float>& meshScale, const Log& log)
{
    if (maxEdgeObject.size() != scene.meshes.size() || meshScale.size() != scene.meshes.size())
        throw BakeError("tessellation: expected one bound and one scale per mesh");
    validateScene(scene);
    const std::vector<uint32_t> order = primitivesInIndexOrder(scene);
    const std::vector<Group> groups = groupPrimitives(scene, maxEdgeObject, meshScale);

    TessellationStats stats;
    stats.trianglesIn = scene.triangleCount();
    SplitResult result;
    result.indices.resize(scene.primitives.size());
    result.changed.assign(scene.primitives.size(), false);
    result.trianglesOut = stats.trianglesIn;

    // Split the groups that have an oversized edge (the others need no welding).
    const size_t vertexCountIn = scene.vertices.size();
    try {
        for (uint32_t g = 0; g < groups.size(); ++g) {
            const double longest = groupLongestEdge(scene, groups[g]);
            stats.maxEdgeWorldBefore = std::max(stats.maxEdgeWorldBefore, longest * groups[g].scale);
            if (longest > groups[g].bound)
                splitGroup(scene, groups[g], meshLabel(scene, g), result, log);
        }
    } catch (...) {
        // Leave the scene as it was: drop the vertices appended so far.
        truncateStreams(scene.vertices, vertexCountIn);
        throw;
    }
    stats.trianglesSplit = result.trianglesSplit;

    if (stats.trianglesSplit > 0) {
        rebuildIndexBuffer(scene, order, result);
        scene.triangleStats.clear(); // no longer lines up with the triangles
    }

    // Report.
    stats.trianglesOut = scene.triangleCount();
    for (const Group& group : groups)
        stats.maxEdgeWorldAfter = std::max(stats.maxEdgeWorldAfter, groupLongestEdge(scene, group) * group.scale);
    if (result.unresolved > 0)
        log.warn("tessellation: " + std::to_string(result.unresolved) +
                 " triangles could not be split further (float precision); they exceed the bound");
    log.info("tessellation: " + std::to_string(stats.trianglesIn) + " -> " +
             std::to_string(stats.trianglesOut) + " triangles (" + std::to_string(stats.trianglesSplit) +
             " split), longest edge " + std::to_string(stats.maxEdgeWorldBefore) + " -> " +
             std::to_string(stats.maxEdgeWorldAfter) + " scene units");
    return stats;
}

TessellationStats tessellateScene(Scene& scene, double maxEdgeWorld, const Log& log)
{
    if (!(maxEdgeWorld > 0.0))
        throw BakeError("tessellation: the maximum edge length must be positive, got " +
                        std::to_string(maxEdgeWorld));
    // Meshes are in object space and may be instanced at several scales: the largest
    // scale decides, so that no instance exceeds the bound.
    const std::vector<float> scale = meshMaxWorldScale(scene);
    if (scale.size() != scene.meshes.size())
        throw BakeError("tessellation: mesh scale list does not match the mesh count");
    std::vector<double> maxEdgeObject(scene.meshes.size(), std::numeric_limits<double>::infinity());
    for (size_t m = 0; m < scale.size(); ++m)
        if (std::isfinite(scale[m]) && scale[m] > 0.0f)
            maxEdgeObject[m] = maxEdgeWorld / double(scale[m]); // unused meshes: untouched
    return tessellateMeshes(scene, maxEdgeObject, scale, log);
}

MeshTopology meshTopology(const Scene& scene, uint32_t mesh)
{
    if (mesh >= scene.meshes.size())
        throw BakeError("mesh topology: mesh " + std::to_string(mesh) + " does not exist");
    validateScene(scene);

    using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;
    TriMesh om;
    MeshTopology topology;
    FlatMap<PositionKey> weldByPosition;
    std::vector<TriMesh::VertexHandle> handles;
    auto welded = [&](uint32_t vertex) {
        const glm::vec3 p = canonicalPosition(scene.vertices.positions[vertex]);
        const auto next = uint32_t(handles.size());
        const uint32_t id = weldByPosition.findOrInsert(positionKey(p), next);
        if (id == next)
            handles.push_back(om.add_vertex(TriMesh::Point(p.x, p.y, p.z)));
        return id;
    };

    // note: OpenMesh complains on stderr about every face it refuses; those faces are
    // counted in rejectedFaces instead.
    OpenMesh::mostream& errors = omerr();
    const bool errorsEnabled = errors.is_enabled();
    errors.disable();
    const Mesh& m = scene.meshes[mesh];
    for (uint32_t p = m.firstPrimitive; p < m.firstPrimitive + m.primitiveCount; ++p) {
        const Primitive& prim = scene.primitives[p];
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; i += 3) {
            const uint32_t a = welded(scene.indices[i]);
            const uint32_t b = welded(scene.indices[i + 1]);
            const uint32_t c = welded(scene.indices[i + 2]);
            if (a == b || b == c || c == a) {
                ++topology.degenerateFaces;
                continue;
            }
            if (om.add_face(handles[a], handles[b], handles[c]).is_valid())
                ++topology.faces;
            else
                ++topology.rejectedFaces;
        }
    }
    if (errorsEnabled)
        errors.enable();

    topology.weldedVertices = handles.size();
    for (const auto edge : om.edges())
        if (om.is_boundary(edge))
            ++topology.boundaryEdges;
    return topology;
}

size_t countBoundaryEdges(const Scene& scene, uint32_t mesh)
{
    return meshTopology(scene, mesh).boundaryEdges;
}

} // namespace lfd::bake
