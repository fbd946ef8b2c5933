// Procedural triangle meshes for the sample scenes: quads, boxes and parametric
// surfaces (superellipsoids, tori, cylinders), all indexed, counter-clockwise when
// seen from the side the normals point to.
//
// Everything is built in the caller's frame: the builders take an objectFromLocal
// matrix so parts can be placed without a node per part.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace lfd::samples {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;      // empty for untextured parts
    std::vector<glm::vec4> tangents; // empty unless the material has a normal map
    std::vector<uint32_t> indices;
    // Skinning (glTF 3.7.3): JOINTS_0 / WEIGHTS_0, empty for rigid parts.
    std::vector<glm::u16vec4> joints;
    std::vector<glm::vec4> weights;
    // Morph targets (glTF 3.7.2.2): per target, POSITION and NORMAL deltas.
    std::vector<std::vector<glm::vec3>> morphPositions;
    std::vector<std::vector<glm::vec3>> morphNormals;

    size_t triangleCount() const { return indices.size() / 3; }
};

// A rectangle with its texture upright: `topLeft` is where uv (u0, v0) sits, `right`
// and `down` span the image's +u and +v directions (glTF uv: v grows downwards in the
// image). The visible side is normalize(cross(down, right)), i.e. the side from which
// the image reads left-to-right, top-to-bottom; that is also the winding's front.
// uvRect = (u0, v0, u1, v1) picks the part of the image shown.
struct QuadSpec {
    glm::vec3 topLeft;
    glm::vec3 right;
    glm::vec3 down;
    glm::vec4 uvRect{0.0f, 0.0f, 1.0f, 1.0f};
};

enum class Attributes { kNormals, kNormalsUvs, kNormalsUvsTangents };

void addQuad(MeshData& mesh, const QuadSpec& quad, Attributes attributes);

// An axis-aligned box [lo, hi] in local space, transformed by objectFromLocal (which
// must not mirror). Six faces with their own vertices (hard edges).
void addBox(MeshData& mesh, const glm::mat4& objectFromLocal, glm::vec3 lo, glm::vec3 hi,
            Attributes attributes = Attributes::kNormals);

// A closed surface of revolution type: sphere-like, parameterised by longitude
// theta in [0, 2pi) and latitude phi in [-pi/2, pi/2]. The poles are single vertices
// and the seam is welded, so the result is watertight (every edge has two triangles).
// `surface` maps (theta, phi) to a local position; it must be outward-oriented like a
// sphere ((cos phi cos theta, sin phi, -cos phi sin theta)). Normals are smooth,
// area-weighted averages of the face normals. No uvs.
void addClosedSurface(MeshData& mesh, const glm::mat4& objectFromLocal, int segments,
                      int rings, const std::function<glm::vec3(float theta, float phi)>& surface);

// Superellipsoid with half-extents `radii`; exponents < 1 make it boxy (1 = ellipsoid).
glm::vec3 superellipsoidPoint(glm::vec3 radii, float eLatitude, float eLongitude, float theta,
                              float phi);

// Torus around the local z axis: ring radius `major`, tube radii (radial `minor`,
// axial `minorZ`). Watertight, smooth normals.
void addTorus(MeshData& mesh, const glm::mat4& objectFromLocal, float major, float minor,
              float minorZ, int segments, int sides);

// Closed cylinder along local z from z0 to z1: side with smooth normals, flat caps with
// their own vertices (geometrically closed, hard rim edge).
void addCylinder(MeshData& mesh, const glm::mat4& objectFromLocal, float radius, float z0,
                 float z1, int segments);

// Appends `part` to `mesh` (indices rebased). Both must carry the same attributes.
void append(MeshData& mesh, const MeshData& part);

} // namespace lfd::samples
