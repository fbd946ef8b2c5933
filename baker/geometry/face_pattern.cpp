// Tessellation pattern of one oversized triangle (see face_pattern.h).
//
// The paper's bound ("spanned no more than a hundred pixels") holds for every output
// edge, not just the boundary, so every candidate is checked on the output positions and
// the one with the fewest triangles within the bound wins. Patterns are built in
// barycentric weights of the face's corners (a point with Bfr coordinates (u, v) of the
// triangle parameterization has weights (1 - u - v, u, v)); every position, both those
// the bound is checked on and those then stored (FacePattern::interiorPoints), comes from
// the caller's FacePoint: in tessellation.cpp the face's bilinear Bfr::Surface
// (bilinear_surface.h), which is the flat triangle.
//
// First, the boundary polygon triangulated without interior points: any triangulation of
// V boundary points with I interior points has V - 2 + 2I triangles, so if this one
// meets the bound nothing beats it (rates 2, 1, 1: 2 triangles, where Bfr, which always
// adds an interior point for unequal rates, fans 4). Most oversized triangles of the
// samples end here. Otherwise candidates, each bisected where edges exceed the bound,
// both as they are and relaxed (edge flips and smoothing of interior points) first:
// - OpenSubdiv's Bfr::Tessellation for the face's edge rates: inner rate 1 (a fan around
//   one interior point), the uniform pattern for equal rates up to 3, and the smallest
//   inner rate whose interior grid meets the bound (Bfr's transition strip between
//   boundary and grid can still exceed it on a long thin face);
// - for faces with few boundary points, the boundary-only triangulations.
// Measured on the gallery sample's faces that need interior points (bounds 100, 40, 20,
// 10 px), each kind wins on some: Bfr's fan relaxed and bisected on about half, Bfr's
// grid (as is or relaxed) on most of the rest, a boundary-only triangulation bisected on
// the remainder.
// Every candidate has the same boundary points, so the choice changes nothing at shared
// edges.
//
// Why the triangle parameterization for the patterns, although the surface is the
// bilinear scheme's: Bfr parameterizes a triangle of the bilinear scheme as three quad
// sub-faces, whose patterns need about 1.5x the triangles (rates 2..6: 6/13/24/37/54
// triangles against 4/9/16/25/36). The triangle parameterization (the one of the Loop
// scheme, whose regular face is the triangle) gives n^2 triangles for rate n. Only the
// parameterization is taken from Loop, never its surface; the bilinear surface converts
// each point's barycentric weights to its own sub-face coordinates.

#include "face_pattern.h"

#include "bake_log.h"

#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/tessellation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <string>
#include <unordered_map>

namespace lfd::bake {
namespace {

namespace Bfr = OpenSubdiv::Bfr;

// The boundary-only triangulation is an O(V^3) search over the V boundary points; on
// faces with more, the long diagonals it starts from bisect into more triangles than
// Bfr's grid needs (measured on the gallery sample at 10 px: 30% more).
constexpr size_t kMaxBoundaryOnlyPoints = 24;
constexpr int kRelaxRounds = 4;

double distance(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::dvec3(b) - glm::dvec3(a)); }

double longestFacetEdge(const std::vector<int>& facets, const std::vector<glm::vec3>& points)
{
    double longest = 0.0;
    for (size_t f = 0; f < facets.size(); f += 3)
        for (size_t e = 0; e < 3; ++e) {
            const double length = distance(points[size_t(facets[f + e])], points[size_t(facets[f + (e + 1) % 3])]);
            if (std::isfinite(length))
                longest = std::max(longest, length);
        }
    return longest;
}

// Bfr (u, v) of boundary point p, in the order of boundaryPointCount.
glm::dvec2 expectedBoundaryCoord(const std::array<int, 3>& r, size_t p)
{
    const auto k = double(p);
    if (p <= size_t(r[0]))
        return {k / r[0], 0.0};
    if (p <= size_t(r[0] + r[1])) {
        const double t = (k - r[0]) / r[1];
        return {1.0 - t, t};
    }
    const double t = (k - r[0] - r[1]) / r[2];
    return {0.0, 1.0 - t};
}

// A candidate pattern under construction: points (boundary first) with their barycentric
// weights and positions, and triangles over them.
struct LocalMesh {
    std::vector<glm::dvec3> weights;
    std::vector<glm::vec3> points;
    std::vector<std::array<size_t, 3>> triangles;
    bool fromOpenSubdiv = false;
};

LocalMesh boundaryMesh(const std::array<int, 3>& rates, std::span<const glm::vec3> boundary)
{
    LocalMesh mesh;
    mesh.points.assign(boundary.begin(), boundary.end());
    for (size_t p = 0; p < boundary.size(); ++p) {
        const glm::dvec2 uv = expectedBoundaryCoord(rates, p);
        mesh.weights.emplace_back(1.0 - uv.x - uv.y, uv.x, uv.y);
    }
    return mesh;
}

// Longest-edge bisection of the edges over the bound, longest first. The longest edge of
// the face is never a boundary piece (those are within the bound), and both triangles
// beside an edge are cut at its midpoint, so the face stays conforming (no T-junctions
// inside it) and its boundary is never touched. Returns false if the triangle count
// would pass maxTriangles.
bool bisectLongEdges(const FacePoint& pointAt, LocalMesh& mesh, double bound, size_t maxTriangles)
{
    auto key = [](size_t a, size_t b) { return uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b)); };
    constexpr size_t kNoTriangle = std::numeric_limits<size_t>::max();
    std::unordered_map<uint64_t, std::array<size_t, 2>> trianglesOf; // edge -> the (up to) two beside it
    struct LongEdge {
        double length;
        size_t a, b;
        bool operator<(const LongEdge& o) const { return length < o.length; }
    };
    std::priority_queue<LongEdge> queue;
    auto attach = [&](size_t a, size_t b, size_t t) {
        auto [it, inserted] = trianglesOf.try_emplace(key(a, b), std::array<size_t, 2>{t, kNoTriangle});
        if (!inserted)
            it->second[1] = t;
        const double length = distance(mesh.points[a], mesh.points[b]);
        if (inserted && length > bound)
            queue.push({length, a, b});
    };
    auto reattach = [&](size_t a, size_t b, size_t from, size_t to) {
        auto& pair = trianglesOf.at(key(a, b));
        (pair[0] == from ? pair[0] : pair[1]) = to;
    };
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (size_t e = 0; e < 3; ++e)
            attach(mesh.triangles[t][e], mesh.triangles[t][(e + 1) % 3], t);

    while (!queue.empty()) {
        const LongEdge edge = queue.top();
        queue.pop();
        const auto found = trianglesOf.find(key(edge.a, edge.b));
        if (found == trianglesOf.end())
            continue; // already bisected
        const std::array<size_t, 2> beside = found->second;
        trianglesOf.erase(found);
        if (mesh.triangles.size() + 2 > maxTriangles)
            return false;
        const size_t m = mesh.points.size();
        mesh.weights.push_back(0.5 * (mesh.weights[edge.a] + mesh.weights[edge.b]));
        mesh.points.push_back(pointAt(mesh.weights.back()));
        for (size_t t : beside) {
            if (t == kNoTriangle)
                continue;
            const std::array<size_t, 3> tri = mesh.triangles[t];
            size_t e = 0;
            while (!((tri[e] == edge.a && tri[(e + 1) % 3] == edge.b) || (tri[e] == edge.b && tri[(e + 1) % 3] == edge.a)))
                ++e;
            const size_t x = tri[e], y = tri[(e + 1) % 3], z = tri[(e + 2) % 3];
            const size_t added = mesh.triangles.size();
            mesh.triangles[t] = {x, m, z}; // both halves keep the winding
            mesh.triangles.push_back({m, y, z});
            reattach(y, z, t, added);
            attach(x, m, t);
            attach(m, y, added);
            attach(m, z, t);
            attach(m, z, added);
        }
    }
    return true;
}

// Twice the signed area of triangle (a, b, c) in the face's parameter plane (barycentric
// weights 1 and 2); positive for the face's winding. The plane maps affinely onto the
// face, so a triangle keeps its winding on the face exactly when it does here.
double parametricArea(const LocalMesh& mesh, size_t a, size_t b, size_t c)
{
    const glm::dvec2 pa(mesh.weights[a].y, mesh.weights[a].z), pb(mesh.weights[b].y, mesh.weights[b].z),
        pc(mesh.weights[c].y, mesh.weights[c].z);
    return (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
}

// Smaller than this (twice a parametric area), a triangle counts as flipped over.
constexpr double kMinRelaxArea = 1e-12;

// One pass of diagonal flips: the diagonal of two triangles becomes the shorter one where
// both stay properly wound, each triangle flipped at most once. Returns whether any was.
bool flipPass(LocalMesh& mesh, std::vector<std::pair<uint64_t, size_t>>& edges)
{
    auto key = [](size_t a, size_t b) { return uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b)); };
    // Edges as (key, triangle), sorted: an interior edge is two equal keys in a row.
    edges.clear();
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (size_t e = 0; e < 3; ++e)
            edges.emplace_back(key(mesh.triangles[t][e], mesh.triangles[t][(e + 1) % 3]), t);
    std::sort(edges.begin(), edges.end());
    std::vector<bool> touched(mesh.triangles.size(), false);
    bool flipped = false;
    for (size_t i = 0; i + 1 < edges.size(); ++i) {
        if (edges[i].first != edges[i + 1].first)
            continue;
        const uint64_t edgeKey = edges[i].first;
        const size_t t0 = edges[i].second, t1 = edges[i + 1].second;
        ++i;
        if (touched[t0] || touched[t1])
            continue;
        const size_t a = size_t(edgeKey >> 32), b = size_t(edgeKey & 0xffffffffu);
        // t0 = (a, b, c) and t1 = (b, a, d) in winding order, whichever holds a -> b.
        auto opposite = [&](size_t t) {
            for (size_t e = 0; e < 3; ++e)
                if (mesh.triangles[t][e] != a && mesh.triangles[t][e] != b)
                    return e;
            return size_t(0);
        };
        const std::array<size_t, 3>& tri0 = mesh.triangles[t0];
        const size_t e0 = opposite(t0);
        const bool forward = tri0[(e0 + 1) % 3] == a; // (c, a, b): t0 holds a -> b
        const size_t from = forward ? a : b, to = forward ? b : a;
        const size_t c = tri0[e0], d = mesh.triangles[t1][opposite(t1)];
        if (distance(mesh.points[c], mesh.points[d]) >= distance(mesh.points[a], mesh.points[b]))
            continue;
        // New triangles (from, d, c) and (d, to, c): the quad from, d, to, c.
        if (parametricArea(mesh, from, d, c) <= kMinRelaxArea || parametricArea(mesh, d, to, c) <= kMinRelaxArea)
            continue;
        mesh.triangles[t0] = {from, d, c};
        mesh.triangles[t1] = {d, to, c};
        touched[t0] = touched[t1] = true;
        flipped = true;
    }
    return flipped;
}

// Moves every interior point to the centroid of its neighbours where none of its triangles
// flips over.
void smoothInterior(const FacePoint& pointAt, LocalMesh& mesh, size_t boundaryCount)
{
    std::vector<std::vector<size_t>> around(mesh.points.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (size_t v : mesh.triangles[t])
            if (v >= boundaryCount)
                around[v].push_back(t);
    for (size_t v = boundaryCount; v < mesh.points.size(); ++v) {
        glm::dvec3 sum(0.0);
        size_t count = 0;
        for (size_t t : around[v])
            for (size_t u : mesh.triangles[t])
                if (u != v) {
                    sum += mesh.weights[u];
                    ++count;
                }
        if (count == 0)
            continue;
        const glm::dvec3 previous = mesh.weights[v];
        mesh.weights[v] = sum / double(count);
        bool wound = true;
        for (size_t t : around[v])
            wound = wound && parametricArea(mesh, mesh.triangles[t][0], mesh.triangles[t][1],
                                            mesh.triangles[t][2]) > kMinRelaxArea;
        if (wound)
            mesh.points[v] = pointAt(mesh.weights[v]);
        else
            mesh.weights[v] = previous;
    }
}

// Shortens edges without adding points, so that fewer of them need bisecting: flips the
// diagonal of two triangles to the shorter one where both stay properly wound (each flip
// shortens the total edge length, so this ends), then moves every interior point to the
// centroid of its neighbours where none of its triangles flips over. Interior points
// only: the boundary, which neighbouring faces share, never moves.
void relax(const FacePoint& pointAt, LocalMesh& mesh, size_t boundaryCount, int rounds)
{
    std::vector<std::pair<uint64_t, size_t>> edges;
    for (int round = 0; round < rounds; ++round) {
        // Flip passes until none applies, at most 8 per round (more changed no triangle
        // count on the samples; the rounds repeat them anyway).
        for (int pass = 0; pass < 8; ++pass)
            if (!flipPass(mesh, edges))
                break;
        smoothInterior(pointAt, mesh, boundaryCount);
    }
}

FacePattern toPattern(const LocalMesh& mesh, size_t boundaryCount)
{
    FacePattern pattern;
    pattern.fromOpenSubdiv = mesh.fromOpenSubdiv;
    pattern.interiorWeights.assign(mesh.weights.begin() + std::ptrdiff_t(boundaryCount), mesh.weights.end());
    pattern.interiorPoints.assign(mesh.points.begin() + std::ptrdiff_t(boundaryCount), mesh.points.end());
    for (const auto& t : mesh.triangles)
        pattern.facets.insert(pattern.facets.end(), {int(t[0]), int(t[1]), int(t[2])});
    pattern.longestEdge = longestFacetEdge(pattern.facets, mesh.points);
    return pattern;
}

LocalMesh openSubdivMesh(const FacePoint& pointAt, const std::array<int, 3>& rates,
                         std::span<const glm::vec3> boundary, int innerRate)
{
    // Loop's regular face is the triangle: this is Bfr's triangle parameterization.
    static const Bfr::Parameterization kTriangle(OpenSubdiv::Sdc::SCHEME_LOOP, 3);
    const int allRates[4] = {rates[0], rates[1], rates[2], innerRate};
    const Bfr::Tessellation tessellation(kTriangle, 4, allRates, Bfr::Tessellation::Options().SetFacetSize(3));
    if (!tessellation.IsValid())
        throw BakeError("tessellation: OpenSubdiv refused edge rates " + std::to_string(rates[0]) + ", " +
                        std::to_string(rates[1]) + ", " + std::to_string(rates[2]));
    if (size_t(tessellation.GetNumBoundaryCoords()) != boundary.size())
        throw BakeError("tessellation: OpenSubdiv made an unexpected number of boundary points");

    std::vector<double> coords(2 * size_t(tessellation.GetNumCoords()));
    tessellation.GetCoords(coords.data());
    // The boundary points are made by tessellation.cpp (shared by both faces of an edge),
    // so Bfr's boundary order must be the one assumed there.
    for (size_t p = 0; p < boundary.size(); ++p) {
        const glm::dvec2 expected = expectedBoundaryCoord(rates, p);
        if (std::abs(coords[2 * p] - expected.x) > 1e-9 || std::abs(coords[2 * p + 1] - expected.y) > 1e-9)
            throw BakeError("tessellation: OpenSubdiv's boundary points are not in the expected order");
    }

    LocalMesh mesh = boundaryMesh(rates, boundary);
    mesh.fromOpenSubdiv = true;
    for (size_t c = boundary.size(); c < size_t(tessellation.GetNumCoords()); ++c) {
        const double u = coords[2 * c], v = coords[2 * c + 1];
        mesh.weights.emplace_back(1.0 - u - v, u, v);
        mesh.points.push_back(pointAt(mesh.weights.back()));
    }
    std::vector<int> facets(3 * size_t(tessellation.GetNumFacets()));
    tessellation.GetFacets(facets.data());
    for (size_t f = 0; f < facets.size(); f += 3)
        mesh.triangles.push_back({size_t(facets[f]), size_t(facets[f + 1]), size_t(facets[f + 2])});
    return mesh;
}

// The boundary polygon triangulated without interior points, by `shape`; none if it
// cannot be (every triple collinear: a degenerate face).
enum class Shape {
    ShortestLongestEdge, // then the shortest total diagonal length
    ShortestDiagonals,   // well-shaped triangles, even if one edge is long
};

std::optional<LocalMesh> boundaryOnlyMesh(const std::array<int, 3>& rates, std::span<const glm::vec3> boundary,
                                          Shape shape)
{
    const size_t n = boundary.size();
    const size_t corner1 = size_t(rates[0]), corner2 = size_t(rates[0] + rates[1]);
    auto onEdge = [&](size_t p, int edge) {
        switch (edge) {
        case 0: return p <= corner1;
        case 1: return p >= corner1 && p <= corner2;
        default: return p >= corner2 || p == 0;
        }
    };
    // Three points on one edge of the face are collinear: never a triangle.
    auto collinear = [&](size_t a, size_t b, size_t c) {
        for (int edge = 0; edge < 3; ++edge)
            if (onEdge(a, edge) && onEdge(b, edge) && onEdge(c, edge))
                return true;
        return false;
    };
    std::vector<double> length(n * n);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            length[i * n + j] = distance(boundary[i], boundary[j]);

    // Best triangulation of each sub-polygon i..j (i < j) by `shape`.
    struct Cost {
        double longest = std::numeric_limits<double>::infinity();
        double diagonals = 0.0;
    };
    auto less = [shape](const Cost& a, const Cost& b) {
        if (shape == Shape::ShortestDiagonals)
            return std::isfinite(a.longest) && (!std::isfinite(b.longest) || a.diagonals < b.diagonals);
        return a.longest < b.longest || (a.longest == b.longest && a.diagonals < b.diagonals);
    };
    std::vector<Cost> cost(n * n);
    std::vector<size_t> apex(n * n, 0);
    for (size_t i = 0; i + 1 < n; ++i)
        cost[i * n + i + 1] = {length[i * n + i + 1], 0.0};
    for (size_t gap = 2; gap < n; ++gap)
        for (size_t i = 0; i + gap < n; ++i) {
            const size_t j = i + gap;
            for (size_t k = i + 1; k < j; ++k) {
                if (collinear(i, k, j))
                    continue;
                const Cost& left = cost[i * n + k];
                const Cost& right = cost[k * n + j];
                const Cost c{std::max({left.longest, right.longest, length[i * n + j]}),
                             left.diagonals + right.diagonals + (k - i > 1 ? length[i * n + k] : 0.0) +
                                 (j - k > 1 ? length[k * n + j] : 0.0)};
                if (less(c, cost[i * n + j])) {
                    cost[i * n + j] = c;
                    apex[i * n + j] = k;
                }
            }
        }
    if (!std::isfinite(cost[n - 1].longest))
        return std::nullopt;

    LocalMesh mesh = boundaryMesh(rates, boundary);
    std::vector<std::pair<size_t, size_t>> stack = {{0, n - 1}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2)
            continue;
        const size_t k = apex[i * n + j];
        // i < k < j runs counter-clockwise like the boundary: the face's winding.
        mesh.triangles.push_back({i, k, j});
        stack.emplace_back(i, k);
        stack.emplace_back(k, j);
    }
    return mesh;
}

// Better of two candidates: within the bound first, then fewer triangles, then a shorter
// longest edge.
bool better(const FacePattern& a, const FacePattern& b, double bound)
{
    const bool aFits = a.longestEdge <= bound, bFits = b.longestEdge <= bound;
    if (aFits != bFits)
        return aFits;
    if (!aFits)
        return a.longestEdge < b.longestEdge;
    return a.facets.size() < b.facets.size();
}

} // namespace

size_t boundaryPointCount(const std::array<int, 3>& rates)
{
    return size_t(rates[0]) + size_t(rates[1]) + size_t(rates[2]);
}

glm::vec3 interiorPosition(const std::array<glm::vec3, 3>& corners, const glm::dvec3& weights)
{
    return glm::vec3(weights.x * glm::dvec3(corners[0]) + weights.y * glm::dvec3(corners[1]) +
                     weights.z * glm::dvec3(corners[2]));
}

FacePattern facePattern(const std::array<glm::vec3, 3>& corners, const std::array<int, 3>& rates,
                        std::span<const glm::vec3> boundary, double bound)
{
    return facePattern([&corners](const glm::dvec3& w) { return interiorPosition(corners, w); }, rates, boundary,
                       bound);
}

FacePattern facePattern(const FacePoint& pointAt, const std::array<int, 3>& rates, std::span<const glm::vec3> boundary,
                        double bound)
{
    if (boundary.size() != boundaryPointCount(rates))
        throw BakeError("tessellation: boundary point count does not match the edge rates");

    // Any triangulation of V boundary points with I interior points has V - 2 + 2I
    // triangles: one without interior points that meets the bound cannot be beaten (and
    // is what most oversized triangles of real scenes get, cheaply).
    if (boundary.size() <= kMaxBoundaryOnlyPoints)
        if (std::optional<LocalMesh> mesh = boundaryOnlyMesh(rates, boundary, Shape::ShortestLongestEdge)) {
            FacePattern fewest = toPattern(*mesh, boundary.size());
            if (fewest.longestEdge <= bound)
                return fewest;
        }

    std::optional<FacePattern> best;
    auto consider = [&](LocalMesh mesh) {
        // Generous: a face needs about area / (0.43 bound^2) triangles; far more than its
        // pattern's own count means bisection is chasing float rounding.
        const size_t maxTriangles = 4 * (mesh.triangles.size() + boundary.size() * boundary.size());
        LocalMesh relaxed = mesh;
        if (bisectLongEdges(pointAt, mesh, bound, maxTriangles)) {
            FacePattern candidate = toPattern(mesh, boundary.size());
            if (!best || better(candidate, *best, bound))
                best = std::move(candidate);
        }
        // The same, relaxed before and after bisection.
        relax(pointAt, relaxed, boundary.size(), kRelaxRounds);
        if (bisectLongEdges(pointAt, relaxed, bound, maxTriangles)) {
            relax(pointAt, relaxed, boundary.size(), kRelaxRounds);
            FacePattern candidate = toPattern(relaxed, boundary.size());
            if (!best || better(candidate, *best, bound))
                best = std::move(candidate);
        }
    };

    // Inner rate 1 gives the fan around one interior point; equal edge rates n <= 3 with
    // inner rate n give the uniform pattern (inner rates 2 and 3 otherwise repeat the fan).
    consider(openSubdivMesh(pointAt, rates, boundary, 1));
    if (rates[0] == rates[1] && rates[1] == rates[2] && rates[0] >= 2 && rates[0] <= 3)
        consider(openSubdivMesh(pointAt, rates, boundary, rates[0]));
    // From inner rate 4 on, interior points lie on a grid of spacing 1/m in barycentric
    // coordinates, so its edges along face edge i measure |edge i| / m: below the largest
    // edge rate (ceil(|edge| / bound)) the grid itself exceeds the bound, and larger
    // inner rates only add triangles.
    const int largestRate = std::max({rates[0], rates[1], rates[2]});
    if (largestRate >= 4)
        consider(openSubdivMesh(pointAt, rates, boundary, largestRate));
    if (boundary.size() <= kMaxBoundaryOnlyPoints)
        for (Shape shape : {Shape::ShortestLongestEdge, Shape::ShortestDiagonals})
            if (std::optional<LocalMesh> mesh = boundaryOnlyMesh(rates, boundary, shape))
                consider(std::move(*mesh));
    if (!best) // every candidate ran past its triangle limit: the uniform pattern as it is
        best = toPattern(openSubdivMesh(pointAt, rates, boundary, largestRate), boundary.size());
    return *best;
}

} // namespace lfd::bake
