// The C++ side of shaders/scene_bindings.glsl (binding points, attribute locations, GPU
// struct layouts): generated from the GLSL file at build time (scene_bindings_gpu.h, by
// player/gl/gpu_layout_gen.cpp), so nothing here is written twice. In
// lfd::player::bindings: every #define as a constant (LFD_SSBO_VIEWS -> kSsboViews) and
// MaterialGpu, NodeGpu, ViewGpu, TriangleStatsGpu and FrameGpu (the FrameBlock uniform
// block). tests/player/gpu_layout_test.cpp checks every member against the driver.
#pragma once

#include "scene_bindings_gpu.h"
