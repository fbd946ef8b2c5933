// Everything that describes one frame to render: display, framing, animation time and the
// N view cameras. Built once per frame by makeFrameSetup and handed to every renderer.
#pragma once

#include "lfd/display_profile.h"
#include "lfd/framing.h"

#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace lfd::player {

struct FrameSetup {
    DisplayProfile profile;  // views/view size already overridden from the command line
    Framing framing;
    double time = 0.0;            // seconds, drives glTF node animations
    double turntableAngle = 0.0;  // radians about the vertical axis through the scene centre
    glm::dmat4 displayFromScene{1.0};
    std::vector<ViewCamera> cameras; // profile.viewCount entries
    // Per-view clipFromScene = cameras[i].clipFromDisplay * displayFromScene (float, for upload).
    std::vector<glm::mat4> clipFromScene;
    std::vector<glm::vec3> eyeScene; // camera positions in scene space (view-dependent shading)
    // Angular supersampling (frame_pipeline.h, --ss 2v) renders more views than the
    // display has; point-based renderers then sample the scene for the display's own
    // views (this frame), so the point cloud does not grow. Null: sample for `cameras`.
    std::shared_ptr<const FrameSetup> pointSampling;

    // The frame point sampling is decided for: *pointSampling, else this frame.
    const FrameSetup& samplingFrame() const { return pointSampling ? *pointSampling : *this; }
};

// Turntable: one revolution every `turntablePeriod` seconds (0 = no rotation).
FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod);

} // namespace lfd::player
