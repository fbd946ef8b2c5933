// Tessellation stage: cut triangles that would span more than the view-pixel bound.
//
// Paper section 5: large triangles were "tessellated ... to ensure that they spanned no more than a
// hundred pixels", because point rendering only beats rasterisation on small triangles.
// docs/baker/lfd-bake.md "What a bake does", step 4: only oversized triangles are cut, attributes
// are interpolated, and the result has no cracks (no T-junctions).
//
// Each edge is cut into ceil(length / bound) equal pieces (its rate), not into the next
// power of two, and each oversized face is filled by OpenSubdiv's Bfr::Tessellation for
// its three edge rates (face_pattern.cpp picks the inner rate and checks every output
// edge against the bound).
//
// Where the new points are: on OpenSubdiv's bilinear surface of the welded mesh
// (bilinear_surface.h: Far::TopologyRefiner -> Bfr::RefinerSurfaceFactory), which is
// exactly the flat triangles. Interior points are evaluated on their face's Bfr::Surface
// at their barycentric weights; where OpenSubdiv refuses the mesh or gives a face no
// surface, they are the barycentric combination of the face's corners (the same flat
// triangle), and the face is counted in TessellationStats. Edge points come from
// BilinearSurface::edgePoint, the surface along an edge, which depends on the edge's two
// ends alone.
//
// Crack-freeness: vertices are welded per mesh by exact position, so the two sides of a
// UV/normal seam see the same welded edge. An edge's rate and the positions of its points
// depend only on that welded edge (its canonical endpoint positions and the mesh bound),
// never on the face being cut (evaluating each face's own surface on the edge would not
// do: the two faces reach it through different sub-faces and agree only to rounding). A
// tessellation pattern's boundary is fixed by its edge rates alone (Bfr places rate - 1
// points along each edge, whatever happens inside the face), so the two faces of a
// shared edge put bit-identical points on it: every point one side has, the other has
// too, hence no T-junctions and no cracks, with or without a seam. Attributes of a new
// point come from the face's own corners, so each side of a seam keeps its own
// uv/normal at the shared position.
//
// Threads (issue 9; the pack must not depend on them, parallel.h): meshes (groups of
// primitives) are tessellated side by side, each reading the scene and writing only its
// own new vertices and pieces, which are then appended in mesh order and renumbered as a
// serial run would have numbered them. Inside a mesh, the patterns of oversized faces
// (most of the time on finely cut scenes) are computed on the threads other meshes have
// left, a chunk of faces at a time, while every step that numbers vertices stays in order.

#include "tessellation.h"

#include "bilinear_surface.h"
#include "deformers.h"
#include "face_pattern.h"
#include "parallel.h"
#include "progress_clock.h"
#include "scene_bounds.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace lfd::bake {
namespace {

constexpr uint32_t kInvalid = std::numeric_limits<uint32_t>::max();
// note: 2^28 triangles are 3 GiB of indices alone; a bound this fine means a broken
// display profile or framing, not a scene anyone can pack or render.
constexpr size_t kMaxOutputTriangles = size_t(1) << 28;
static_assert(kMaxOutputTriangles * 3 < std::numeric_limits<uint32_t>::max(),
              "indices of the output must fit uint32_t");
// Most pieces per edge: a face of rate n has about n^2 triangles, so a larger rate could
// never fit kMaxOutputTriangles anyway (and Bfr's rates are ints).
constexpr int kMaxEdgeRate = 1 << 14;
// Seconds between two progress lines while a mesh is cut (a fine bound can keep one mesh
// busy for many seconds; a line per chunk would flood the log on fast ones).
constexpr double kProgressSeconds = 1.0;
// Faces planned at a time (MeshTessellator::plan): enough work to share between threads,
// few enough patterns held at once. A chunk also ends at about kPiecesPerChunk pieces, so
// its patterns stay a few MiB however finely its faces are cut.
constexpr size_t kFacesPerChunk = 4096;
constexpr size_t kPiecesPerChunk = size_t(1) << 16;
// Faces per work item when the patterns of a chunk are shared out.
constexpr size_t kFacesPerItem = 32;
// Most vertices a tessellated scene may have (fits int32_t: the limit the splitter has
// always had).
constexpr size_t kMaxVertices = size_t(std::numeric_limits<int32_t>::max());
// note: the refusals name no mesh: groups run concurrently, and the same input must be
// refused with the same message whatever the thread count and whichever group noticed.
const char* const kTooManyTriangles =
    "tessellation: the scene would exceed 268435456 (2^28) triangles at this edge bound; raise the bound";
const char* const kTooManyVertices = "tessellation: more than 2^31 - 1 vertices; raise the edge bound";

// ---- Small open-addressing hash map ---------------------------------------------------
// The weld, edge-rate and edge-point maps see millions of inserts on big meshes; linear probing over
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

    // The value stored for key, kInvalid if absent.
    uint32_t find(const Key& key) const
    {
        for (size_t i = hashKey(key) & mask_; values_[i] != kInvalid; i = (i + 1) & mask_)
            if (keys_[i] == key)
                return values_[i];
        return kInvalid;
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

// ---- Tessellating one mesh ------------------------------------------------------------

// The vertices one group of primitives sees while it is tessellated: the scene's, read
// only and shared by every group (so groups can run on different threads), followed by
// the ones this group adds. Added vertex k is numbered base + k, as if appended to the
// scene; tessellateMeshes renumbers them once the groups before this one have said how
// many they added, so the final numbering is the serial one whatever the thread count.
struct GroupVertices {
    const VertexStreams& scene;
    uint32_t base = 0; // scene.size()
    VertexStreams added;

    const glm::vec3& position(uint32_t i) const { return i < base ? scene.positions[i] : added.positions[i - base]; }
};

// Tessellates the triangles of one mesh against one bound (object units). Holds the weld,
// edge-rate and edge-point maps, which must live as long as any triangle of the mesh is
// being tessellated. Only ever reads the scene: everything it makes lands in `vertices`
// and in the caller's output indices.
class MeshTessellator {
public:
    // The input triangles use scene vertices firstVertex .. firstVertex + vertexSpan - 1
    // (the weld table covers that range only).
    MeshTessellator(GroupVertices& vertices, uint32_t firstVertex, size_t vertexSpan, double bound,
                    size_t expectedVertices)
        : v_(vertices), firstVertex_(firstVertex), weldOf_(vertexSpan, kInvalid), bound_(bound),
          weldByPosition_(expectedVertices), rateOf_(expectedVertices), edgePointsOf_(expectedVertices / 2)
    {
        weldPosition_.reserve(expectedVertices);
    }

    // Welds the corners of the group's next triangle (triangles in the order plan() will
    // see them: the face numbering of the group's surface).
    void weldFace(const uint32_t* corner)
    {
        for (size_t i = 0; i < 3; ++i) {
            const uint32_t w = weldId(v_.scene.positions[corner[i]]);
            weldOf_[corner[i] - firstVertex_] = w;
            faceWelds_.push_back(w);
        }
    }

    // Triangles are tessellated a chunk at a time, in three steps, so that the costly
    // part - the pattern of each oversized face (face_pattern.cpp) - can run on several
    // threads while everything that numbers vertices stays in triangle order:
    //   plan      (in order)  edge rates of the next triangles, the chunk's faces;
    //   patterns  (parallel)  the pattern of every cut face of the chunk, from positions
    //                         alone: a pure function of its corners and edge points;
    //   emit      (in order)  edge points, interior points and pieces, face by face.
    // The output is the one a face-by-face loop gives, for any thread count.
    //
    // plan: takes up to kFacesPerChunk triangles (fewer when their pieces would be many)
    // from `triangles` (3 scene vertex indices each, `count` triangles) and returns how
    // many it took. Throws if a face alone could exceed `budget` more triangles.
    size_t plan(const uint32_t* triangles, size_t count, size_t budget);
    // Skips the faces left once stopped() says so (the chunk is then abandoned).
    void patterns(ThreadBudget& threads, const std::function<bool()>& stopped);
    // Appends chunk face f, or the pieces it is cut into, to out (3 indices each).
    // Returns whether it was cut.
    bool emit(size_t f, std::vector<uint32_t>& out);

    size_t unresolved() const { return unresolved_; }
    // Whether the group's surface was built (only once a face needs cutting), OpenSubdiv's
    // refusal of it (empty where it took the mesh), and the cut faces whose interior
    // points were placed by barycentric weights because the surface has no face for them.
    bool surfaceBuilt() const { return surface_ != nullptr; }
    std::string surfaceRefusal() const { return surface_ && surface_->refused() ? surface_->refusal() : std::string(); }
    size_t fallbacks() const { return fallbacks_; }

private:
    // A triangle of the chunk being tessellated.
    struct Face {
        uint32_t index = 0; // in the group: the surface's face index
        std::array<uint32_t, 3> corner{};
        std::array<int, 3> rates{};
        bool cut = false;
        bool onSurface = false; // set by patterns(): the pattern's points are on the surface
        FacePattern pattern;    // set by patterns() where cut
    };

    uint32_t weldOf(uint32_t vertex) const { return weldOf_[vertex - firstVertex_]; }
    uint32_t weldId(const glm::vec3& position)
    {
        const glm::vec3 p = canonicalPosition(position);
        const auto next = uint32_t(weldPosition_.size());
        const uint32_t id = weldByPosition_.findOrInsert(positionKey(p), next);
        if (id == next)
            weldPosition_.push_back(p);
        return id;
    }

    int edgeRate(uint32_t wa, uint32_t wb);
    glm::vec3 edgePoint(uint32_t wa, uint32_t wb, int rate, int k) const;
    glm::vec3 boundaryPoint(uint32_t va, uint32_t vb, int rate, int k) const;
    uint32_t edgePoints(uint32_t va, uint32_t vb, int rate);
    uint32_t appendVertex();

    GroupVertices& v_;
    uint32_t firstVertex_;
    std::vector<uint32_t> weldOf_; // welded id of scene vertex firstVertex_ + i
    double bound_;
    std::vector<glm::vec3> weldPosition_; // canonical position per welded id
    FlatMap<PositionKey> weldByPosition_;
    FlatMap<uint64_t> rateOf_;       // welded edge -> pieces
    FlatMap<uint64_t> edgePointsOf_; // vertex pair -> first of its rate - 1 edge points
    std::vector<uint32_t> faceWelds_; // 3 welded ids per face, until the surface is built
    std::unique_ptr<BilinearSurface> surface_;
    uint32_t nextFace_ = 0; // group index of the next face plan() takes
    std::vector<Face> chunk_;
    std::vector<uint32_t> boundaryIndex_;
    size_t unresolved_ = 0;
    size_t fallbacks_ = 0;
};

// Point k of `rate` points along welded edge (wa, wb), counted from wa: the bilinear
// surface along the edge. Computed from the edge's canonical endpoint order (lower welded
// id first) and its canonical point number, so every face that has this edge - on either
// side of a UV/normal seam, whichever way it runs along the edge - gets the
// bit-identical position.
glm::vec3 MeshTessellator::edgePoint(uint32_t wa, uint32_t wb, int rate, int k) const
{
    const bool forward = wa < wb;
    const int canonical = forward ? k : rate - k;
    return glm::vec3(BilinearSurface::edgePoint(weldPosition_[forward ? wa : wb], weldPosition_[forward ? wb : wa],
                                                double(canonical) / double(rate)));
}

// The rate rule: ceil(length / bound) pieces, a function of the welded edge only, so
// every face sharing the edge cuts it the same way. (A dyadic split would round up to the
// next power of two: an edge of 2.01 bounds became 4 pieces, now 3.) Raised where float
// rounding of the points would leave a piece a hair over the bound; lowered where the
// edge is too short for its coordinates' float precision to place distinct points.
int MeshTessellator::edgeRate(uint32_t wa, uint32_t wb)
{
    if (wa == wb)
        return 1;
    const uint64_t key = pairKey(wa, wb);
    if (const uint32_t known = rateOf_.find(key); known != kInvalid)
        return int(known);

    const glm::vec3& pLo = weldPosition_[std::min(wa, wb)];
    const glm::vec3& pHi = weldPosition_[std::max(wa, wb)];
    const double length = std::sqrt(edgeLength2(pLo, pHi));
    int rate = 1;
    if (std::isfinite(length) && length > bound_) {
        const float magnitude = std::max({std::abs(pLo.x), std::abs(pLo.y), std::abs(pLo.z), std::abs(pHi.x),
                                          std::abs(pHi.y), std::abs(pHi.z)});
        const double resolvable = 8.0 * double(std::numeric_limits<float>::epsilon()) * double(magnitude);
        const double finest = resolvable > 0.0 ? std::floor(length / resolvable) : double(kMaxEdgeRate);
        const double wanted = std::ceil(length / bound_);
        const int cap = int(std::clamp(finest, 1.0, double(kMaxEdgeRate)));
        rate = int(std::min(wanted, double(cap)));
        auto fits = [&](int n) {
            glm::vec3 previous = pLo;
            for (int k = 1; k <= n; ++k) {
                const glm::vec3 next = k == n ? pHi : edgePoint(std::min(wa, wb), std::max(wa, wb), n, k);
                if (edgeLength2(previous, next) > bound_ * bound_)
                    return false;
                previous = next;
            }
            return true;
        };
        while (rate < cap && !fits(rate))
            ++rate;
        if (!fits(rate))
            ++unresolved_;
    }
    rateOf_.findOrInsert(key, uint32_t(rate));
    return rate;
}

// note: tessellateMeshes checks the limit again on the sum over all groups.
uint32_t MeshTessellator::appendVertex()
{
    VertexStreams& added = v_.added;
    if (size_t(v_.base) + added.size() >= kMaxVertices)
        throw BakeError(kTooManyVertices);
    const auto index = v_.base + uint32_t(added.size());
    added.positions.emplace_back();
    if (!v_.scene.normals.empty())
        added.normals.emplace_back();
    if (!v_.scene.tangents.empty())
        added.tangents.emplace_back();
    if (!v_.scene.uvs.empty())
        added.uvs.emplace_back();
    const DeformationStreams& deform = v_.scene.deform;
    if (deform.skinned()) {
        added.deform.joints.emplace_back();
        added.deform.weights.emplace_back();
    }
    const size_t slots = deform.morphTargets;
    for (auto [from, to] : {std::pair{&deform.positions, &added.deform.positions},
                            std::pair{&deform.normals, &added.deform.normals},
                            std::pair{&deform.tangents, &added.deform.tangents}})
        if (!from->empty())
            to->resize(to->size() + slots);
    return index;
}

// Skin influences and morph deltas of new vertex `target` (glTF 3.7.2.2, 3.7.3): deltas
// linearly per target; influences as the weighted sum over the corners' joints, the four
// largest kept and renormalised (so a point inside a triangle bends as its corners do).
template <size_t N>
void interpolateDeformation(const VertexStreams& v, VertexStreams& to, size_t target,
                            const std::array<uint32_t, N>& from, const std::array<double, N>& weight)
{
    const DeformationStreams& d = v.deform;
    if (d.skinned()) {
        std::array<std::pair<double, uint32_t>, 4 * N> sum{};
        size_t used = 0;
        for (size_t i = 0; i < N; ++i)
            for (int k = 0; k < 4; ++k) {
                const uint32_t joint = d.joints[from[i]][k];
                const double w = weight[i] * double(d.weights[from[i]][k]);
                size_t slot = 0;
                while (slot < used && sum[slot].second != joint)
                    ++slot;
                if (slot == used)
                    sum[used++] = {0.0, joint};
                sum[slot].first += w;
            }
        for (size_t i = 1; i < used; ++i) // heaviest first (insertion sort: at most 12 entries)
            for (size_t k = i; k > 0 && sum[k].first > sum[k - 1].first; --k)
                std::swap(sum[k], sum[k - 1]);
        double total = 0.0;
        for (size_t k = 0; k < 4 && k < used; ++k)
            total += sum[k].first;
        glm::uvec4 joints(0u);
        glm::vec4 weights(0.0f);
        for (size_t k = 0; k < 4 && k < used && total > 0.0; ++k) {
            joints[glm::length_t(k)] = sum[k].second;
            weights[glm::length_t(k)] = float(sum[k].first / total);
        }
        to.deform.joints[target] = joints;
        to.deform.weights[target] = weights;
    }
    const size_t slots = d.morphTargets;
    for (auto [src, dst] : {std::pair{&d.positions, &to.deform.positions}, std::pair{&d.normals, &to.deform.normals},
                            std::pair{&d.tangents, &to.deform.tangents}}) {
        if (src->empty())
            continue;
        for (size_t t = 0; t < slots; ++t) {
            glm::dvec3 delta(0.0);
            for (size_t i = 0; i < N; ++i)
                delta += weight[i] * glm::dvec3((*src)[from[i] * slots + t]);
            (*dst)[target * slots + t] = glm::vec3(delta);
        }
    }
}

// Interpolated attributes of new vertex `target` (an index into `to`) from scene vertices
// `from` of `v` and their weights (the face's own corners, or an edge's two vertices): uv
// linearly, normal and tangent re-normalised, tangent handedness from the heaviest corner.
// Weights that cancel out a direction (opposite normals) keep the heaviest corner's
// instead of dividing by zero.
template <size_t N>
void interpolateAttributes(const VertexStreams& v, VertexStreams& to, size_t target, const std::array<uint32_t, N>& from,
                           const std::array<double, N>& weight)
{
    size_t heaviest = 0;
    for (size_t i = 1; i < N; ++i)
        if (weight[i] > weight[heaviest])
            heaviest = i;
    auto direction = [&](auto get) {
        glm::dvec3 sum(0.0);
        for (size_t i = 0; i < N; ++i)
            sum += weight[i] * glm::dvec3(get(from[i]));
        const double length = glm::length(sum);
        return length > 1e-20 ? glm::vec3(sum / length) : get(from[heaviest]);
    };
    if (!v.normals.empty())
        to.normals[target] = direction([&](uint32_t i) { return v.normals[i]; });
    if (!v.tangents.empty())
        to.tangents[target] = glm::vec4(direction([&](uint32_t i) { return glm::vec3(v.tangents[i]); }),
                                        v.tangents[from[heaviest]].w);
    if (!v.uvs.empty()) {
        glm::dvec2 uv(0.0);
        for (size_t i = 0; i < N; ++i)
            uv += weight[i] * glm::dvec2(v.uvs[from[i]]);
        to.uvs[target] = glm::vec2(uv);
    }
    interpolateDeformation<N>(v, to, target, from, weight);
}

// First of the rate - 1 points of the edge between vertices va and vb, stored from the
// lower vertex index to the higher. One run per vertex pair: faces that share both
// corner vertices (same side of any seam) share the points, so the index topology stays
// connected; a face on the other side of a seam has its own run, at the same positions,
// with its own uvs and normals.
uint32_t MeshTessellator::edgePoints(uint32_t va, uint32_t vb, int rate)
{
    const auto next = v_.base + uint32_t(v_.added.size());
    const uint32_t found = edgePointsOf_.findOrInsert(pairKey(va, vb), next);
    if (found != next)
        return found;
    const uint32_t lo = std::min(va, vb), hi = std::max(va, vb);
    for (int k = 1; k < rate; ++k) {
        const size_t vertex = appendVertex() - v_.base;
        v_.added.positions[vertex] = boundaryPoint(lo, hi, rate, k);
        const double t = double(k) / double(rate);
        interpolateAttributes<2>(v_.scene, v_.added, vertex, {lo, hi}, {1.0 - t, t});
    }
    return next;
}

// Where point k of the edge from vertex va to vertex vb is (rate pieces): the position
// edgePoints() stores for it, computed the same way (from the lower vertex index), so a
// pattern computed before the point exists sees the bits it will have.
glm::vec3 MeshTessellator::boundaryPoint(uint32_t va, uint32_t vb, int rate, int k) const
{
    const uint32_t lo = std::min(va, vb), hi = std::max(va, vb);
    return edgePoint(weldOf(lo), weldOf(hi), rate, va < vb ? k : rate - k);
}

size_t MeshTessellator::plan(const uint32_t* triangles, size_t count, size_t budget)
{
    chunk_.clear();
    size_t pieces = 0; // estimated, for the chunk's memory
    for (size_t t = 0; t < count && chunk_.size() < kFacesPerChunk && pieces < kPiecesPerChunk; ++t) {
        Face& face = chunk_.emplace_back();
        face.index = nextFace_++;
        face.corner = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
        for (size_t i = 0; i < 3; ++i)
            face.rates[i] = edgeRate(weldOf(face.corner[i]), weldOf(face.corner[(i + 1) % 3]));
        // Every edge within the bound: the face is emitted as it is.
        face.cut = face.rates != std::array<int, 3>{1, 1, 1};
        if (!face.cut)
            continue;
        // A face of rate n has about n^2 pieces; refuse before allocating them.
        const double largest = double(std::max({face.rates[0], face.rates[1], face.rates[2]}));
        if (largest * largest > double(budget))
            throw BakeError(kTooManyTriangles);
        pieces += size_t(largest * largest);
    }
    return chunk_.size();
}

void MeshTessellator::patterns(ThreadBudget& threads, const std::function<bool()>& stopped)
{
    // The surface of the whole welded mesh, once its first face needs cutting (a mesh
    // with nothing to cut never pays for it).
    if (!surface_ && std::any_of(chunk_.begin(), chunk_.end(), [](const Face& face) { return face.cut; })) {
        surface_ = std::make_unique<BilinearSurface>(faceWelds_, weldPosition_);
        std::vector<uint32_t>().swap(faceWelds_);
    }
    // note: only reads the weld table, the surface and positions, which nothing changes
    // until emit.
    const size_t ranges = (chunk_.size() + kFacesPerItem - 1) / kFacesPerItem;
    parallelFor(ranges, threads, [&](size_t r) {
        std::vector<glm::vec3> boundary;
        BilinearSurface::Face surface;
        for (size_t f = r * kFacesPerItem; f < std::min(chunk_.size(), (r + 1) * kFacesPerItem); ++f) {
            Face& face = chunk_[f];
            if (!face.cut || stopped())
                continue;
            // Boundary points in Bfr's order (face_pattern.h): corner i, then edge i's
            // points from corner i towards corner i + 1.
            boundary.clear();
            for (size_t i = 0; i < 3; ++i) {
                const uint32_t va = face.corner[i], vb = face.corner[(i + 1) % 3];
                boundary.push_back(v_.scene.positions[va]);
                for (int k = 1; k < face.rates[i]; ++k)
                    boundary.push_back(boundaryPoint(va, vb, face.rates[i], k));
            }
            face.onSurface = surface_->initFace(face.index, surface);
            if (face.onSurface) {
                face.pattern = facePattern([&surface](const glm::dvec3& w) { return glm::vec3(surface.at(w)); },
                                           face.rates, boundary, bound_);
            } else {
                const std::array<glm::vec3, 3> position = {v_.scene.positions[face.corner[0]],
                                                           v_.scene.positions[face.corner[1]],
                                                           v_.scene.positions[face.corner[2]]};
                face.pattern = facePattern(position, face.rates, boundary, bound_);
            }
        }
    });
}

bool MeshTessellator::emit(size_t f, std::vector<uint32_t>& out)
{
    Face& face = chunk_[f];
    const std::array<uint32_t, 3>& corner = face.corner;
    if (!face.cut) {
        out.insert(out.end(), corner.begin(), corner.end());
        return false;
    }

    // The boundary's vertices, in the order patterns() listed their positions.
    boundaryIndex_.clear();
    for (size_t i = 0; i < 3; ++i) {
        const uint32_t va = corner[i], vb = corner[(i + 1) % 3];
        const int rate = face.rates[i];
        boundaryIndex_.push_back(va);
        if (rate == 1)
            continue;
        const uint32_t first = edgePoints(va, vb, rate);
        for (int k = 1; k < rate; ++k)
            boundaryIndex_.push_back(va < vb ? first + uint32_t(k - 1) : first + uint32_t(rate - k - 1));
    }

    const FacePattern& pattern = face.pattern;
    if (!(pattern.longestEdge <= bound_))
        ++unresolved_;
    if (!face.onSurface)
        ++fallbacks_;

    // Interior points belong to this face alone: stored where the pattern checked the
    // bound, with attributes by their barycentric weights (each side of a seam from its
    // own corners).
    const auto firstInterior = v_.base + uint32_t(v_.added.size());
    for (size_t k = 0; k < pattern.interiorWeights.size(); ++k) {
        const glm::dvec3& w = pattern.interiorWeights[k];
        const size_t vertex = appendVertex() - v_.base;
        v_.added.positions[vertex] = pattern.interiorPoints[k];
        interpolateAttributes<3>(v_.scene, v_.added, vertex, corner, {w.x, w.y, w.z});
    }
    const auto boundaryCount = int(boundaryIndex_.size());
    for (int index : pattern.facets)
        out.push_back(index < boundaryCount ? boundaryIndex_[size_t(index)]
                                            : firstInterior + uint32_t(index - boundaryCount));
    face.pattern = FacePattern(); // done with it: free its memory now
    return true;
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
    const DeformationStreams& d = v.deform;
    if ((d.skinned() && (d.joints.size() != n || d.weights.size() != n)) ||
        (!d.positions.empty() && d.positions.size() != n * d.morphTargets) ||
        (!d.normals.empty() && d.normals.size() != n * d.morphTargets) ||
        (!d.tangents.empty() && d.tangents.size() != n * d.morphTargets))
        throw BakeError("tessellation: skin or morph streams do not match the vertex count");
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

// Longest edge and total edge length of some triangles (every triangle's three edges;
// an edge two triangles share counts twice). Non-finite lengths are skipped.
struct EdgeSummary {
    double longest = 0.0;
    double sum = 0.0;
    size_t count = 0;

    // position(i): where vertex i is.
    template <typename Position>
    void add(const Position& position, const uint32_t* indices, size_t indexCount)
    {
        for (size_t i = 0; i < indexCount; i += 3)
            for (size_t e = 0; e < 3; ++e) {
                const double length =
                    std::sqrt(edgeLength2(position(indices[i + e]), position(indices[i + (e + 1) % 3])));
                if (!std::isfinite(length))
                    continue;
                longest = std::max(longest, length);
                sum += length;
                ++count;
            }
    }
};

void truncateStreams(VertexStreams& v, size_t count)
{
    v.positions.resize(count);
    if (!v.normals.empty())
        v.normals.resize(count);
    if (!v.tangents.empty())
        v.tangents.resize(count);
    if (!v.uvs.empty())
        v.uvs.resize(count);
    DeformationStreams& d = v.deform;
    if (d.skinned()) {
        d.joints.resize(count);
        d.weights.resize(count);
    }
    for (std::vector<glm::vec3>* deltas : {&d.positions, &d.normals, &d.tangents})
        if (!deltas->empty())
            deltas->resize(count * d.morphTargets);
}

void appendStreams(VertexStreams& v, const VertexStreams& added)
{
    v.positions.insert(v.positions.end(), added.positions.begin(), added.positions.end());
    v.normals.insert(v.normals.end(), added.normals.begin(), added.normals.end());
    v.tangents.insert(v.tangents.end(), added.tangents.begin(), added.tangents.end());
    v.uvs.insert(v.uvs.end(), added.uvs.begin(), added.uvs.end());
    DeformationStreams& d = v.deform;
    d.joints.insert(d.joints.end(), added.deform.joints.begin(), added.deform.joints.end());
    d.weights.insert(d.weights.end(), added.deform.weights.begin(), added.deform.weights.end());
    d.positions.insert(d.positions.end(), added.deform.positions.begin(), added.deform.positions.end());
    d.normals.insert(d.normals.end(), added.deform.normals.begin(), added.deform.normals.end());
    d.tangents.insert(d.tangents.end(), added.deform.tangents.begin(), added.deform.tangents.end());
}

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

// Edges of a group's triangles, object units.
EdgeSummary groupEdges(const Scene& scene, const Group& group)
{
    const auto& positions = scene.vertices.positions;
    EdgeSummary edges;
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        edges.add([&](uint32_t i) -> const glm::vec3& { return positions[i]; },
                  scene.indices.data() + prim.firstIndex, prim.indexCount);
    }
    return edges;
}

// The pieces of one primitive; `changed` false: none of its triangles was cut and its
// original index range is kept.
struct PrimitivePieces {
    std::vector<uint32_t> indices;
    bool changed = false;
};

// What tessellating one group produced. A group reads the scene and writes only its own
// result and the pieces of its own primitives, so groups can run on different threads.
struct GroupResult {
    double longestBefore = 0.0; // object units
    bool split = false;         // had an oversized edge, so it was tessellated
    VertexStreams added;        // new vertices, numbered from the scene's vertex count on
    size_t trianglesAdded = 0;  // output minus input triangles
    size_t trianglesSplit = 0;
    size_t unresolved = 0;
    bool surfaceBuilt = false;   // the group had faces to cut, so its surface was built
    bool surfaceRefused = false; // and OpenSubdiv refused it
    size_t fallbacks = 0;        // cut faces placed by barycentric weights instead
    double pieceEdgeSum = 0.0; // scene units, edges of the pieces of cut triangles
    size_t pieceEdgeCount = 0;
};

// What the groups of one tessellateMeshes call share: the scene-wide output limit, and
// which group failed first.
struct SplitShared {
    size_t available = 0;        // triangles that may be added: kMaxOutputTriangles minus the input
    std::atomic<size_t> used{0}; // triangles added by all groups so far
    // Groups after the lowest failed one stop at their next face (their work is lost
    // anyway); groups before it run on, since a serial run would have reached them first
    // and their own error, if any, is the one to report (parallel.h).
    std::atomic<size_t> firstFailed{std::numeric_limits<size_t>::max()};

    bool stopped(size_t group) const { return firstFailed.load(std::memory_order_relaxed) < group; }
    void failed(size_t group)
    {
        for (size_t seen = firstFailed.load(); group < seen && !firstFailed.compare_exchange_weak(seen, group);) {
        }
    }
};

// Thrown by a group that stopped because an earlier group failed; never reported, as the
// earlier group's error is always the lower item's.
struct Stopped {};

// A group's triangle count and the range of vertices its triangles use.
struct GroupRange {
    size_t triangles = 0;
    uint32_t firstVertex = kInvalid, lastVertex = 0;
};

GroupRange groupRange(const Scene& scene, const Group& group)
{
    GroupRange r;
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        r.triangles += prim.indexCount / 3;
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; ++i) {
            r.firstVertex = std::min(r.firstVertex, scene.indices[i]);
            r.lastVertex = std::max(r.lastVertex, scene.indices[i]);
        }
    }
    return r;
}

// Books the pieces one cut face emitted from out[before]: counts and edge figures, and the
// scene-wide total. That total only grows: once it is over the limit the bake is refused
// whichever group notices, so stop now rather than let every group run up its own worst
// case in memory.
template <typename Position>
void bookCutFace(const Position& position, const std::vector<uint32_t>& out, size_t before, const Group& group,
                 SplitShared& shared, GroupResult& result)
{
    ++result.trianglesSplit;
    const size_t added = (out.size() - before) / 3 - 1;
    result.trianglesAdded += added;
    EdgeSummary cut;
    cut.add(position, out.data() + before, out.size() - before);
    result.pieceEdgeSum += cut.sum * group.scale;
    result.pieceEdgeCount += cut.count;
    if (shared.used.fetch_add(added) + added > shared.available)
        throw BakeError(kTooManyTriangles);
}

// The tessellator's figures into the group's result, and the group's log lines.
void finishGroup(MeshTessellator& tessellator, GroupVertices& vertices, const std::string& label, size_t trianglesIn,
                 size_t trianglesOut, GroupResult& result, const Log& log)
{
    result.added = std::move(vertices.added);
    result.unresolved = tessellator.unresolved();
    result.surfaceBuilt = tessellator.surfaceBuilt();
    result.fallbacks = tessellator.fallbacks();
    if (const std::string refusal = tessellator.surfaceRefusal(); !refusal.empty()) {
        result.surfaceRefused = true;
        log.info("tessellation: " + label + ": OpenSubdiv refused the mesh (" + refusal +
                 "); its new points are placed by barycentric weights of the triangles' corners");
    }
    log.info("tessellation: " + label + ": " + std::to_string(trianglesIn) + " -> " + std::to_string(trianglesOut) +
             " triangles (" + std::to_string(result.trianglesSplit) + " split)");
}

// Tessellates the oversized triangles of one group, primitive by primitive.
void splitGroup(const Scene& scene, const Group& group, size_t groupIndex, const std::string& label,
                SplitShared& shared, ThreadBudget& threads, GroupResult& result, std::vector<PrimitivePieces>& pieces,
                const Log& log)
{
    const GroupRange range = groupRange(scene, group);
    const size_t groupTriangles = range.triangles;
    if (groupTriangles == 0)
        return;
    result.split = true;

    // Weld every vertex the group uses.
    GroupVertices vertices{scene.vertices, uint32_t(scene.vertices.size()), {}};
    MeshTessellator tessellator(vertices, range.firstVertex, size_t(range.lastVertex - range.firstVertex) + 1,
                                group.bound, groupTriangles);
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; i += 3)
            tessellator.weldFace(scene.indices.data() + i);
    }
    const auto position = [&](uint32_t i) -> const glm::vec3& { return vertices.position(i); };

    // Triangle by triangle; each primitive's pieces stay together and in order.
    size_t groupOut = 0, done = 0;
    ProgressClock progress(kProgressSeconds);
    for (uint32_t p : group.primitives) {
        const Primitive& prim = scene.primitives[p];
        std::vector<uint32_t>& out = pieces[p].indices;
        out.reserve(prim.indexCount + prim.indexCount / 2);
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount;) {
            // note: the limit a face is checked against before it is cut counts this
            // group's own pieces only, so whether a face is refused does not depend on
            // how far the other groups have got.
            const size_t faces = tessellator.plan(scene.indices.data() + i, (prim.firstIndex + prim.indexCount - i) / 3,
                                                  shared.available - result.trianglesAdded);
            const auto stopped = [&] { return shared.stopped(groupIndex); };
            tessellator.patterns(threads, stopped);
            if (stopped())
                throw Stopped{};
            for (size_t f = 0; f < faces; ++f) {
                const size_t before = out.size();
                if (tessellator.emit(f, out)) {
                    pieces[p].changed = true;
                    bookCutFace(position, out, before, group, shared, result);
                }
            }
            i += uint32_t(3 * faces);
            done += faces;
            if (progress.due())
                log.info("tessellation: " + label + ": " + std::to_string(done) + " / " +
                         std::to_string(groupTriangles) + " triangles, " +
                         std::to_string(groupOut + out.size() / 3) + " pieces so far");
        }
        groupOut += out.size() / 3;
        if (!pieces[p].changed)
            std::vector<uint32_t>().swap(out); // unchanged: the original range is kept
    }
    finishGroup(tessellator, vertices, label, groupTriangles, groupOut, result, log);
}

// New index buffer: primitives in index order, changed ones replaced by their pieces;
// triangles outside any primitive are carried over unchanged.
void rebuildIndexBuffer(Scene& scene, const std::vector<uint32_t>& order, std::vector<PrimitivePieces>& pieces,
                        size_t trianglesOut)
{
    std::vector<uint32_t> indices;
    indices.reserve(trianglesOut * 3);
    uint32_t cursor = 0; // next old index not yet copied
    for (uint32_t p : order) {
        Primitive& prim = scene.primitives[p];
        if (prim.firstIndex > cursor)
            indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.begin() + prim.firstIndex);
        cursor = std::max(cursor, prim.firstIndex + prim.indexCount);
        const auto first = uint32_t(indices.size());
        if (pieces[p].changed)
            indices.insert(indices.end(), pieces[p].indices.begin(), pieces[p].indices.end());
        else
            indices.insert(indices.end(), scene.indices.begin() + prim.firstIndex,
                           scene.indices.begin() + prim.firstIndex + prim.indexCount);
        prim.firstIndex = first;
        prim.indexCount = uint32_t(indices.size()) - first;
        std::vector<uint32_t>().swap(pieces[p].indices);
    }
    indices.insert(indices.end(), scene.indices.begin() + cursor, scene.indices.end());
    scene.indices = std::move(indices);
}

// A Log whose calls may come from several threads at once (one line at a time).
Log serialisedLog(const Log& log, std::mutex& mutex)
{
    Log out;
    out.info = [&log, &mutex](const std::string& s) {
        const std::lock_guard<std::mutex> lock(mutex);
        log.info(s);
    };
    out.warn = [&log, &mutex](const std::string& s) {
        const std::lock_guard<std::mutex> lock(mutex);
        log.warn(s);
    };
    return out;
}

// What the groups' results add up to, in group order (as a serial run would have: group
// g's new vertices follow those of the groups before it).
struct CombinedResults {
    size_t vertexCount = 0, trianglesAdded = 0, pieceEdgeCount = 0, unresolved = 0;
    double pieceEdgeSum = 0.0;
};

// Splits the groups that have an oversized edge (the others need no welding), each into
// its own result: the scene is not touched until every group is done. Groups run side by
// side; a group's face patterns use the threads other groups have finished with (a
// scene's largest mesh is often most of its work).
void splitGroups(const Scene& scene, const std::vector<Group>& groups, size_t trianglesIn, const Log& log,
                 unsigned threads, std::vector<GroupResult>& results, std::vector<PrimitivePieces>& pieces)
{
    SplitShared shared;
    shared.available = kMaxOutputTriangles - std::min(trianglesIn, kMaxOutputTriangles);
    std::mutex logMutex;
    const Log groupLog = serialisedLog(log, logMutex);
    ThreadBudget pool(threads);
    parallelFor(groups.size(), pool, [&](size_t g) {
        try {
            results[g].longestBefore = groupEdges(scene, groups[g]).longest;
            if (results[g].longestBefore > groups[g].bound)
                splitGroup(scene, groups[g], g, meshLabel(scene, uint32_t(g)), shared, pool, results[g], pieces,
                           groupLog);
        } catch (const Stopped&) {
            throw;
        } catch (...) {
            shared.failed(g);
            throw;
        }
    });
}

// Shifts each group's new vertex indices past the groups before it and sums the results.
CombinedResults combineResults(const std::vector<Group>& groups, const std::vector<GroupResult>& results,
                               size_t vertexCountIn, std::vector<PrimitivePieces>& pieces, TessellationStats& stats)
{
    CombinedResults c;
    c.vertexCount = vertexCountIn;
    for (size_t g = 0; g < groups.size(); ++g) {
        const GroupResult& r = results[g];
        stats.maxEdgeWorldBefore = std::max(stats.maxEdgeWorldBefore, r.longestBefore * groups[g].scale);
        if (!r.split)
            continue;
        const auto shift = uint32_t(c.vertexCount - vertexCountIn);
        if (shift > 0)
            for (uint32_t p : groups[g].primitives)
                for (uint32_t& index : pieces[p].indices)
                    if (index >= vertexCountIn)
                        index += shift;
        c.vertexCount += r.added.size();
        if (c.vertexCount > kMaxVertices)
            throw BakeError(kTooManyVertices);
        c.trianglesAdded += r.trianglesAdded;
        stats.trianglesSplit += r.trianglesSplit;
        c.pieceEdgeSum += r.pieceEdgeSum;
        c.pieceEdgeCount += r.pieceEdgeCount;
        c.unresolved += r.unresolved;
        stats.surfaceMeshes += r.surfaceBuilt && !r.surfaceRefused ? 1 : 0;
        stats.surfaceMeshesRefused += r.surfaceRefused ? 1 : 0;
        stats.surfaceFallbacks += r.fallbacks;
    }
    return c;
}

// Appends every group's new vertices; on failure the scene keeps the vertices it had.
void appendGroupVertices(Scene& scene, std::vector<GroupResult>& results, size_t vertexCountIn, size_t vertexCount)
{
    try {
        VertexStreams& v = scene.vertices;
        v.positions.reserve(vertexCount);
        v.normals.reserve(v.normals.empty() ? 0 : vertexCount);
        v.tangents.reserve(v.tangents.empty() ? 0 : vertexCount);
        v.uvs.reserve(v.uvs.empty() ? 0 : vertexCount);
        for (GroupResult& r : results) {
            appendStreams(v, r.added);
            r.added = VertexStreams(); // free it before the next group is appended
        }
    } catch (...) {
        truncateStreams(scene.vertices, vertexCountIn);
        throw;
    }
}

// The edge figures after the split (sums in group order, so the figures do not depend on
// the thread count), and the log lines.
void reportEdges(const Scene& scene, const std::vector<Group>& groups, const CombinedResults& c, const Log& log,
                 unsigned threads, TessellationStats& stats)
{
    stats.trianglesOut = scene.triangleCount();
    std::vector<EdgeSummary> after(groups.size());
    parallelFor(groups.size(), threads, [&](size_t g) { after[g] = groupEdges(scene, groups[g]); });
    double edgeSum = 0.0;
    size_t edgeCount = 0;
    for (size_t g = 0; g < groups.size(); ++g) {
        stats.maxEdgeWorldAfter = std::max(stats.maxEdgeWorldAfter, after[g].longest * groups[g].scale);
        edgeSum += after[g].sum * groups[g].scale;
        edgeCount += after[g].count;
    }
    stats.meanEdgeWorldAfter = edgeCount > 0 ? edgeSum / double(edgeCount) : 0.0;
    stats.meanPieceEdgeWorld = c.pieceEdgeCount > 0 ? c.pieceEdgeSum / double(c.pieceEdgeCount) : 0.0;
    if (c.unresolved > 0)
        log.warn("tessellation: " + std::to_string(c.unresolved) +
                 " edges or triangles could not be cut within the bound (float precision); they exceed it");
    log.info("tessellation: " + std::to_string(stats.trianglesIn) + " -> " +
             std::to_string(stats.trianglesOut) + " triangles (" + std::to_string(stats.trianglesSplit) +
             " split), longest edge " + std::to_string(stats.maxEdgeWorldBefore) + " -> " +
             std::to_string(stats.maxEdgeWorldAfter) + " scene units, mean edge " +
             std::to_string(stats.meanEdgeWorldAfter) + " (pieces of split triangles " +
             std::to_string(stats.meanPieceEdgeWorld) + ")" +
             (stats.trianglesSplit > 0
                  ? "; new points on OpenSubdiv's bilinear surface of " + std::to_string(stats.surfaceMeshes) +
                        " meshes (refused: " + std::to_string(stats.surfaceMeshesRefused) +
                        "), split triangles placed by barycentric weights instead: " +
                        std::to_string(stats.surfaceFallbacks)
                  : std::string()));
}

} // namespace

TessellationStats tessellateMeshes(Scene& scene, const std::vector<double>& maxEdgeObject,
                                   const std::vector<float>& meshScale, const Log& log, unsigned threads)
{
    if (maxEdgeObject.size() != scene.meshes.size() || meshScale.size() != scene.meshes.size())
        throw BakeError("tessellation: expected one bound and one scale per mesh");
    validateScene(scene);
    const std::vector<uint32_t> order = primitivesInIndexOrder(scene);
    const std::vector<Group> groups = groupPrimitives(scene, maxEdgeObject, meshScale);

    TessellationStats stats;
    stats.trianglesIn = scene.triangleCount();
    std::vector<GroupResult> results(groups.size());
    std::vector<PrimitivePieces> pieces(scene.primitives.size());
    splitGroups(scene, groups, stats.trianglesIn, log, threads, results, pieces);

    const size_t vertexCountIn = scene.vertices.size();
    const CombinedResults combined = combineResults(groups, results, vertexCountIn, pieces, stats);
    if (stats.trianglesSplit > 0) {
        appendGroupVertices(scene, results, vertexCountIn, combined.vertexCount);
        rebuildIndexBuffer(scene, order, pieces, stats.trianglesIn + combined.trianglesAdded);
        scene.triangleStats.clear(); // no longer lines up with the triangles
    }
    reportEdges(scene, groups, combined, log, threads, stats);
    return stats;
}

// Blending between joints stretches the inside of a triangle more than its edges (a
// piece near a bending joint turns with the weight gradient), so a deformed mesh's
// pieces can exceed the bound in a pose although its original edges did not. The
// stretch is measured again on the pieces (meshMaxWorldScale over their own edges) and
// a mesh that stretches more than it was split for is split again, at most twice (the
// measure converges as the pieces shrink; tests/baker/geometry/skin_bake_test.cpp checks the
// bound at sampled poses).
void refineDeformedMeshes(Scene& scene, double maxEdgeWorld, std::vector<float> scale, const Log& log,
                          unsigned threads, TessellationStats& stats)
{
    for (int pass = 0; pass < 2 && !scene.deformers.empty(); ++pass) {
        const std::vector<float> posed = meshMaxWorldScale(scene);
        std::vector<double> maxEdgeObject(scene.meshes.size(), std::numeric_limits<double>::infinity());
        bool again = false;
        for (size_t m = 0; m < posed.size(); ++m)
            if (std::isfinite(posed[m]) && posed[m] > scale[m] * 1.0001f) {
                maxEdgeObject[m] = maxEdgeWorld / double(posed[m]);
                scale[m] = posed[m];
                again = true;
            }
        if (!again)
            return;
        const TessellationStats more = tessellateMeshes(scene, maxEdgeObject, scale, log, threads);
        assignDeformerVertices(scene);
        stats.trianglesOut = more.trianglesOut;
        stats.trianglesSplit += more.trianglesSplit;
        stats.maxEdgeWorldAfter = more.maxEdgeWorldAfter;
        stats.meanEdgeWorldAfter = more.meanEdgeWorldAfter;
    }
}

TessellationStats tessellateScene(Scene& scene, double maxEdgeWorld, const Log& log, unsigned threads)
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
    TessellationStats stats = tessellateMeshes(scene, maxEdgeObject, scale, log, threads);
    assignDeformerVertices(scene); // new vertices were appended after every mesh's
    refineDeformedMeshes(scene, maxEdgeWorld, scale, log, threads, stats);
    return stats;
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
