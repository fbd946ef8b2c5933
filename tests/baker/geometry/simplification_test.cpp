// Issue 40: display-aware simplification. An over-dense heightfield loses most of its
// triangles within the error bound; attribute seams, mesh borders and material boundaries
// keep every vertex; skinned meshes are left whole; instanced meshes are simplified for
// their largest scale; the result is the same for any thread count; the tessellation
// bound still holds after.
#include "bake_log.h"
#include "simplification.h"
#include "tessellation.h"

#include "skinned_test_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace lfd::bake {
namespace {

// Smooth hills over [0, size]^2 in x/z with heights up to `amplitude`.
float hills(float x, float z, float size, float amplitude)
{
    const float u = x / size, v = z / size;
    return amplitude * (std::sin(6.0f * u + 0.3f) * std::cos(5.0f * v - 0.2f) + 0.3f * std::sin(17.0f * u * v));
}

struct GridOptions {
    uint32_t cells = 64;
    float size = 1.0f;
    float amplitude = 0.0f;  // 0: flat
    glm::vec3 origin{0.0f};
    int32_t material = kNone;
    bool uvSeam = false;     // the middle column of vertices twice, with uvs 1 apart
    uint32_t splitColumn = 0; // > 0: cells left of it are one primitive (material 0), the rest another (material 1)
};

// An (n + 1)^2-vertex grid in x/z as one mesh (one or two primitives). Returns the mesh.
uint32_t addHeightfield(Scene& s, const GridOptions& o)
{
    VertexStreams& v = s.vertices;
    const uint32_t n = o.cells, row = n + 1;
    const auto base = uint32_t(v.positions.size());
    auto position = [&](uint32_t i, uint32_t j) {
        const float x = o.size * float(i) / float(n), z = o.size * float(j) / float(n);
        return o.origin + glm::vec3(x, hills(x, z, o.size, o.amplitude), z);
    };
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) {
            v.positions.push_back(position(i, j));
            v.normals.emplace_back(0.0f, 1.0f, 0.0f);
            v.uvs.emplace_back(float(i) / float(n), float(j) / float(n));
        }
    // The seam: the right side of column n / 2 uses copies with uv.x + 1.
    const uint32_t seamColumn = n / 2, seamBase = uint32_t(v.positions.size());
    if (o.uvSeam)
        for (uint32_t j = 0; j <= n; ++j) {
            v.positions.push_back(position(seamColumn, j));
            v.normals.emplace_back(0.0f, 1.0f, 0.0f);
            v.uvs.emplace_back(float(seamColumn) / float(n) + 1.0f, float(j) / float(n));
        }
    auto vertex = [&](uint32_t i, uint32_t j, bool rightOfSeam) {
        if (o.uvSeam && i == seamColumn && rightOfSeam)
            return seamBase + j;
        return base + j * row + i;
    };
    Mesh mesh{"grid " + std::to_string(s.meshes.size()), uint32_t(s.primitives.size()), 0};
    const uint32_t split = o.splitColumn > 0 ? o.splitColumn : n;
    for (auto [from, to, material] : {std::tuple{0u, split, o.splitColumn > 0 ? 0 : o.material},
                                      std::tuple{split, n, 1}}) {
        if (from >= to)
            continue;
        Primitive prim{uint32_t(s.indices.size()), 0, material};
        for (uint32_t j = 0; j < n; ++j)
            for (uint32_t i = from; i < to; ++i) {
                const bool right = i >= seamColumn;
                const uint32_t a = vertex(i, j, right), b = vertex(i + 1, j, right), c = vertex(i, j + 1, right),
                               d = vertex(i + 1, j + 1, right);
                s.indices.insert(s.indices.end(), {a, c, b, b, c, d});
            }
        prim.indexCount = uint32_t(s.indices.size()) - prim.firstIndex;
        s.primitives.push_back(prim);
        ++mesh.primitiveCount;
    }
    s.meshes.push_back(mesh);
    return uint32_t(s.meshes.size() - 1);
}

std::set<uint32_t> usedVertices(const Scene& s, uint32_t primitive)
{
    const Primitive& p = s.primitives[primitive];
    return {s.indices.begin() + p.firstIndex, s.indices.begin() + p.firstIndex + p.indexCount};
}

bool samePosition(const glm::vec3& a, const glm::vec3& b) { return a == b; }

// Vertices of `s` at the position of each of `positions` (by exact position).
size_t countAt(const Scene& s, const std::set<uint32_t>& used, const std::vector<glm::vec3>& positions)
{
    size_t found = 0;
    for (const glm::vec3& p : positions)
        found += std::any_of(used.begin(), used.end(), [&](uint32_t v) { return samePosition(s.vertices.positions[v], p); })
                     ? 1
                     : 0;
    return found;
}

const Log kQuiet;

std::vector<double> all(const Scene& s, double value) { return std::vector<double>(s.meshes.size(), value); }

// ---- Over-dense heightfield -----------------------------------------------------------

// Height of the simplified heightfield (primitive 0) under (x, z), by the triangle whose
// x/z projection contains it; NaN where none does.
struct HeightLookup {
    const Scene& s;
    uint32_t cells;
    float size;
    std::vector<std::vector<uint32_t>> buckets; // triangle ids by bounding-box cell

    HeightLookup(const Scene& scene, uint32_t grid, float extent) : s(scene), cells(grid), size(extent)
    {
        buckets.resize(size_t(cells) * cells);
        for (uint32_t t = 0; t < s.triangleCount(); ++t) {
            glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = s.vertices.positions[s.indices[3 * t + k]];
                lo = glm::min(lo, glm::vec2(p.x, p.z));
                hi = glm::max(hi, glm::vec2(p.x, p.z));
            }
            const glm::uvec2 a = cell(lo), b = cell(hi);
            for (uint32_t j = a.y; j <= b.y; ++j)
                for (uint32_t i = a.x; i <= b.x; ++i)
                    buckets[size_t(j) * cells + i].push_back(t);
        }
    }
    glm::uvec2 cell(glm::vec2 p) const
    {
        const glm::vec2 c = glm::clamp(p / size * float(cells), glm::vec2(0.0f), glm::vec2(float(cells) - 1.0f));
        return glm::uvec2(c);
    }
    double height(double x, double z) const
    {
        for (uint32_t t : buckets[size_t(cell({float(x), float(z)}).y) * cells + cell({float(x), float(z)}).x]) {
            const glm::dvec3 a(s.vertices.positions[s.indices[3 * t]]), b(s.vertices.positions[s.indices[3 * t + 1]]),
                c(s.vertices.positions[s.indices[3 * t + 2]]);
            const double det = (b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z);
            if (det == 0.0)
                continue;
            const double u = ((x - a.x) * (c.z - a.z) - (c.x - a.x) * (z - a.z)) / det;
            const double w = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / det;
            constexpr double eps = 1e-9;
            if (u >= -eps && w >= -eps && u + w <= 1.0 + eps)
                return a.y + u * (b.y - a.y) + w * (c.y - a.y);
        }
        return std::numeric_limits<double>::quiet_NaN();
    }
};

TEST(Simplification, OverDenseHeightfieldLosesMostTrianglesWithinTheBound)
{
    // 400^2 cells (320K triangles) of gentle hills: 1/400 of the patch per cell, so a
    // bound of 1/1000 of it is finer than nothing the grid resolves, yet most triangles
    // are far below it.
    Scene s;
    const GridOptions grid{.cells = 400, .size = 1.0f, .amplitude = 0.05f};
    addHeightfield(s, grid);
    const Scene input = s;
    const double bound = 1e-3;
    const SimplificationStats stats = simplifyMeshes(s, all(s, bound), all(s, 1.0), kQuiet, 2);
    EXPECT_EQ(stats.trianglesIn, input.triangleCount());
    EXPECT_EQ(stats.trianglesOut, s.triangleCount());
    EXPECT_GE(input.triangleCount(), 5 * s.triangleCount()) << s.triangleCount() << " triangles left";
    EXPECT_LE(stats.maxErrorPx, bound);
    ASSERT_EQ(stats.meshes.size(), 1u);
    EXPECT_EQ(stats.meshes[0].trianglesOut, s.triangleCount());
    EXPECT_LT(s.vertices.size(), input.vertices.size() / 5) << "vertices no triangle uses are dropped";

    // Measured: every input vertex lies within the bound of the simplified surface. The
    // vertical distance bounds the true one from above; slopes are gentle (<= 0.4), so
    // it overstates it by at most sqrt(1 + 0.4^2) ~ 8%.
    const HeightLookup lookup(s, 64, grid.size);
    double worst = 0.0;
    for (const glm::vec3& p : input.vertices.positions) {
        const double h = lookup.height(p.x, p.z);
        ASSERT_FALSE(std::isnan(h)) << "hole in the simplified surface at " << p.x << ", " << p.z;
        worst = std::max(worst, std::abs(h - double(p.y)));
    }
    EXPECT_LE(worst, 1.1 * bound) << "largest vertical distance";
    EXPECT_LE(worst, 1.1 * stats.maxErrorPx) << "the reported error does not understate";
    std::printf("heightfield: %zu -> %zu triangles, reported error %.3g, measured vertical distance %.3g (bound %.3g)\n",
                input.triangleCount(), s.triangleCount(), stats.maxErrorPx, worst, bound);
    EXPECT_GT(worst, 0.1 * bound) << "the bound was used";

    // Merge, then split: the tessellation bound holds on the simplified mesh.
    const double maxEdge = 0.02;
    tessellateMeshes(s, all(s, maxEdge), std::vector<float>(s.meshes.size(), 1.0f), kQuiet, 2);
    double longest = 0.0;
    for (size_t t = 0; t < s.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, double(glm::distance(s.vertices.positions[s.indices[3 * t + k]],
                                                             s.vertices.positions[s.indices[3 * t + (k + 1) % 3]])));
    EXPECT_LE(longest, maxEdge);
}

TEST(Simplification, ZeroOrNoBoundLeavesTheSceneAlone)
{
    Scene s;
    addHeightfield(s, {.cells = 32});
    const Scene input = s;
    for (double bound : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        const SimplificationStats stats = simplifyMeshes(s, all(s, bound), all(s, 1.0), kQuiet, 1);
        EXPECT_EQ(stats.trianglesOut, stats.trianglesIn) << bound;
        EXPECT_EQ(s.indices, input.indices) << bound;
    }
    const SimplificationStats off = simplifyScene(s, 0.0, 1.0, kQuiet, 1);
    EXPECT_EQ(off.boundPx, 0.0);
    EXPECT_EQ(s.indices, input.indices);
}

// ---- Seams, borders, material boundaries --------------------------------------------

TEST(Simplification, UvSeamVerticesAllStayWithTheirOwnUvs)
{
    // A flat grid: without the lock, everything but the corners could go.
    Scene s;
    addHeightfield(s, {.cells = 40, .uvSeam = true});
    const Scene input = s;
    std::vector<uint32_t> seam; // both copies of every seam vertex
    for (uint32_t v = 0; v < input.vertices.size(); ++v)
        for (uint32_t w = 0; w < input.vertices.size(); ++w)
            if (v != w && input.vertices.positions[v] == input.vertices.positions[w])
                seam.push_back(v);
    ASSERT_EQ(seam.size(), 2u * 41u);

    const SimplificationStats stats = simplifyMeshes(s, all(s, 0.01), all(s, 1.0), kQuiet, 1);
    EXPECT_LT(s.triangleCount(), input.triangleCount() / 5) << "the flat interior merges";
    EXPECT_EQ(stats.lockedSeamVertices, 2u * 41u);
    // Every seam vertex is still used, with its position and its own uv.
    std::set<std::pair<std::tuple<float, float, float>, std::pair<float, float>>> after;
    for (uint32_t i : s.indices) {
        const glm::vec3& p = s.vertices.positions[i];
        after.insert({{p.x, p.y, p.z}, {s.vertices.uvs[i].x, s.vertices.uvs[i].y}});
    }
    for (uint32_t v : seam) {
        const glm::vec3& p = input.vertices.positions[v];
        EXPECT_TRUE(after.count({{p.x, p.y, p.z}, {input.vertices.uvs[v].x, input.vertices.uvs[v].y}}))
            << "seam vertex at " << p.x << ", " << p.z << " uv " << input.vertices.uvs[v].x;
    }
    // No triangle reaches across the seam, and each side uses its own copies (uv.x > 1:
    // the right side's).
    const float seamX = 20.0f / 40.0f;
    for (size_t t = 0; t < s.triangleCount(); ++t) {
        bool left = false, right = false, leftCopy = false, rightCopy = false;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = s.indices[3 * t + k];
            const float x = s.vertices.positions[v].x;
            left |= x < seamX;
            right |= x > seamX;
            leftCopy |= x == seamX && s.vertices.uvs[v].x < 1.0f;
            rightCopy |= x == seamX && s.vertices.uvs[v].x > 1.0f;
        }
        EXPECT_FALSE(left && right) << "triangle " << t << " crosses the seam";
        EXPECT_FALSE(left && rightCopy) << "triangle " << t;
        EXPECT_FALSE(right && leftCopy) << "triangle " << t;
    }
}

TEST(Simplification, BordersStayWhereTheyAre)
{
    Scene s;
    addHeightfield(s, {.cells = 40});
    const Scene input = s;
    std::vector<glm::vec3> border;
    for (const glm::vec3& p : input.vertices.positions)
        if (p.x == 0.0f || p.z == 0.0f || p.x == 1.0f || p.z == 1.0f)
            border.push_back(p);
    ASSERT_EQ(border.size(), 4u * 40u);
    simplifyMeshes(s, all(s, 0.01), all(s, 1.0), kQuiet, 1);
    EXPECT_LT(s.triangleCount(), input.triangleCount() / 5);
    EXPECT_EQ(countAt(s, usedVertices(s, 0), border), border.size()) << "a border vertex was merged away";
}

TEST(Simplification, MaterialBoundariesStayWhereTheyAre)
{
    // Two primitives on one vertex grid, materials 0 (left 15 columns) and 1 (the rest):
    // the column they share is each one's border.
    Scene s;
    addHeightfield(s, {.cells = 40, .splitColumn = 15});
    const Scene input = s;
    ASSERT_EQ(s.primitives.size(), 2u);
    std::vector<glm::vec3> boundary;
    for (const glm::vec3& p : input.vertices.positions)
        if (p.x == 15.0f / 40.0f)
            boundary.push_back(p);
    ASSERT_EQ(boundary.size(), 41u);
    simplifyMeshes(s, all(s, 0.01), all(s, 1.0), kQuiet, 2);
    for (uint32_t p = 0; p < 2; ++p) {
        EXPECT_EQ(s.primitives[p].material, int32_t(p));
        EXPECT_LT(s.primitives[p].indexCount, input.primitives[p].indexCount / 3) << "primitive " << p;
        EXPECT_EQ(countAt(s, usedVertices(s, p), boundary), boundary.size()) << "primitive " << p;
    }
    // The two sides still meet in the same vertices (no crack along the boundary).
    std::set<uint32_t> shared;
    const std::set<uint32_t> left = usedVertices(s, 0), right = usedVertices(s, 1);
    std::set_intersection(left.begin(), left.end(), right.begin(), right.end(), std::inserter(shared, shared.end()));
    EXPECT_EQ(shared.size(), boundary.size());
}

// ---- Skinned meshes, instances ------------------------------------------------------------

TEST(Simplification, SkinnedMeshesAreLeftWholeWithANote)
{
    Scene s = test::skinnedArmScene(41);
    const Scene input = s;
    const SimplificationStats stats = simplifyMeshes(s, all(s, 1.0), all(s, 1.0), kQuiet, 2);
    ASSERT_EQ(stats.meshes.size(), 2u);
    EXPECT_TRUE(stats.meshes[0].leftWhole.empty()) << "the static floor";
    EXPECT_NE(stats.meshes[1].leftWhole.find("skinned"), std::string::npos);
    EXPECT_EQ(stats.meshes[1].trianglesOut, stats.meshes[1].trianglesIn);
    EXPECT_EQ(s.indices, input.indices);
    EXPECT_EQ(s.deformers[0].firstVertex, input.deformers[0].firstVertex);
    EXPECT_EQ(s.vertices.deform.weights.size(), input.vertices.deform.weights.size());
}

TEST(Simplification, InstancedMeshesAreSimplifiedForTheirLargestScale)
{
    // One mesh drawn by one node at scale 1, then also by one at scale 8: the bound in
    // object units is 8 times finer, so more triangles stay, and the error in view pixels
    // (measured at scale 8) stays within the bound.
    auto bake = [](bool large) {
        Scene s;
        addHeightfield(s, {.cells = 120, .amplitude = 0.05f});
        Node node;
        node.mesh = 0;
        s.nodes.push_back(node);
        if (large) {
            node.scale = glm::vec3(8.0f);
            s.nodes.push_back(node);
        }
        const SimplificationStats stats = simplifyScene(s, 0.5, 1e-3, kQuiet, 1); // 1 view pixel = 1e-3 units
        EXPECT_LE(stats.maxErrorPx, 0.5);
        EXPECT_GT(stats.maxErrorPx, 0.05);
        return s.triangleCount();
    };
    const size_t small = bake(false), large = bake(true);
    EXPECT_GT(large, 2 * small);
}

// ---- Threads --------------------------------------------------------------------------------

TEST(Simplification, SameResultForAnyThreadCount)
{
    auto bake = [](unsigned threads) {
        Scene s;
        for (uint32_t m = 0; m < 6; ++m)
            addHeightfield(s, {.cells = 60 + 10 * m,
                               .amplitude = 0.02f * float(m + 1),
                               .origin = {2.0f * float(m), 0.0f, 0.0f},
                               .uvSeam = m % 2 == 0,
                               .splitColumn = m % 3 == 0 ? 20u : 0u});
        simplifyMeshes(s, all(s, 2e-3), all(s, 1.0), kQuiet, threads);
        return s;
    };
    const Scene one = bake(1);
    for (unsigned threads : {2u, 3u, 8u}) {
        const Scene many = bake(threads);
        EXPECT_EQ(many.indices, one.indices) << threads;
        ASSERT_EQ(many.vertices.size(), one.vertices.size()) << threads;
        EXPECT_EQ(0, std::memcmp(many.vertices.positions.data(), one.vertices.positions.data(),
                                 one.vertices.size() * sizeof(glm::vec3)));
        EXPECT_EQ(0, std::memcmp(many.vertices.uvs.data(), one.vertices.uvs.data(),
                                 one.vertices.size() * sizeof(glm::vec2)));
        for (size_t p = 0; p < one.primitives.size(); ++p) {
            EXPECT_EQ(many.primitives[p].firstIndex, one.primitives[p].firstIndex);
            EXPECT_EQ(many.primitives[p].indexCount, one.primitives[p].indexCount);
        }
    }
}

} // namespace
} // namespace lfd::bake
