// Camera-line coherence for LFDPR's visibility pipeline (shaders/lfdpr_camera_line.glsl):
// the LFD view cameras lie on one line parallel to the screen and share its rectangle
// (off-axis frusta, never toe-in), so a scene point's clip y, z and w are the same in
// every view and its clip x is affine in the camera's offset along the line. Shaders then
// project a point once and step per view with one multiply-add.
#pragma once

#include "frame.h"
#include "lfdpr_bindings_gpu.h"

#include <glm/glm.hpp>

#include <vector>

namespace lfd::player {

inline constexpr uint32_t kLfdprMaxViews = lfdpr_bindings::kMaxViews;

// The camera-line uniform block (LfdprCameraLineBlock), generated from
// shaders/lfdpr_bindings.glsl: view i's offset is component i % 4 of viewOffsets[i / 4].
using lfdpr_bindings::LfdprCameraLineGpu;

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
