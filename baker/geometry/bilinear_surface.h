// The welded triangle mesh of one tessellation group as OpenSubdiv's bilinear surface
// (docs/baker/lfd-bake.md "What a bake does", step 4): Far::TopologyRefiner over the welded faces
// -> Bfr::RefinerSurfaceFactory, one Bfr::Surface per face. tessellation.cpp places the new points
// of oversized faces on it; face_pattern.cpp builds its patterns in barycentric weights, so a face
// here is addressed by barycentric weights of its corners.
#pragma once

#include <glm/glm.hpp>

#include <opensubdiv/bfr/surface.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace OpenSubdiv::OPENSUBDIV_VERSION::Far {
class TopologyRefiner;
}
namespace OpenSubdiv::OPENSUBDIV_VERSION::Bfr {
class RefinerSurfaceFactoryBase;
}

namespace lfd::bake {

// A point of a triangle in Bfr's parameterization of the bilinear scheme, which splits a
// triangle into three quad sub-faces (Bfr::Parameterization::QUAD_SUBFACES): sub-face i
// has, at its normalized coordinates (s, t), corner i at (0, 0), the midpoint of edge i
// (corner i to corner i + 1) at (1, 0), the centroid at (1, 1) and the midpoint of edge
// i - 1 at (0, 1), and is bilinear in between.
struct SubFaceCoord {
    int subFace = 0;
    glm::dvec2 st{0.0};
};

// The sub-face point with barycentric weights `weights` (of corners 0, 1, 2; summing to
// 1, none negative): the inverse of the bilinear map, in double precision.
SubFaceCoord subFaceCoord(const glm::dvec3& weights);
// The barycentric weights of a sub-face point (the bilinear map itself).
glm::dvec3 barycentricWeights(const SubFaceCoord& coord);

class BilinearSurface {
public:
    // faceCorners: 3 welded vertex ids per face (face f is faceCorners[3f .. 3f + 2]);
    // positions: one per welded vertex. Never throws for the mesh's topology: where
    // OpenSubdiv refuses it, refused() says so and no face has a surface.
    BilinearSurface(std::span<const uint32_t> faceCorners, std::span<const glm::vec3> positions);
    ~BilinearSurface();
    BilinearSurface(const BilinearSurface&) = delete;
    BilinearSurface& operator=(const BilinearSurface&) = delete;

    bool refused() const { return factory_ == nullptr; }
    // OpenSubdiv's message (or ours) when refused.
    const std::string& refusal() const { return refusal_; }

    // The surface of one face, ready to evaluate.
    class Face {
    public:
        // The point with barycentric weights `weights` of the face's corners (in the
        // order the face lists them), in double precision.
        glm::dvec3 at(const glm::dvec3& weights) const;

    private:
        friend class BilinearSurface;
        OpenSubdiv::Bfr::Surface<double> surface_;
        std::vector<double> patchPoints_; // 3 per patch point
    };

    // The surface along an edge at t (0..1) from end a to end b: each half of the edge is
    // a side of a sub-face, running from a corner to the edge's midpoint, along which the
    // bilinear map is linear, so the whole edge is the straight line a + (b - a) t and
    // depends on its two ends alone. Evaluating a face's Bfr::Surface there gives the
    // same point up to rounding (tested), but the two faces of an edge reach it through
    // different sub-faces; this gives both faces the same bits.
    static glm::dvec3 edgePoint(const glm::vec3& a, const glm::vec3& b, double t)
    {
        const glm::dvec3 from(a);
        return from + (glm::dvec3(b) - from) * t;
    }

    // Initialises `face` for face index f; false where OpenSubdiv gives the face no
    // surface (or refused the mesh). Safe to call from several threads at once.
    bool initFace(uint32_t f, Face& face) const;

private:
    std::vector<double> points_; // welded positions, 3 doubles each
    std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner_;
    std::unique_ptr<OpenSubdiv::Bfr::RefinerSurfaceFactoryBase> factory_;
    std::string refusal_;
};

} // namespace lfd::bake
