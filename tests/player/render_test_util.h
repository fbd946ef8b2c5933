// Renders an in-memory scene with a named renderer and reads every view back (tests).
#pragma once

#include "frame.h"
#include "image_output.h"

#include "lfd/scene.h"

#include <string>
#include <vector>

namespace lfd::test {

struct RenderedViews {
    player::FrameSetup frame;
    std::vector<player::Image> views; // RGBA8, image order (row 0 = top)
    std::vector<std::pair<std::string, double>> stageMs; // GpuTimer stages of the frame
};

// Needs a current GL context. `profile` already carries the view count and size.
RenderedViews renderScene(const Scene& scene, const std::string& renderer,
                          const DisplayProfile& profile, double time, double turntablePeriod);

// The prototype profile with small views, for fast tests.
DisplayProfile smallProfile(uint32_t views, uint32_t width, uint32_t height);

} // namespace lfd::test
