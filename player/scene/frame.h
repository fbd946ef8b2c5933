// Everything that describes one frame to render: display, framing, animation time and the
// N view cameras. Built once per frame by makeFrameSetup and handed to every renderer.
#pragma once

#include "scene_lights.h"

#include "lfd/display_profile.h"
#include "lfd/framing.h"

#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace lfd::player {

class GpuEnvironment; // gpu_environment.h

// What the frame's views show of the scene's light (pbr_shading.glsl, docs/lighting.md).
enum class ToneMap : uint32_t { None = 0, PbrNeutral = 1 };

struct FrameLighting {
    // Image-based lighting; null: the constant ambient term instead.
    const GpuEnvironment* environment = nullptr;
    double environmentRotationDeg = 0.0; // about the display's vertical (+: counter-clockwise from above)
    double exposureEv = 0.0;             // radiance * 2^EV before tone mapping
    ToneMap toneMap = ToneMap::None;
    // The scene's punctual lights this frame (sceneLights). Empty: the default directional
    // light, when there is no environment; an environment alone lights a scene without lights.
    std::vector<PunctualLight> lights;
};

// Everything in `lighting` (with `environment`, GpuEnvironment::key()) that changes pixels,
// as text, for caches of rendered views (gstd's): the lights come from the pack.
std::string frameLightingKey(const FrameLighting& lighting, const GpuEnvironment* environment);

struct FrameSetup {
    DisplayProfile profile;  // views/view size already overridden from the command line
    Framing framing;
    double time = 0.0;            // seconds, drives glTF node animations
    double turntableAngle = 0.0;  // radians about the vertical axis through the scene centre
    float textureAnisotropy = 1.0f; // --aniso as the scene's textures got it (GpuScene::maxAnisotropy)
    glm::dmat4 displayFromScene{1.0};
    std::vector<ViewCamera> cameras; // profile.viewCount entries
    // Per-view clipFromScene = cameras[i].clipFromDisplay * displayFromScene (float, for upload).
    std::vector<glm::mat4> clipFromScene;
    std::vector<glm::vec3> eyeScene; // camera positions in scene space (view-dependent shading)
    FrameLighting lighting;
    // Angular supersampling (frame_pipeline.h, --ss 2v) renders more views than the
    // display has; point-based renderers then sample the scene for the display's own
    // views (this frame), so the point cloud does not grow. Null: sample for `cameras`.
    std::shared_ptr<const FrameSetup> pointSampling;

    // The frame point sampling is decided for: *pointSampling, else this frame.
    const FrameSetup& samplingFrame() const { return pointSampling ? *pointSampling : *this; }
};

// What the viewer steers on top of the baker's framing (lfd-play's window controls and
// headless flags; player/app/camera_controls.h drives it). Display space (framing.h): mm,
// +x right, +y up, +z toward the viewer, screen plane z = 0 = zero parallax.
struct ViewControls {
    double yawDeg = 0.0;   // orbit about the vertical axis through the scene centre (+: front moves right)
    double pitchDeg = 0.0; // then about the horizontal axis (+: front moves down)
    double zoom = 1.0;     // scale of the fitted scene (2: twice as large)
    glm::dvec2 panMm{0.0}; // shift along the screen plane
    // The display depth (before the shift) put at zero parallax: the scene moves by
    // -focalDepthMm along z, so a point that was focalDepthMm in front of the screen lands
    // on it and looks the same in every view.
    double focalDepthMm = 0.0;
    double depthiness = 1.0; // view-cone scale: 0 = flat (every camera central), 1 = the profile's cone
    bool turntable = true;   // the turntable angle (time / period) adds to the yaw
};

// Turntable angle in radians at `time`: 2 pi t / period (0 when the period is 0).
double turntableAngle(double time, double turntablePeriod);

// Turntable: one revolution every `turntablePeriod` seconds (0 = no rotation).
FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod);
// With the viewer's controls. The result's `profile` carries the scaled view cone and its
// `framing` the zoomed scale with a radius that covers the shifted scene (near/far), so
// code that re-derives cameras from them (gstd's sub-views) agrees with `cameras`:
//   displayFromScene = T(pan.x, pan.y, -focal) * S(mmPerUnit * zoom) * R_x(pitch)
//                      * R_y(yaw + turntable) * T(-centre)
FrameSetup makeFrameSetup(const DisplayProfile& profile, const Framing& framing, double time,
                          double turntablePeriod, const ViewControls& controls);

} // namespace lfd::player
