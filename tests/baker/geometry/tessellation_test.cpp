// Tessellation stage: the bound holds, area and uv area are preserved, closed meshes stay
// closed (OpenMesh) with no T-junctions across UV/normal seams, attributes are
// interpolated, small triangles are untouched, instance scale is respected; an edge is
// cut into ceil(length / bound) pieces; face patterns cover their face; new points lie on
// OpenSubdiv's bilinear surface, and a mesh OpenSubdiv refuses is split all the same.

#include "bake_log.h"
#include "scene_bounds.h"
#include "face_pattern.h"
#include "tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <tuple>

namespace lfd::bake {
namespace {

// ---- Scene building -------------------------------------------------------------------

struct Vertex {
    glm::vec3 position;
    glm::vec2 uv{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
};

// Appends one primitive (own vertices) to the scene; returns its index.
uint32_t addPrimitive(Scene& scene, const std::vector<Vertex>& vertices,
                      const std::vector<uint32_t>& triangles, int32_t material = kNone)
{
    const auto base = uint32_t(scene.vertices.positions.size());
    for (const Vertex& v : vertices) {
        scene.vertices.positions.push_back(v.position);
        scene.vertices.uvs.push_back(v.uv);
        scene.vertices.normals.push_back(v.normal);
        scene.vertices.tangents.push_back(v.tangent);
    }
    Primitive prim;
    prim.firstIndex = uint32_t(scene.indices.size());
    prim.indexCount = uint32_t(triangles.size());
    prim.material = material;
    for (uint32_t i : triangles)
        scene.indices.push_back(base + i);
    scene.primitives.push_back(prim);
    return uint32_t(scene.primitives.size() - 1);
}

// Adds a mesh over the last primitiveCount primitives and a node with the given scale.
void addMesh(Scene& scene, const std::string& name, uint32_t primitiveCount, float nodeScale = 1.0f)
{
    Mesh mesh;
    mesh.name = name;
    mesh.primitiveCount = primitiveCount;
    mesh.firstPrimitive = uint32_t(scene.primitives.size()) - primitiveCount;
    scene.meshes.push_back(mesh);
    if (nodeScale > 0.0f) {
        Node node;
        node.name = name;
        node.mesh = int32_t(scene.meshes.size() - 1);
        node.scale = glm::vec3(nodeScale);
        scene.nodes.push_back(node);
    }
}

// Unit quad in the xy plane with uv = (x, y).
std::vector<Vertex> quadVertices(glm::vec2 origin = {0, 0}, float size = 1.0f)
{
    std::vector<Vertex> v;
    for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
        const glm::vec2 p = origin + c * size;
        v.push_back({glm::vec3(p, 0.0f), p});
    }
    return v;
}

Scene quadScene()
{
    Scene scene;
    addPrimitive(scene, quadVertices(), {0, 1, 2, 0, 2, 3});
    addMesh(scene, "quad", 1);
    return scene;
}

// Unit cube centred at the origin as glTF stores it: 24 vertices, every face with its
// own uvs, normals and tangents (seams along all 12 edges), outward winding.
Scene cubeScene()
{
    Scene scene;
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    // (normal, u axis, v axis) with u x v = normal
    const std::array<std::array<glm::vec3, 3>, 6> faces = {{
        {X, Y, Z}, {-X, Z, Y}, {Y, Z, X}, {-Y, X, Z}, {Z, X, Y}, {-Z, Y, X}}};
    std::vector<Vertex> vertices;
    std::vector<uint32_t> triangles;
    for (const auto& [n, u, v] : faces) {
        const auto base = uint32_t(vertices.size());
        for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
            vertices.push_back({0.5f * n + (c.x - 0.5f) * u + (c.y - 0.5f) * v, c, n, glm::vec4(u, 1.0f)});
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
            triangles.push_back(base + i);
    }
    addPrimitive(scene, vertices, triangles);
    addMesh(scene, "cube", 1);
    return scene;
}

// Closed torus grid with jittered tube radii: a random closed 2-manifold, 2 * n * n
// triangles. As glTF exporters do, the uv seams along i = n and j = n get their own
// vertices (bit-identical positions, uv = 1 instead of 0).
Scene jitteredTorus(uint32_t n, uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
    std::vector<float> radius(size_t(n) * n);
    for (float& r : radius)
        r = 1.0f + jitter(rng);
    std::vector<Vertex> vertices;
    for (uint32_t i = 0; i <= n; ++i)
        for (uint32_t j = 0; j <= n; ++j) {
            const uint32_t iw = i % n, jw = j % n; // the seam repeats the first row/column
            constexpr float twoPi = 2.0f * std::numbers::pi_v<float>;
            const float a = twoPi * float(iw) / float(n), b = twoPi * float(jw) / float(n);
            const float r = radius[size_t(iw) * n + jw];
            const float ring = 3.0f + r * std::cos(b);
            Vertex v;
            v.position = {ring * std::cos(a), ring * std::sin(a), r * std::sin(b)};
            v.normal = glm::normalize(glm::vec3(std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b)));
            v.uv = {float(i) / float(n), float(j) / float(n)};
            vertices.push_back(v);
        }
    std::vector<uint32_t> triangles;
    triangles.reserve(size_t(n) * n * 6);
    auto at = [n](uint32_t i, uint32_t j) { return i * (n + 1) + j; };
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = 0; j < n; ++j) {
            const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            triangles.insert(triangles.end(), {a, b, c, a, c, d});
        }
    Scene scene;
    addPrimitive(scene, vertices, triangles);
    addMesh(scene, "torus", 1);
    return scene;
}

// ---- Measurements ---------------------------------------------------------------------

glm::dvec3 pos(const Scene& s, uint32_t i) { return glm::dvec3(s.vertices.positions[i]); }

double longestEdge(const Scene& s)
{
    double longest = 0.0;
    for (size_t t = 0; t < s.triangleCount(); ++t)
        for (int e = 0; e < 3; ++e)
            longest = std::max(longest, glm::length(pos(s, s.indices[3 * t + e]) - pos(s, s.indices[3 * t + (e + 1) % 3])));
    return longest;
}

glm::dvec3 triangleCross(const Scene& s, size_t t)
{
    const glm::dvec3 a = pos(s, s.indices[3 * t]), b = pos(s, s.indices[3 * t + 1]), c = pos(s, s.indices[3 * t + 2]);
    return glm::cross(b - a, c - a);
}

double worldArea(const Scene& s)
{
    double area = 0.0;
    for (size_t t = 0; t < s.triangleCount(); ++t)
        area += 0.5 * glm::length(triangleCross(s, t));
    return area;
}

double uvArea(const Scene& s)
{
    double area = 0.0;
    for (size_t t = 0; t < s.triangleCount(); ++t) {
        const glm::dvec2 a(s.vertices.uvs[s.indices[3 * t]]), b(s.vertices.uvs[s.indices[3 * t + 1]]),
            c(s.vertices.uvs[s.indices[3 * t + 2]]);
        area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    return area;
}

// Streams have one length, nothing is NaN, normals and tangent directions are unit.
void expectSaneStreams(const Scene& s)
{
    const VertexStreams& v = s.vertices;
    ASSERT_EQ(v.normals.size(), v.positions.size());
    ASSERT_EQ(v.tangents.size(), v.positions.size());
    ASSERT_EQ(v.uvs.size(), v.positions.size());
    for (size_t i = 0; i < v.positions.size(); ++i) {
        ASSERT_TRUE(std::isfinite(v.positions[i].x) && std::isfinite(v.positions[i].y) && std::isfinite(v.positions[i].z)) << i;
        ASSERT_TRUE(std::isfinite(v.uvs[i].x) && std::isfinite(v.uvs[i].y)) << i;
        ASSERT_NEAR(glm::length(v.normals[i]), 1.0f, 1e-5f) << i;
        ASSERT_NEAR(glm::length(glm::vec3(v.tangents[i])), 1.0f, 1e-5f) << i;
        ASSERT_EQ(std::abs(v.tangents[i].w), 1.0f) << i;
    }
}

// Primitives keep their order, are back to back and cover the whole index buffer.
void expectConsistentRanges(const Scene& s)
{
    uint32_t next = 0;
    for (const Primitive& prim : s.primitives) {
        EXPECT_EQ(prim.firstIndex, next);
        EXPECT_EQ(prim.indexCount % 3, 0u);
        next = prim.firstIndex + prim.indexCount;
    }
    EXPECT_EQ(next, s.indices.size());
    for (uint32_t i : s.indices)
        ASSERT_LT(i, s.vertices.size());
}

// Welded positions that lie strictly inside an edge of some triangle: T-junctions
// (a vertex on one side of an edge that the other side does not have).
size_t countTJunctions(const Scene& s)
{
    std::set<std::tuple<float, float, float>> unique;
    for (const glm::vec3& p : s.vertices.positions)
        unique.insert({p.x, p.y, p.z});
    std::set<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>> edges;
    for (size_t t = 0; t < s.triangleCount(); ++t)
        for (int e = 0; e < 3; ++e) {
            const glm::vec3 a = s.vertices.positions[s.indices[3 * t + e]];
            const glm::vec3 b = s.vertices.positions[s.indices[3 * t + (e + 1) % 3]];
            auto ka = std::make_tuple(a.x, a.y, a.z), kb = std::make_tuple(b.x, b.y, b.z);
            edges.insert({std::min(ka, kb), std::max(ka, kb)});
        }
    size_t count = 0;
    for (const auto& [ka, kb] : edges) {
        const glm::dvec3 a(std::get<0>(ka), std::get<1>(ka), std::get<2>(ka));
        const glm::dvec3 b(std::get<0>(kb), std::get<1>(kb), std::get<2>(kb));
        const glm::dvec3 ab = b - a;
        const double length2 = glm::dot(ab, ab);
        if (length2 == 0.0)
            continue;
        for (const auto& kq : unique) {
            const glm::dvec3 q(std::get<0>(kq), std::get<1>(kq), std::get<2>(kq));
            const double t = glm::dot(q - a, ab) / length2;
            if (t <= 1e-6 || t >= 1.0 - 1e-6)
                continue;
            if (glm::length(q - (a + t * ab)) < 1e-6)
                ++count;
        }
    }
    return count;
}

std::vector<double> bounds(const Scene& s, double bound) { return std::vector<double>(s.meshes.size(), bound); }
std::vector<float> unitScales(const Scene& s) { return std::vector<float>(s.meshes.size(), 1.0f); }

// ---- Tests ----------------------------------------------------------------------------

TEST(Tessellation, QuadMeetsBoundAndPreservesArea)
{
    Scene scene = quadScene();
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 0.3), unitScales(scene), Log{});

    EXPECT_LE(longestEdge(scene), 0.3);
    EXPECT_NEAR(worldArea(scene), 1.0, 1e-5);
    EXPECT_NEAR(uvArea(scene), 1.0, 1e-5);
    EXPECT_EQ(stats.trianglesIn, 2u);
    EXPECT_EQ(stats.trianglesSplit, 2u);
    EXPECT_EQ(stats.trianglesOut, scene.triangleCount());
    EXPECT_GT(stats.trianglesOut, 2u * 16u); // edges of 1 need 4 segments: at least 16x
    EXPECT_NEAR(stats.maxEdgeWorldBefore, std::sqrt(2.0), 1e-6);
    EXPECT_DOUBLE_EQ(stats.maxEdgeWorldAfter, longestEdge(scene));
    expectSaneStreams(scene);
    expectConsistentRanges(scene);
    // Winding kept: every triangle still faces +z.
    for (size_t t = 0; t < scene.triangleCount(); ++t)
        EXPECT_GT(triangleCross(scene, t).z, 0.0) << t;
}

TEST(Tessellation, InterpolatesAttributes)
{
    Scene scene = quadScene();
    scene.vertices.tangents.assign(4, glm::vec4(1, 0, 0, -1)); // handedness must survive
    tessellateMeshes(scene, bounds(scene, 0.2), unitScales(scene), Log{});
    ASSERT_GT(scene.vertices.size(), 4u);
    for (size_t i = 0; i < scene.vertices.size(); ++i) {
        const glm::vec3 p = scene.vertices.positions[i];
        EXPECT_NEAR(scene.vertices.uvs[i].x, p.x, 1e-6f) << i; // uv = (x, y) is linear
        EXPECT_NEAR(scene.vertices.uvs[i].y, p.y, 1e-6f) << i;
        EXPECT_EQ(p.z, 0.0f);
        EXPECT_NEAR(glm::length(scene.vertices.normals[i] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
        EXPECT_EQ(scene.vertices.tangents[i], glm::vec4(1, 0, 0, -1));
    }
    // Edge points are shared: no two vertices of this seamless quad sit at one position.
    std::set<std::tuple<float, float, float>> unique;
    for (const glm::vec3& p : scene.vertices.positions)
        unique.insert({p.x, p.y, p.z});
    EXPECT_EQ(unique.size(), scene.vertices.size());
}

TEST(Tessellation, RenormalisesInterpolatedNormals)
{
    // A bent strip: two corners lean left, two lean right; new normals must be unit length.
    Scene scene;
    std::vector<Vertex> v = quadVertices({0, 0}, 4.0f);
    v[0].normal = v[3].normal = glm::normalize(glm::vec3(-1, 0, 1));
    v[1].normal = v[2].normal = glm::normalize(glm::vec3(1, 0, 1));
    addPrimitive(scene, v, {0, 1, 2, 0, 2, 3});
    addMesh(scene, "bent", 1);
    tessellateMeshes(scene, bounds(scene, 1.0), unitScales(scene), Log{});
    expectSaneStreams(scene);
}

TEST(Tessellation, CubeWithSeamsStaysWatertight)
{
    Scene scene = cubeScene();
    const MeshTopology before = meshTopology(scene, 0);
    ASSERT_TRUE(before.closedManifold()); // welding closes the seams of the input
    EXPECT_EQ(before.weldedVertices, 8u);

    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 0.3), unitScales(scene), Log{});
    EXPECT_EQ(stats.trianglesSplit, 12u);
    EXPECT_LE(longestEdge(scene), 0.3);
    EXPECT_NEAR(worldArea(scene), 6.0, 6e-5);
    EXPECT_NEAR(uvArea(scene), 6.0, 6e-5);
    expectSaneStreams(scene);
    expectConsistentRanges(scene);

    const MeshTopology after = meshTopology(scene, 0);
    EXPECT_TRUE(after.closedManifold());
    EXPECT_EQ(after.boundaryEdges, 0u);
    EXPECT_EQ(after.rejectedFaces, 0u);
    EXPECT_EQ(after.degenerateFaces, 0u);
    EXPECT_EQ(after.faces, scene.triangleCount());
    // Euler characteristic of a sphere: V - E + F = 2 with E = 3F / 2.
    EXPECT_EQ(int64_t(after.weldedVertices) - int64_t(after.faces) / 2, 2);
    EXPECT_EQ(countTJunctions(scene), 0u);

    // Every side of a seam kept its own attributes: all corners of a triangle carry the
    // face normal, and uv follows the face's own parametrisation of the position.
    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        const glm::vec3 n = scene.vertices.normals[scene.indices[3 * t]];
        const glm::vec3 u = glm::vec3(scene.vertices.tangents[scene.indices[3 * t]]);
        const glm::vec3 v = glm::cross(n, u);
        EXPECT_GT(glm::dot(glm::vec3(triangleCross(scene, t)), n), 0.0f) << t; // outward
        for (int c = 0; c < 3; ++c) {
            const uint32_t i = scene.indices[3 * t + c];
            ASSERT_EQ(scene.vertices.normals[i], n) << t;
            const glm::vec3 corner00 = 0.5f * n - 0.5f * u - 0.5f * v;
            const glm::vec3 d = scene.vertices.positions[i] - corner00;
            EXPECT_NEAR(scene.vertices.uvs[i].x, glm::dot(d, u), 1e-6f) << t;
            EXPECT_NEAR(scene.vertices.uvs[i].y, glm::dot(d, v), 1e-6f) << t;
        }
    }
}

TEST(Tessellation, CrackCheckersDetectACrack)
{
    // Guard for the checks above: a square cut into 3 triangles with a T-junction at
    // (1, 0.5), then closed by a mirrored copy so that only the T-junction is open.
    Scene scene;
    std::vector<Vertex> v(5);
    v[0].position = {0, 0, 0};
    v[1].position = {1, 0, 0};
    v[2].position = {1, 1, 0};
    v[3].position = {0, 1, 0};
    v[4].position = {1, 0.5f, 0};
    addPrimitive(scene, v, {0, 1, 4, 0, 4, 2, 0, 2, 3, /* back: no vertex 4 */ 0, 2, 1, 0, 3, 2});
    addMesh(scene, "cracked", 1);
    EXPECT_EQ(countTJunctions(scene), 1u);
    EXPECT_FALSE(meshTopology(scene, 0).closedManifold());
    EXPECT_GT(countBoundaryEdges(scene, 0), 0u);
}

TEST(Tessellation, OnlyOversizedTrianglesAreTouched)
{
    // One big triangle, a sliver across its long edge (shares that oversized edge, so it
    // must split too, or it would leave a T-junction), a small triangle touching it at a corner only, and a far strip of
    // tiny triangles. Bound 1.
    Scene scene;
    std::vector<Vertex> v;
    for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(4, 0, 0), glm::vec3(0, 4, 0), // big
                        glm::vec3(2.01f, 2.01f, 0),                                  // sliver apex
                        glm::vec3(-0.5f, 0, 0), glm::vec3(0, -0.5f, 0)})             // corner touch
        v.push_back({p, glm::vec2(p) * 0.25f});
    std::vector<uint32_t> tris = {0, 1, 2, 1, 3, 2, 0, 4, 5};
    for (uint32_t k = 0; k < 10; ++k) {
        const auto base = uint32_t(v.size());
        const float x = 10.0f + 0.2f * float(k); // disjoint from each other
        for (glm::vec3 p : {glm::vec3(x, 0, 0), glm::vec3(x + 0.1f, 0, 0), glm::vec3(x, 0.1f, 0)})
            v.push_back({p, glm::vec2(p) * 0.25f});
        tris.insert(tris.end(), {base, base + 1, base + 2});
    }
    addPrimitive(scene, v, tris);
    addMesh(scene, "mixed", 1);
    ASSERT_EQ(countTJunctions(scene), 0u);
    const std::vector<uint32_t> original = scene.indices;
    const size_t originalVertices = scene.vertices.size();

    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 1.0), unitScales(scene), Log{});
    EXPECT_EQ(stats.trianglesSplit, 2u); // the big one and the sliver
    EXPECT_LE(longestEdge(scene), 1.0);
    EXPECT_EQ(countTJunctions(scene), 0u);

    // The 11 small triangles appear verbatim (same vertex indices, same order).
    std::multiset<std::array<uint32_t, 3>> out;
    for (size_t t = 0; t < scene.triangleCount(); ++t)
        out.insert({scene.indices[3 * t], scene.indices[3 * t + 1], scene.indices[3 * t + 2]});
    size_t untouched = 0;
    for (size_t t = 2; t < original.size() / 3; ++t)
        untouched += out.count({original[3 * t], original[3 * t + 1], original[3 * t + 2]});
    EXPECT_EQ(untouched, 11u);
    // Exactly those use original vertices only; everything else is new pieces.
    size_t originalOnly = 0;
    for (const auto& tri : out)
        originalOnly += (tri[0] < originalVertices && tri[1] < originalVertices && tri[2] < originalVertices) ? 1 : 0;
    EXPECT_EQ(originalOnly, 11u);
}

TEST(Tessellation, UntouchedWhenWithinBound)
{
    Scene scene = cubeScene();
    const Scene before = scene;
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 1.5), unitScales(scene), Log{});
    EXPECT_EQ(stats.trianglesSplit, 0u);
    EXPECT_EQ(stats.trianglesOut, 12u);
    EXPECT_EQ(scene.indices, before.indices);
    EXPECT_EQ(scene.vertices.positions, before.vertices.positions);
    EXPECT_NEAR(stats.maxEdgeWorldBefore, std::sqrt(2.0), 1e-6);
    EXPECT_DOUBLE_EQ(stats.maxEdgeWorldAfter, stats.maxEdgeWorldBefore);
}

TEST(Tessellation, DegenerateTrianglesAreSplitWithoutNaNs)
{
    // Collinear corners and a repeated corner: zero area, long edges.
    Scene scene;
    std::vector<Vertex> v(5);
    v[0].position = {0, 0, 0};
    v[1].position = {4, 0, 0};
    v[2].position = {2, 0, 0};
    v[3].position = {0, 3, 0};
    v[4].position = {0, 3, 0}; // same position as 3, another vertex
    v[0].normal = {0, 0, 1};
    v[1].normal = {0, 0, -1}; // opposite normals: the sum is zero
    addPrimitive(scene, v, {0, 1, 2, 0, 3, 4});
    addMesh(scene, "flat", 1);
    tessellateMeshes(scene, bounds(scene, 0.7), unitScales(scene), Log{});
    EXPECT_LE(longestEdge(scene), 0.7);
    EXPECT_EQ(worldArea(scene), 0.0);
    expectSaneStreams(scene);
}

TEST(Tessellation, PrimitiveRangesStayInOrder)
{
    // Mesh a: two primitives (x in [0,2] and [3,5]); mesh b: one primitive (x in [6,8]).
    // Primitive 1 is within the bound, 0 and 2 are not.
    Scene scene;
    addPrimitive(scene, quadVertices({0, 0}, 2.0f), {0, 1, 2, 0, 2, 3}, 0);
    addPrimitive(scene, quadVertices({3, 0}, 0.5f), {0, 1, 2, 0, 2, 3}, 1);
    addMesh(scene, "a", 2);
    addPrimitive(scene, quadVertices({6, 0}, 2.0f), {0, 1, 2, 0, 2, 3}, 2);
    addMesh(scene, "b", 1);
    tessellateMeshes(scene, bounds(scene, 0.8), unitScales(scene), Log{});

    expectConsistentRanges(scene);
    ASSERT_EQ(scene.primitives.size(), 3u);
    EXPECT_EQ(scene.primitives[1].indexCount, 6u);
    const float xMin[3] = {0, 3, 6}, xMax[3] = {2, 3.5f, 8};
    for (size_t p = 0; p < 3; ++p) {
        EXPECT_EQ(scene.primitives[p].material, int32_t(p));
        const Primitive& prim = scene.primitives[p];
        for (uint32_t i = prim.firstIndex; i < prim.firstIndex + prim.indexCount; ++i) {
            EXPECT_GE(scene.vertices.positions[scene.indices[i]].x, xMin[p]) << p;
            EXPECT_LE(scene.vertices.positions[scene.indices[i]].x, xMax[p]) << p;
        }
    }
    EXPECT_LE(longestEdge(scene), 0.8);
}

TEST(Tessellation, PerMeshBoundsAndScales)
{
    // Same quad twice: mesh 0 bound 0.5, mesh 1 left alone (infinite bound).
    Scene scene;
    addPrimitive(scene, quadVertices(), {0, 1, 2, 0, 2, 3});
    addMesh(scene, "split", 1);
    addPrimitive(scene, quadVertices({2, 0}), {0, 1, 2, 0, 2, 3});
    addMesh(scene, "kept", 1);
    const TessellationStats stats = tessellateMeshes(
        scene, {0.5, std::numeric_limits<double>::infinity()}, {2.0f, 1.0f}, Log{});
    EXPECT_EQ(scene.primitives[1].indexCount, 6u);
    EXPECT_NEAR(stats.maxEdgeWorldBefore, 2.0 * std::sqrt(2.0), 1e-5); // scaled by mesh 0
    // Mesh 0 ends at <= 0.5 * 2 = 1; mesh 1's untouched diagonal (sqrt 2) is the longest.
    EXPECT_NEAR(stats.maxEdgeWorldAfter, std::sqrt(2.0), 1e-6);
}

TEST(Tessellation, RespectsInstanceScale)
{
    // The quad is instanced at scale 1 and 2: the 2x instance decides, so the
    // object-space bound is 1 / 2.
    Scene scene = quadScene();
    Node twice;
    twice.mesh = 0;
    twice.scale = glm::vec3(2.0f);
    scene.nodes.push_back(twice);
    // A mesh no node uses stays as it is.
    addPrimitive(scene, quadVertices({5, 0}, 3.0f), {0, 1, 2, 0, 2, 3});
    addMesh(scene, "unused", 1, 0.0f);
    ASSERT_EQ(meshMaxWorldScale(scene), (std::vector<float>{2.0f, 0.0f}));

    const TessellationStats stats = tessellateScene(scene, 1.0, Log{});
    const Primitive& quad = scene.primitives[0];
    double longest = 0.0;
    for (uint32_t i = quad.firstIndex; i < quad.firstIndex + quad.indexCount; i += 3)
        for (int e = 0; e < 3; ++e)
            longest = std::max(longest, glm::length(pos(scene, scene.indices[i + e]) - pos(scene, scene.indices[i + (e + 1) % 3])));
    EXPECT_LE(longest, 0.5);
    EXPECT_GT(longest, 0.25); // not over-split: a scale-1 bound would be 1
    EXPECT_EQ(scene.primitives[1].indexCount, 6u);
    EXPECT_NEAR(stats.maxEdgeWorldBefore, 2.0 * std::sqrt(2.0), 1e-5);
    EXPECT_LE(stats.maxEdgeWorldAfter, 1.0);
}

TEST(Tessellation, RejectsBadInputWithoutChangingTheScene)
{
    Scene scene = quadScene();
    EXPECT_THROW(tessellateScene(scene, 0.0, Log{}), BakeError);
    EXPECT_THROW(tessellateScene(scene, -1.0, Log{}), BakeError);
    EXPECT_THROW(tessellateScene(scene, std::nan(""), Log{}), BakeError);

    Scene badIndex = quadScene();
    badIndex.indices[5] = 99;
    EXPECT_THROW(tessellateMeshes(badIndex, bounds(badIndex, 0.3), unitScales(badIndex), Log{}), BakeError);
    EXPECT_EQ(badIndex.vertices.size(), 4u);

    Scene badMesh = quadScene();
    badMesh.meshes[0].primitiveCount = 3;
    EXPECT_THROW(tessellateMeshes(badMesh, bounds(badMesh, 0.3), unitScales(badMesh), Log{}), BakeError);

    Scene overlapping = quadScene();
    overlapping.primitives.push_back({3, 3, kNone});
    overlapping.meshes[0].primitiveCount = 2;
    EXPECT_THROW(tessellateMeshes(overlapping, bounds(overlapping, 0.3), unitScales(overlapping), Log{}), BakeError);

    Scene mismatch = quadScene();
    EXPECT_THROW(tessellateMeshes(mismatch, {}, {}, Log{}), BakeError);
}

TEST(Tessellation, LogsPerMeshAndSummary)
{
    Scene scene = quadScene();
    std::vector<std::string> lines;
    Log log;
    log.info = [&](const std::string& line) { lines.push_back(line); };
    tessellateMeshes(scene, bounds(scene, 0.3), unitScales(scene), log);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NE(lines[0].find("mesh 'quad'"), std::string::npos) << lines[0];
    EXPECT_NE(lines[1].find("2 -> " + std::to_string(scene.triangleCount())), std::string::npos) << lines[1];
    EXPECT_NE(lines[1].find("bilinear surface of 1 meshes (refused: 0), split triangles placed by barycentric "
                            "weights instead: 0"),
              std::string::npos)
        << lines[1];
}

TEST(Tessellation, MixedSizesAcrossSeamsHaveNoTJunctions)
{
    // 1152 triangles; ring edges run from ~0.54 (inside) to ~1.03 (outside), tube edges
    // ~0.26: a bound of 0.7 splits the outer triangles and leaves the inner ones, so
    // split and unsplit triangles meet, also across the uv seams.
    Scene scene = jitteredTorus(24, 11);
    ASSERT_TRUE(meshTopology(scene, 0).closedManifold());
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 0.7), unitScales(scene), Log{});
    EXPECT_GT(stats.trianglesSplit, 0u);
    EXPECT_LT(stats.trianglesSplit, stats.trianglesIn);
    EXPECT_LE(longestEdge(scene), 0.7);
    EXPECT_NEAR(uvArea(scene), 1.0, 1e-5); // uv is interpolated linearly: the domain is kept
    expectSaneStreams(scene);
    EXPECT_TRUE(meshTopology(scene, 0).closedManifold());
    EXPECT_EQ(countTJunctions(scene), 0u);
}

TEST(Tessellation, LargeRandomClosedMeshStaysClosed)
{
    // 2 * 224^2 = 100352 triangles on a jittered torus (ring radius 3, tube ~1): ring
    // edges ~0.057 (inside) .. ~0.11 (outside), tube edges ~0.028; a bound of 0.08 splits
    // about half of them.
    Scene scene = jitteredTorus(224, 7);
    ASSERT_EQ(scene.triangleCount(), 100352u);
    const auto start = std::chrono::steady_clock::now();
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, 0.08), unitScales(scene), Log{});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ timing   ] tessellated %zu -> %zu triangles (%zu split) in %.3f s\n", stats.trianglesIn,
                stats.trianglesOut, stats.trianglesSplit, seconds);

    EXPECT_GT(stats.trianglesSplit, stats.trianglesIn / 4);
    EXPECT_LT(stats.trianglesSplit, stats.trianglesIn);
    EXPECT_LE(longestEdge(scene), 0.08);
    expectConsistentRanges(scene);
    const MeshTopology topology = meshTopology(scene, 0);
    EXPECT_TRUE(topology.closedManifold());
    EXPECT_EQ(topology.boundaryEdges, 0u);
    EXPECT_EQ(topology.degenerateFaces, 0u);
    // Torus: Euler characteristic 0, so V = F / 2.
    EXPECT_EQ(topology.weldedVertices * 2, topology.faces);
}

TEST(Tessellation, EdgeOfKBoundsPlusEpsilonBecomesKPlusOnePieces)
{
    // A long edge on the x axis with its apex close by: the rate rule cuts the edge into
    // ceil(length / bound) = k + 1 pieces, not the next power of two (4 for k = 2).
    const double bound = 1.0;
    for (int k = 1; k <= 6; ++k) {
        const float length = float(k * bound) + 1e-3f;
        Scene scene;
        std::vector<Vertex> v(3);
        v[0].position = {0, 0, 0};
        v[1].position = {length, 0, 0};
        v[2].position = {0.5f * length, 0.3f, 0};
        addPrimitive(scene, v, {0, 1, 2});
        addMesh(scene, "long", 1);
        tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), Log{});
        std::set<float> onEdge;
        for (const glm::vec3& p : scene.vertices.positions)
            if (p.y == 0.0f && p.z == 0.0f)
                onEdge.insert(p.x);
        EXPECT_EQ(onEdge.size(), size_t(k + 2)) << "k = " << k; // k + 1 pieces
        // Equal pieces.
        float previous = 0.0f;
        for (float x : onEdge) {
            if (x > 0.0f) {
                EXPECT_NEAR(x - previous, length / float(k + 1), 1e-5f) << "k = " << k;
            }
            previous = x;
        }
        EXPECT_LE(longestEdge(scene), bound) << "k = " << k;
        EXPECT_NEAR(worldArea(scene), 0.15 * length, 1e-5) << "k = " << k;
    }
}

TEST(Tessellation, FacePatternsCoverTheFaceWithinTheBound)
{
    // Every pattern (OpenSubdiv's, bisected, or boundary-only) keeps the face's boundary
    // points, covers its area exactly once with its winding, and meets the bound; a
    // face with one edge cut in two becomes 2 triangles (Bfr alone would fan 4).
    const std::array<glm::vec3, 3> corners = {glm::vec3(0, 0, 0), glm::vec3(7.3f, 0.4f, 0), glm::vec3(2.1f, 5.2f, 0)};
    const double bound = 1.0;
    auto lerp = [&](int i, int k, int n) {
        const glm::dvec3 a(corners[size_t(i)]), b(corners[size_t(i + 1) % 3]);
        return glm::vec3(a + (b - a) * (double(k) / n));
    };
    const double faceArea = 0.5 * glm::length(glm::cross(glm::dvec3(corners[1] - corners[0]), glm::dvec3(corners[2] - corners[0])));
    std::array<int, 3> rates{};
    for (int i = 0; i < 3; ++i)
        rates[size_t(i)] = int(std::ceil(glm::length(glm::dvec3(corners[size_t(i + 1) % 3] - corners[size_t(i)])) / bound));
    std::vector<glm::vec3> boundary;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < rates[size_t(i)]; ++k)
            boundary.push_back(lerp(i, k, rates[size_t(i)]));
    ASSERT_EQ(boundary.size(), boundaryPointCount(rates));

    const FacePattern pattern = facePattern(corners, rates, boundary, bound);
    std::vector<glm::vec3> points = boundary;
    for (const glm::dvec3& w : pattern.interiorWeights) {
        EXPECT_NEAR(w.x + w.y + w.z, 1.0, 1e-12);
        points.push_back(interiorPosition(corners, w));
    }
    double area = 0.0;
    std::set<int> used;
    for (size_t f = 0; f < pattern.facets.size(); f += 3) {
        const glm::dvec3 a(points[size_t(pattern.facets[f])]), b(points[size_t(pattern.facets[f + 1])]),
            c(points[size_t(pattern.facets[f + 2])]);
        const double z = glm::cross(b - a, c - a).z;
        EXPECT_GT(z, 0.0) << f; // winding kept, nothing degenerate
        area += 0.5 * z;
        for (int e = 0; e < 3; ++e) {
            used.insert(pattern.facets[f + size_t(e)]);
            EXPECT_LE(glm::length(glm::dvec3(points[size_t(pattern.facets[f + size_t(e)])]) -
                                  glm::dvec3(points[size_t(pattern.facets[f + size_t(e + 1) % 3])])),
                      bound);
        }
    }
    EXPECT_NEAR(area, faceArea, 1e-4);
    EXPECT_EQ(used.size(), points.size()); // every boundary point is a corner of some piece
    EXPECT_LE(pattern.longestEdge, bound);

    // Rates 2, 1, 1 on a face whose other edges fit: 2 triangles, no interior point.
    const std::array<glm::vec3, 3> small = {glm::vec3(0, 0, 0), glm::vec3(1.6f, 0, 0), glm::vec3(0.8f, 0.5f, 0)};
    const std::vector<glm::vec3> smallBoundary = {small[0], glm::vec3(0.8f, 0, 0), small[1], small[2]};
    const FacePattern halves = facePattern(small, {2, 1, 1}, smallBoundary, bound);
    EXPECT_EQ(halves.facets.size(), 6u);
    EXPECT_TRUE(halves.interiorWeights.empty());
    // A uniform equilateral face of rate 3 takes OpenSubdiv's n^2 pattern.
    const float s = 2.7f;
    const std::array<glm::vec3, 3> equilateral = {glm::vec3(0, 0, 0), glm::vec3(s, 0, 0),
                                                  glm::vec3(0.5f * s, s * std::sqrt(3.0f) / 2.0f, 0)};
    std::vector<glm::vec3> equilateralBoundary;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            equilateralBoundary.push_back(glm::mix(equilateral[size_t(i)], equilateral[size_t(i + 1) % 3], float(k) / 3.0f));
    const FacePattern uniform = facePattern(equilateral, {3, 3, 3}, equilateralBoundary, bound);
    EXPECT_EQ(uniform.facets.size(), 9u * 3u);
    EXPECT_TRUE(uniform.fromOpenSubdiv);
    EXPECT_LE(uniform.longestEdge, bound);
}

TEST(Tessellation, CubeStaysWatertightAtEveryRate)
{
    // Cube edges 1 and face diagonals sqrt 2 at bounds that give rates 2..8 (never a power
    // of two for both): seams are closed bit for bit (OpenMesh welds exact positions).
    for (double bound : {0.9, 0.6, 0.45, 0.34, 0.21, 0.13}) {
        Scene scene = cubeScene();
        const TessellationStats stats = tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), Log{});
        EXPECT_EQ(stats.trianglesSplit, 12u) << bound;
        EXPECT_LE(longestEdge(scene), bound) << bound;
        EXPECT_NEAR(worldArea(scene), 6.0, 6e-5) << bound;
        EXPECT_NEAR(uvArea(scene), 6.0, 6e-5) << bound;
        expectSaneStreams(scene);
        const MeshTopology topology = meshTopology(scene, 0);
        EXPECT_TRUE(topology.closedManifold()) << bound;
        EXPECT_EQ(topology.degenerateFaces, 0u) << bound;
        EXPECT_EQ(int64_t(topology.weldedVertices) - int64_t(topology.faces) / 2, 2) << bound;
        EXPECT_EQ(countTJunctions(scene), 0u) << bound;
        // Reported means: every output edge, and the pieces of the split triangles (all here).
        double sum = 0.0;
        for (size_t t = 0; t < scene.triangleCount(); ++t)
            for (int e = 0; e < 3; ++e)
                sum += glm::length(pos(scene, scene.indices[3 * t + e]) - pos(scene, scene.indices[3 * t + (e + 1) % 3]));
        const double mean = sum / double(3 * scene.triangleCount());
        EXPECT_NEAR(stats.meanEdgeWorldAfter, mean, 1e-9) << bound;
        EXPECT_NEAR(stats.meanPieceEdgeWorld, mean, 1e-9) << bound;
        EXPECT_LE(stats.meanEdgeWorldAfter, bound);
    }
}

TEST(Tessellation, NewPointsLieOnTheBilinearSurfaceAcrossSeams)
{
    // The cube's faces have their own vertices (seams along every edge). Its new points
    // are evaluated on OpenSubdiv's bilinear surface of the welded cube (no fallback),
    // which is the flat faces: every vertex lies exactly (to the float) on a face plane,
    // and the cube stays closed.
    for (double bound : {0.6, 0.21, 0.07}) {
        Scene scene = cubeScene();
        const TessellationStats stats = tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), Log{});
        EXPECT_EQ(stats.surfaceMeshes, 1u);
        EXPECT_EQ(stats.surfaceMeshesRefused, 0u);
        EXPECT_EQ(stats.surfaceFallbacks, 0u);
        EXPECT_LE(longestEdge(scene), bound);
        EXPECT_EQ(countTJunctions(scene), 0u);
        EXPECT_TRUE(meshTopology(scene, 0).closedManifold());
        for (const glm::vec3& p : scene.vertices.positions)
            EXPECT_EQ(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 0.5f) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(Tessellation, AwkwardTopologyIsSplitOnTheSurface)
{
    // A closed cone of 64 large triangles around one apex (valence 64: the car sample's
    // wheel hubs have 48), a double-sided pair and an edge shared by three faces: every
    // split triangle gets its points from the bilinear surface, within the bound, on its
    // own plane.
    Scene scene;
    constexpr uint32_t kRim = 64;
    std::vector<Vertex> cone(1 + kRim);
    cone[0].position = {0.0f, 0.0f, 2.0f};
    for (uint32_t i = 0; i < kRim; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(kRim);
        cone[1 + i].position = {6.0f * std::cos(a), 6.0f * std::sin(a), 0.0f};
    }
    std::vector<uint32_t> triangles;
    for (uint32_t i = 0; i < kRim; ++i)
        triangles.insert(triangles.end(), {0u, 1 + i, 1 + (i + 1) % kRim});
    for (uint32_t i = 1; i + 1 < kRim; ++i) // the base, so that the cone is closed
        triangles.insert(triangles.end(), {1u, 2 + i, 1 + i});
    const auto base = uint32_t(cone.size());
    for (glm::vec3 p : {glm::vec3(10, 0, 0), glm::vec3(13, 0, 0.5f), glm::vec3(10.3f, 2.7f, -0.4f),
                        glm::vec3(11, -2.5f, 0.2f), glm::vec3(11, 0.3f, 2.8f)})
        cone.push_back({p});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 1u, 1u, 0u, 3u, 0u, 1u, 4u})
        triangles.push_back(base + i);
    addPrimitive(scene, cone, triangles);
    addMesh(scene, "awkward", 1);
    const Scene input = scene;
    const double bound = 0.5;
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), Log{});
    EXPECT_EQ(stats.trianglesSplit, input.triangleCount());
    EXPECT_EQ(stats.surfaceMeshes, 1u);
    EXPECT_EQ(stats.surfaceFallbacks, 0u);
    EXPECT_LE(longestEdge(scene), bound);
    EXPECT_NEAR(worldArea(scene), worldArea(input), 1e-4 * worldArea(input));
    expectSaneStreams(scene);
}

TEST(Tessellation, MeshOpenSubdivRefusesIsSplitByBarycentricWeightsAndCounted)
{
    // One mesh OpenSubdiv refuses (a fan whose centre has 65536 edges, past its valence
    // limit, beside one oversized triangle) and one it takes (the cube): the refused
    // mesh is still split within the bound, by barycentric weights, and counted.
    Scene scene;
    constexpr uint32_t kRim = 65536;
    std::vector<Vertex> fan(1 + kRim);
    for (uint32_t i = 0; i < kRim; ++i) {
        const double a = 2.0 * 3.14159265358979 * double(i) / kRim;
        fan[1 + i].position = {float(0.4 * std::cos(a)), float(0.4 * std::sin(a)), 0.0f};
    }
    std::vector<uint32_t> triangles;
    for (uint32_t i = 0; i < kRim; ++i)
        triangles.insert(triangles.end(), {0u, 1 + i, 1 + (i + 1) % kRim});
    fan.push_back({glm::vec3(10, 0, 0), glm::vec2(0, 0)});
    fan.push_back({glm::vec3(13, 0, 0), glm::vec2(1, 0)});
    fan.push_back({glm::vec3(10, 3, 0), glm::vec2(0, 1)});
    triangles.insert(triangles.end(), {kRim + 1, kRim + 2, kRim + 3});
    addPrimitive(scene, fan, triangles);
    addMesh(scene, "fan", 1);
    const Scene cube = cubeScene();
    std::vector<Vertex> cubeVertices(cube.vertices.positions.size());
    for (size_t i = 0; i < cubeVertices.size(); ++i)
        cubeVertices[i] = {cube.vertices.positions[i], cube.vertices.uvs[i], cube.vertices.normals[i],
                           cube.vertices.tangents[i]};
    addPrimitive(scene, cubeVertices, cube.indices);
    addMesh(scene, "cube", 1);
    const double areaBefore = worldArea(scene);

    std::vector<std::string> lines;
    Log log;
    log.info = [&](const std::string& s) { lines.push_back(s); };
    const double bound = 0.9;
    const TessellationStats stats = tessellateMeshes(scene, bounds(scene, bound), unitScales(scene), log);
    EXPECT_EQ(stats.surfaceMeshesRefused, 1u);
    EXPECT_EQ(stats.surfaceMeshes, 1u);
    EXPECT_EQ(stats.surfaceFallbacks, 1u); // the fan's big triangle
    EXPECT_EQ(stats.trianglesSplit, 13u);
    EXPECT_LE(longestEdge(scene), bound);
    EXPECT_NEAR(worldArea(scene), areaBefore, 1e-3);
    expectSaneStreams(scene);
    EXPECT_TRUE(meshTopology(scene, 1).closedManifold());
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const std::string& s) {
        return s.find("'fan': OpenSubdiv refused") != std::string::npos && s.find("valence") != std::string::npos;
    }));
}

} // namespace
} // namespace lfd::bake
