// OpenSubdiv's bilinear surface of a welded mesh (baker/geometry/bilinear_surface.h), on which the
// tessellation stage places new points: every face must evaluate to its own flat triangle
// - checked numerically rather than trusted, also at a vertex of high valence, on a
// non-manifold edge, in a double-sided pair and with two corners welded together - the
// barycentric <-> sub-face conversion must round-trip, the edge rule must be the surface
// along the edge, and OpenSubdiv's refusal of a mesh must be reported, not thrown.

#include "bilinear_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <random>
#include <vector>

namespace lfd::bake {
namespace {

struct TestMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> faces; // 3 welded ids per face
};

// Barycentric weights on a triangular grid of `steps` (corners and edges included), and
// random ones inside.
std::vector<glm::dvec3> sampleWeights(int steps, size_t random, uint32_t seed)
{
    std::vector<glm::dvec3> weights;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            const double u = double(i) / steps, v = double(j) / steps;
            weights.emplace_back(1.0 - u - v, u, v);
        }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (size_t k = 0; k < random; ++k) {
        double u = unit(rng), v = unit(rng);
        if (u + v > 1.0)
            u = 1.0 - u, v = 1.0 - v;
        weights.emplace_back(1.0 - u - v, u, v);
    }
    return weights;
}

// A bumpy, jittered grid with random diagonals (boundary and interior vertices of
// valence 2 to 8), then: a closed fan of 64 triangles around one vertex, a double-sided
// pair of faces with the same corners, an edge shared by three faces, and a face with
// two corners welded together.
TestMesh awkwardMesh()
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    TestMesh mesh;
    constexpr uint32_t n = 12;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i)
            mesh.positions.emplace_back(float(i) + jitter(rng), float(j) + jitter(rng),
                                        0.7f * std::sin(0.9f * float(i)) * std::cos(0.6f * float(j)) + jitter(rng));
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            if (rng() & 1)
                mesh.faces.insert(mesh.faces.end(), {a, b, d, a, d, c});
            else
                mesh.faces.insert(mesh.faces.end(), {a, b, c, b, d, c});
        }
    // The fan: a cone over a wavy rim, 64 faces at its apex (the car sample's wheel hubs
    // have 48, where Loop with sharp creases overran a heap buffer in OpenSubdiv 3.5).
    constexpr uint32_t kRim = 64;
    const auto apex = uint32_t(mesh.positions.size());
    mesh.positions.emplace_back(20.0f, 0.0f, 1.5f);
    for (uint32_t i = 0; i < kRim; ++i) {
        const double a = 2.0 * std::numbers::pi * double(i) / kRim;
        mesh.positions.emplace_back(float(20.0 + 3.0 * std::cos(a)), float(3.0 * std::sin(a)),
                                    float(0.4 * std::sin(5.0 * a)));
    }
    for (uint32_t i = 0; i < kRim; ++i)
        mesh.faces.insert(mesh.faces.end(), {apex, apex + 1 + i, apex + 1 + (i + 1) % kRim});
    // Double-sided pair, three faces on one edge, two corners welded together.
    const auto base = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{30, 0, 0}, {32, 0, 0.5f}, {30.3f, 1.7f, -0.4f}, {31, -1.5f, 0.2f},
                                                 {31, 0.3f, 1.8f}, {30.5f, 0.2f, -1.6f}});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 1u, 1u, 0u, 3u, 0u, 1u, 4u, 1u, 0u, 5u, 3u, 3u, 4u})
        mesh.faces.push_back(base + i);
    return mesh;
}

TEST(BilinearSurface, SubFaceCoordinatesRoundTrip)
{
    // Barycentric -> sub-face -> barycentric, over a grid (corners, edges, centroid and
    // the sub-face borders included) and random points; and the sub-face's own corners.
    double largest = 0.0;
    for (const glm::dvec3& w : sampleWeights(48, 20000, 3)) {
        const SubFaceCoord coord = subFaceCoord(w);
        ASSERT_GE(coord.st.x, 0.0);
        ASSERT_LE(coord.st.x, 1.0);
        ASSERT_GE(coord.st.y, 0.0);
        ASSERT_LE(coord.st.y, 1.0);
        const glm::dvec3 back = barycentricWeights(coord);
        largest = std::max({largest, std::abs(back.x - w.x), std::abs(back.y - w.y), std::abs(back.z - w.z)});
    }
    EXPECT_LT(largest, 1e-12);
    std::printf("largest round-trip error of a weight: %.3g\n", largest);
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 corner(0.0), mid(0.0), prevMid(0.0);
        corner[i] = 1.0;
        mid[i] = mid[(i + 1) % 3] = 0.5;
        prevMid[i] = prevMid[(i + 2) % 3] = 0.5;
        const glm::dvec3 centroid(1.0 / 3.0);
        auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-15; };
        EXPECT_TRUE(near(barycentricWeights({i, {0.0, 0.0}}), corner)) << i;
        EXPECT_TRUE(near(barycentricWeights({i, {1.0, 0.0}}), mid)) << i;
        EXPECT_TRUE(near(barycentricWeights({i, {1.0, 1.0}}), centroid)) << i;
        EXPECT_TRUE(near(barycentricWeights({i, {0.0, 1.0}}), prevMid)) << i;
        EXPECT_EQ(subFaceCoord(corner).subFace, i);
    }
}

TEST(BilinearSurface, EveryFaceIsItsFlatTriangle)
{
    // Barycentric weights -> sub-face coordinates -> Bfr::Surface::Evaluate must give
    // the barycentric combination of the face's corners, for every face of the awkward
    // mesh (measured: about 1e-15 of the face's size).
    const TestMesh mesh = awkwardMesh();
    const BilinearSurface surface(mesh.faces, mesh.positions);
    ASSERT_FALSE(surface.refused()) << surface.refusal();
    const std::vector<glm::dvec3> weights = sampleWeights(12, 200, 5);
    double largest = 0.0;
    for (uint32_t f = 0; f < mesh.faces.size() / 3; ++f) {
        BilinearSurface::Face face;
        ASSERT_TRUE(surface.initFace(f, face)) << f;
        const glm::dvec3 p0(mesh.positions[mesh.faces[3 * f]]), p1(mesh.positions[mesh.faces[3 * f + 1]]),
            p2(mesh.positions[mesh.faces[3 * f + 2]]);
        const double size = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
        double faceLargest = 0.0;
        for (const glm::dvec3& w : weights) {
            const glm::dvec3 expected = w.x * p0 + w.y * p1 + w.z * p2;
            faceLargest = std::max(faceLargest, glm::length(face.at(w) - expected) / size);
        }
        EXPECT_LT(faceLargest, 1e-12) << "face " << f;
        largest = std::max(largest, faceLargest);
    }
    std::printf("largest distance from the flat triangle: %.3g of the face's size\n", largest);
}

TEST(BilinearSurface, EdgeRuleIsTheSurfaceAlongTheEdge)
{
    // Every edge point the tessellation stores (BilinearSurface::edgePoint, from the
    // edge's ends) is where each face of the edge evaluates its own surface: within
    // 1e-12 of the edge's length in double, and at most one float ulp apart once stored.
    const TestMesh mesh = awkwardMesh();
    const BilinearSurface surface(mesh.faces, mesh.positions);
    ASSERT_FALSE(surface.refused()) << surface.refusal();
    double largest = 0.0;
    size_t points = 0, floatDiffers = 0;
    for (uint32_t f = 0; f < mesh.faces.size() / 3; ++f) {
        BilinearSurface::Face face;
        ASSERT_TRUE(surface.initFace(f, face)) << f;
        for (int i = 0; i < 3; ++i) {
            const glm::vec3 a = mesh.positions[mesh.faces[3 * f + size_t(i)]];
            const glm::vec3 b = mesh.positions[mesh.faces[3 * f + size_t(i + 1) % 3]];
            const double length = glm::length(glm::dvec3(b) - glm::dvec3(a));
            for (int rate = 2; rate <= 9; ++rate)
                for (int k = 1; k < rate; ++k) {
                    const double t = double(k) / double(rate);
                    glm::dvec3 w(0.0);
                    w[i] = 1.0 - t;
                    w[(i + 1) % 3] = t;
                    const glm::dvec3 onSurface = face.at(w);
                    const glm::dvec3 rule = BilinearSurface::edgePoint(a, b, t);
                    if (length > 0.0)
                        largest = std::max(largest, glm::length(onSurface - rule) / length);
                    const glm::vec3 stored(rule), evaluated(onSurface);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_LE(std::abs(stored[c] - evaluated[c]),
                                  std::nextafter(std::abs(stored[c]), INFINITY) - std::abs(stored[c]))
                            << "face " << f << " edge " << i << " rate " << rate << " point " << k;
                    ++points;
                    floatDiffers += stored != evaluated ? 1 : 0;
                }
        }
    }
    EXPECT_LT(largest, 1e-12);
    std::printf("edge points: %zu, largest distance from the surface %.3g of the edge's length, "
                "%zu differ by one float ulp\n",
                points, largest, floatDiffers);
}

TEST(BilinearSurface, RefusalIsReportedNotThrown)
{
    // A vertex with 65536 edges is past OpenSubdiv's valence limit (65535).
    TestMesh mesh;
    constexpr uint32_t kRim = 65536;
    mesh.positions.emplace_back(0.0f, 0.0f, 0.0f);
    for (uint32_t i = 0; i < kRim; ++i) {
        const double a = 2.0 * std::numbers::pi * double(i) / kRim;
        mesh.positions.emplace_back(float(0.5 * std::cos(a)), float(0.5 * std::sin(a)), 0.0f);
    }
    for (uint32_t i = 0; i < kRim; ++i)
        mesh.faces.insert(mesh.faces.end(), {0u, 1 + i, 1 + (i + 1) % kRim});
    const BilinearSurface surface(mesh.faces, mesh.positions);
    EXPECT_TRUE(surface.refused());
    EXPECT_NE(surface.refusal().find("valence"), std::string::npos) << surface.refusal();
    BilinearSurface::Face face;
    EXPECT_FALSE(surface.initFace(0, face));
}

} // namespace
} // namespace lfd::bake
