// Small deterministic scenes built in memory for the player tests (no files needed).
#pragma once

#include "lfd/display_profile.h"
#include "lfd/scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace lfd::test {

// Appends a mesh of one primitive (indices absolute into scene.vertices); returns its index.
int32_t addMesh(Scene& scene, const std::vector<uint32_t>& indices, int32_t material);
// A UV sphere of `radius` about the origin (normals, tangents, uvs 0..1), vertices
// appended to scene.vertices; returns its triangle list (absolute indices).
std::vector<uint32_t> addSphere(Scene& scene, float radius, uint32_t slices, uint32_t stacks);
// A grid of cells x cells quads in the plane z = 0, [-h, h]^2, facing +z (normals,
// tangents along +x), uvs 0..uvScale with v down; split into cells as the baker's
// tessellation bound would split a big quad. Returns its triangle list.
std::vector<uint32_t> addGrid(Scene& scene, float h, uint32_t cells, float uvScale);
// Appends a node instancing `mesh` with local transform T * R * S.
void addNode(Scene& scene, int32_t mesh, const glm::vec3& t, const glm::quat& r, const glm::vec3& s);
// What the baker computes for a finished scene: per-triangle statistics (texture sizes
// must be set) and bounds, with the baker's own stages.
void finishScene(Scene& scene);

// Bounds of the cube [-1, 1]^3 (centre 0, radius 1): a framing the tests can work by hand.
SceneBounds unitBounds();
// One view pixel (horizontal, vertical) on the zero-parallax plane, in scene units, for
// scenes framed by unitBounds().
glm::dvec2 pixelUnits(const DisplayProfile& profile);

// Appends a vertex with a position, a normal and a uv (the streams the stability scenes
// use); returns its index.
uint32_t addVertex(Scene& scene, glm::vec3 p, glm::vec3 n, glm::vec2 uv);

// RGBA8 checker texture (squares of `square` texels) with its full box-filtered mip chain.
Texture checkerTexture(uint32_t size, uint32_t square, glm::u8vec4 a, glm::u8vec4 b, bool srgb);

// A textured, normal-mapped-free cube (checker base colour, tangents present) rotated on
// the left, an untextured red sphere on the right, and a small default-material (-1) box
// in front. Bounds enclose everything. Deterministic.
Scene cubeAndSphereScene();

// A block of rotated instances of the test cube and sphere: many small triangles, depth
// and occlusion (a miniature of the dense benchmark sample).
Scene denseTestScene();

// Positions only (no normals, uvs or tangents), default material: a tetrahedron-ish
// pyramid. Exercises the "missing streams" paths.
Scene positionsOnlyScene();

// A material that shows `emissive` alone: base colour black, metallic 1, roughness 1, so
// direct and ambient light add nothing measurable.
Material emissiveOnlyMaterial(const glm::vec3& emissive);

// Two emissive-only unit quads facing +z (base colour black, metallic 1, roughness 1, so
// direct and ambient light add nothing measurable): `front` centred at (-x, +y, 0) on the
// scene centre plane (zero parallax), `back` at (+x, 0, zBack). Bounds: sphere of
// `radius` about the origin, so the framing is known.
struct EmissiveQuads {
    Scene scene;
    glm::vec3 frontCenter, backCenter;
    glm::vec3 frontEmissive, backEmissive;
};
EmissiveQuads emissiveQuadsScene(float radius, float zBack);

} // namespace lfd::test
