// The tessellation pattern of one oversized triangle, given the number of pieces each of
// its edges is cut into (tessellation.cpp decides those per welded edge and makes the
// edge points; this file only connects them). Used by tessellation.cpp and its tests.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace lfd::bake {

// Boundary points of a face with edge rates r0, r1, r2, in the order OpenSubdiv's
// Bfr::Tessellation lists them (counter-clockwise, i.e. in the face's winding): corner 0,
// the r0 - 1 points of edge 0 from corner 0 towards corner 1, corner 1, the points of
// edge 1, corner 2, the points of edge 2. Edge i runs from corner i to corner i + 1.
size_t boundaryPointCount(const std::array<int, 3>& rates);

struct FacePattern {
    // Triangles, 3 indices each, in the winding of the face: an index below
    // boundaryPointCount(rates) is a boundary point, index boundaryPointCount + k is
    // interior point k.
    std::vector<int> facets;
    // Barycentric weights of corners 0, 1, 2 for each interior point (Bfr's (u, v) is
    // (weights.y, weights.z)), and its position: what the bound was checked on, and what
    // tessellation.cpp stores.
    std::vector<glm::dvec3> interiorWeights;
    std::vector<glm::vec3> interiorPoints;
    double longestEdge = 0.0; // of all facet edges, in the units of the positions given
    bool fromOpenSubdiv = false; // false: boundary-only triangulation (see face_pattern.cpp)
};

// Where the point of a face with barycentric weights `weights` (of its corners 0, 1, 2)
// is stored, float as the vertex stream holds it: tessellation.cpp evaluates the face's
// bilinear surface (bilinear_surface.h), or interiorPosition where OpenSubdiv gives the
// face none.
using FacePoint = std::function<glm::vec3(const glm::dvec3& weights)>;

// The barycentric combination of the corners, rounded to float.
glm::vec3 interiorPosition(const std::array<glm::vec3, 3>& corners, const glm::dvec3& weights);

// Pattern for a face whose points lie at `pointAt`, with edge rates (>= 1 each, not all
// 1) and boundary point positions (boundaryPointCount(rates) of them, in the order above,
// as they are stored). Among the patterns tried it keeps the one with the fewest
// triangles whose every edge is at most `bound`; when none meets the bound, the one with
// the shortest longest edge (longestEdge then tells by how much). The bound is checked on
// exactly the positions pointAt gives, which the pattern returns as interiorPoints.
// Throws BakeError if OpenSubdiv rejects the rates.
FacePattern facePattern(const FacePoint& pointAt, const std::array<int, 3>& rates, std::span<const glm::vec3> boundary,
                        double bound);
// The same for a face whose points are interiorPosition of `corners`.
FacePattern facePattern(const std::array<glm::vec3, 3>& corners, const std::array<int, 3>& rates,
                        std::span<const glm::vec3> boundary, double bound);

} // namespace lfd::bake
