// LFDPR point generation (paper section 3.1; shaders/lfdpr_paper_points.{vert,geom,frag}): the
// frame constants the stage needs, and the pass itself - every draw of the scene through
// VS -> GS -> FS into a framebuffer without attachments (the LFDPR_TILE_SIZE^2 sampling
// viewport), appending points to the point buffer and writing one record per emitting
// triangle.
#pragma once

#include "frame.h"
#include "gl_handles.h"
#include "lfdpr_bindings_gpu.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace lfd::player {

class GpuScene;

// The frame constants block (LfdprFrameBlock), generated from shaders/lfdpr_bindings.glsl.
using lfdpr_bindings::LfdprFrameGpu;

// The six planes (display space, inside: dot(plane, (p, 1)) >= 0) of a convex polytope
// containing every view frustum of `frame`: near and far (the views share them), and for
// left, right, top and bottom the chord between the union's extreme boundary at the near
// and at the far plane. Each view's side plane is linear in depth, so the union's
// boundary is the minimum (maximum) of linear functions - concave (convex) - and lies on
// the inner side of that chord: the polytope is conservative. Planes are pushed out by
// `slackMm` so vertices on a frustum boundary are never culled.
std::array<glm::dvec4, 6> unionFrustumPlanesDisplay(const FrameSetup& frame, double slackMm = 1e-3);

// The frame constants for `frame` (planes taken to scene space). `splatViewCount` (counts.w):
// the views the points will be splatted into, 0 = frame's own; under angular supersampling
// (FrameSetup::pointSampling) points are sampled for N views and splatted into 2N.
LfdprFrameGpu makeLfdprFrame(const FrameSetup& frame, uint32_t pointCapacity, uint32_t options,
                             uint32_t splatViewCount = 0);

class LfdprPaperPointGeneration {
public:
    LfdprPaperPointGeneration(); // builds the program and the attachment-less framebuffer

    unsigned program() const { return program_.get(); }
    // Number of triangle records the scene needs (sum over draws; instanced meshes count
    // once per node).
    static uint64_t recordCount(const GpuScene& scene);
    // Issues every draw. The caller has bound the scene, LFDPR buffers and uniform blocks.
    void run(const GpuScene& scene) const;

private:
    gl::Program program_;
    gl::Framebuffer framebuffer_;
};

} // namespace lfd::player
