#include "frame.h"

#include "gpu_environment.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace lfd::player {

namespace {

// The framing the cameras see: the scale includes the zoom, and the radius grows by the
// focal shift so that near/far (placed around a sphere at the screen centre,
// makeViewCamera) still enclose the moved scene. Pan moves the scene along the screen
// plane only, which leaves its depth range alone.
Framing controlledFraming(const Framing& framing, const ViewControls& controls)
{
    Framing f = framing;
    f.mmPerUnit = framing.mmPerUnit * controls.zoom;
    f.sceneRadius = framing.sceneRadius + std::abs(controls.focalDepthMm) / f.mmPerUnit;
    return f;
}

// displayFromScene = T(pan, -focal) * S(mmPerUnit * zoom) * R_x(pitch) * R_y(yaw) * T(-c),
// read right to left.
glm::dmat4 controlledDisplayFromScene(const Framing& framing, const ViewControls& controls, double yawRad)
{
    const glm::dmat4 centredFromScene = glm::translate(glm::dmat4(1.0), -framing.sceneCenter);
    const glm::dmat4 yawed = glm::rotate(glm::dmat4(1.0), yawRad, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 pitched = glm::rotate(glm::dmat4(1.0), glm::radians(controls.pitchDeg), glm::dvec3(1.0, 0.0, 0.0));
    const glm::dmat4 scaled = glm::scale(glm::dmat4(1.0), glm::dvec3(framing.mmPerUnit * controls.zoom));
    const glm::dmat4 shifted =
        glm::translate(glm::dmat4(1.0), glm::dvec3(controls.panMm.x, controls.panMm.y, -controls.focalDepthMm));
    return shifted * scaled * pitched * yawed * centredFromScene;
}

} // namespace

// Turntable: angle = 2 pi t / period about the vertical axis through the scene centre
// (fmod keeps the angle small for long runs, where float precision would suffer).
double turntableAngle(double time, double turntablePeriod)
{
    if (turntablePeriod <= 0.0)
        return 0.0;
    return 2.0 * std::numbers::pi * std::fmod(time, turntablePeriod) / turntablePeriod;
}

FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod)
{
    return makeFrameSetup(profile, framing, time, turntablePeriod, ViewControls{});
}

FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod, const ViewControls& controls)
{
    FrameSetup frame;
    frame.profile = profile;
    frame.profile.viewConeDeg = profile.viewConeDeg * controls.depthiness;
    frame.framing = controlledFraming(framing, controls);
    frame.time = time;

    if (controls.turntable)
        frame.turntableAngle = turntableAngle(time, turntablePeriod);
    const double yaw = glm::radians(controls.yawDeg) + frame.turntableAngle;
    frame.displayFromScene = controlledDisplayFromScene(framing, controls, yaw);
    const glm::dmat4 sceneFromDisplay = glm::inverse(frame.displayFromScene);

    // Per view: clipFromScene = clipFromDisplay * displayFromScene, and the camera eye
    // taken back to scene space for view-dependent shading.
    const uint32_t n = profile.viewCount;
    frame.cameras.reserve(n);
    frame.clipFromScene.reserve(n);
    frame.eyeScene.reserve(n);
    for (uint32_t i = 0; i < n; ++i) {
        const ViewCamera camera = makeViewCamera(frame.profile, frame.framing, i, n);
        frame.cameras.push_back(camera);
        frame.clipFromScene.push_back(glm::mat4(camera.clipFromDisplay * frame.displayFromScene));
        frame.eyeScene.push_back(glm::vec3(sceneFromDisplay * glm::dvec4(camera.eye, 1.0)));
    }
    return frame;
}

std::string frameLightingKey(const FrameLighting& lighting, const GpuEnvironment* environment)
{
    // %a: exact (hexadecimal) doubles, so equal keys mean bit-equal settings.
    char text[160];
    std::snprintf(text, sizeof(text), "rotation=%a exposure=%a tonemap=%u", lighting.environmentRotationDeg,
                  lighting.exposureEv, unsigned(lighting.toneMap));
    return "environment=" + (environment ? environment->key() : std::string("none")) + " " + text;
}

} // namespace lfd::player
