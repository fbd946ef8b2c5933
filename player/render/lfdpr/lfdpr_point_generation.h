// LFDPR point generation (paper section 3.1; shaders/lfdpr_points.{vert,geom,frag}): the
// frame constants the stage needs, and the pass itself - every draw of the scene through
// VS -> GS -> FS into a framebuffer without attachments (the LFDPR_TILE_SIZE^2 sampling
// viewport), appending points to the point buffer and writing one record per emitting
// triangle.
#pragma once

#include "frame.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace lfd::player {

class GpuScene;

// std140 mirror of LfdprFrameBlock in shaders/lfdpr_bindings.glsl (208 bytes; the size is
// checked against the driver's block size when the program is built).
struct LfdprFrameGpu {
    glm::vec4 displayX;     // xyz unit display x in scene space, w view pixel width (scene units)
    glm::vec4 displayY;     // xyz unit display y, w view pixel height (scene units)
    glm::vec4 displayZ;     // xyz unit screen normal (towards the viewer)
    glm::vec4 screenCenter; // xyz screen centre (scene)
    glm::vec4 viewLine;     // xyz a point of the viewing line (camera 0's eye, scene)
    glm::vec4 planes[6];    // hull of the union of the view frusta (scene), inside: dot >= 0
    glm::uvec4 counts;      // view count, point capacity, options bits, 0
    glm::vec4 viewSize;     // view width, height (pixels), 0, 0
};
static_assert(sizeof(LfdprFrameGpu) == 208);

// The six planes (display space, inside: dot(plane, (p, 1)) >= 0) of a convex polytope
// containing every view frustum of `frame`: near and far (the views share them), and for
// left, right, top and bottom the chord between the union's extreme boundary at the near
// and at the far plane. Each view's side plane is linear in depth, so the union's
// boundary is the minimum (maximum) of linear functions - concave (convex) - and lies on
// the inner side of that chord: the polytope is conservative. Planes are pushed out by
// `slackMm` so vertices on a frustum boundary are never culled.
std::array<glm::dvec4, 6> unionFrustumPlanesDisplay(const FrameSetup& frame, double slackMm = 1e-3);

// The frame constants for `frame` (planes taken to scene space).
LfdprFrameGpu makeLfdprFrame(const FrameSetup& frame, uint32_t pointCapacity, uint32_t options);

class LfdprPointGeneration {
public:
    LfdprPointGeneration(); // builds the program and the attachment-less framebuffer
    ~LfdprPointGeneration();
    LfdprPointGeneration(const LfdprPointGeneration&) = delete;
    LfdprPointGeneration& operator=(const LfdprPointGeneration&) = delete;

    unsigned program() const { return program_; }
    // Number of triangle records the scene needs (sum over draws; instanced meshes count
    // once per node).
    static uint64_t recordCount(const GpuScene& scene);
    // Issues every draw. The caller has bound the scene, LFDPR buffers and uniform blocks.
    void run(const GpuScene& scene) const;

private:
    unsigned program_ = 0;
    unsigned framebuffer_ = 0;
};

} // namespace lfd::player
