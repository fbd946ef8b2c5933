#include "frame.h"

#include <cmath>
#include <numbers>

namespace lfd::player {

FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod)
{
    FrameSetup frame;
    frame.profile = profile;
    frame.framing = framing;
    frame.time = time;

    // Turntable: angle = 2 pi t / period about the vertical axis through the scene centre
    // (fmod keeps the angle small for long runs, where float precision would suffer).
    if (turntablePeriod > 0.0)
        frame.turntableAngle = 2.0 * std::numbers::pi * std::fmod(time, turntablePeriod) / turntablePeriod;
    frame.displayFromScene = displayFromScene(framing, frame.turntableAngle);
    const glm::dmat4 sceneFromDisplay = glm::inverse(frame.displayFromScene);

    // Per view: clipFromScene = clipFromDisplay * displayFromScene, and the camera eye
    // taken back to scene space for view-dependent shading.
    const uint32_t n = profile.viewCount;
    frame.cameras.reserve(n);
    frame.clipFromScene.reserve(n);
    frame.eyeScene.reserve(n);
    for (uint32_t i = 0; i < n; ++i) {
        const ViewCamera camera = makeViewCamera(profile, framing, i, n);
        frame.cameras.push_back(camera);
        frame.clipFromScene.push_back(glm::mat4(camera.clipFromDisplay * frame.displayFromScene));
        frame.eyeScene.push_back(glm::vec3(sceneFromDisplay * glm::dvec4(camera.eye, 1.0)));
    }
    return frame;
}

} // namespace lfd::player
