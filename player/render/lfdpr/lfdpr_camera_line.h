// Camera-line coherence for LFDPR's visibility pipeline (shaders/lfdpr_camera_line.glsl):
// the LFD view cameras lie on one line parallel to the screen and share its rectangle
// (off-axis frusta, never toe-in), so a scene point's clip y, z and w are the same in
// every view and its clip x is affine in the camera's offset along the line. Shaders then
// project a point once and step per view with one multiply-add.
#pragma once

#include "frame.h"

#include <glm/glm.hpp>

#include <vector>

namespace lfd::player {

inline constexpr uint32_t kLfdprMaxViews = 256; // LFDPR_MAX_VIEWS

// std140 mirror of LfdprCameraLineBlock (shaders/lfdpr_bindings.glsl).
struct LfdprCameraLineGpu {
    glm::vec4 row0;          // clip x row of view 0 (scene space)
    glm::vec4 row0PerOffset; // d row0 / d offset
    glm::vec4 row1;          // clip y row, every view
    glm::vec4 row3;          // clip w row, every view
    glm::vec4 wRange;        // near w, far w, 0, 0
    glm::vec4 viewOffsets[kLfdprMaxViews / 4]; // view i: component i % 4 of element i / 4
};
static_assert(sizeof(LfdprCameraLineGpu) == 1104);

struct LfdprCameraLine {
    LfdprCameraLineGpu gpu;
    std::vector<float> viewOffsets; // per view: camera offset from view 0 (display mm)
};

// Builds the coherent form of frame's cameras and checks it: every view's clip rows must
// match the affine model to 1e-5 of the row's size; otherwise (cameras not on one line
// parallel to the screen), or more than kLfdprMaxViews views, throws
// std::invalid_argument.
LfdprCameraLine makeLfdprCameraLine(const FrameSetup& frame);

} // namespace lfd::player
