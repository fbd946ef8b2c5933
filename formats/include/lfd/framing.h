// Framing and view cameras: where the scene sits in the display volume and what one view
// pixel measures on it. Shared by the baker (tessellation bound) and the player (cameras),
// so both agree on pixel sizes.
//
// Display space: millimetres, origin at the screen centre, +x right, +y up, +z toward the
// viewer; the screen rectangle [-W/2, W/2] x [-H/2, H/2] at z = 0 is the zero-parallax
// plane of every view. View i's camera sits at (x_i, 0, D), D = viewing distance,
//   x_i = D * tan(viewCone * ((i + 0.5) / N - 0.5))      (view 0 = leftmost camera)
// with an off-axis (sheared) frustum through the screen rectangle - never toe-in.
//
// Scene fitting: the scene's bounding sphere (centre c, radius r, from SceneBounds) is
// centred on the screen (z = 0) and scaled to `fill` times the largest radius that fits
// the display: half the screen height, and horizontally inside the frustum of every view
// of the cone (less than half the width on a portrait panel seen from a wide cone;
// formats/display_profiles.md section 4). The turntable rotates the scene about
// the vertical axis through c, which leaves the bounding sphere unchanged, so every bound
// below holds for every rotation angle.
#pragma once

#include "lfd/display_profile.h"
#include "lfd/scene.h"

#include <glm/glm.hpp>

namespace lfd {

struct Framing {
    glm::dvec3 sceneCenter{0.0}; // scene space
    double sceneRadius = 1.0;    // scene units
    double mmPerUnit = 1.0;      // display mm per scene unit
    double fill = 1.0;
};

Framing fitSceneToDisplay(const DisplayProfile& profile, const SceneBounds& bounds,
                          double fill = 1.0);

// displayFromScene (turntable angle in radians about the vertical axis through c):
// p_display = mmPerUnit * R_y(angle) * (p_scene - c)
glm::dmat4 displayFromScene(const Framing& framing, double turntableAngle = 0.0);

// Size in mm of one view pixel on the screen plane (horizontal, vertical).
glm::dvec2 viewPixelSizeMm(const DisplayProfile& profile);

// Conservative world length of one view pixel: the smallest footprint, over all views and
// all turntable angles, of the smaller pixel edge at the scene point nearest the camera
// line, in scene units. A pixel's footprint at camera distance z is pixelMm * z / D; the
// nearest the scene gets is z = D - r*mmPerUnit. Edges running in depth off a camera's
// axis (lateral offset s) project longer, by sqrt(1 + (s / z)^2), so the bound takes, per
// axis, the largest projection rate over the fitted sphere and every camera position in
// the cone: an edge of length n * minViewPixelWorld spans at most n view pixels in either
// axis in every view (derivation in framing.cpp). For the prototype this equals the plain
// footprint (the vertical pixel at z = D - r rules); a Looking Glass Portrait gets 8% less.
double minViewPixelWorld(const DisplayProfile& profile, const Framing& framing);

struct ViewCamera {
    glm::dvec3 eye{0.0};       // display space
    glm::dmat4 viewFromDisplay{1.0};
    glm::dmat4 clipFromView{1.0}; // OpenGL clip space, off-axis frustum
    glm::dmat4 clipFromDisplay{1.0};
};

// Near/far planes are placed around the fitted scene sphere.
ViewCamera makeViewCamera(const DisplayProfile& profile, const Framing& framing,
                          uint32_t viewIndex, uint32_t viewCount);
// The camera at any position of the view cone: `conePosition` in [0, 1] (0 = left edge of
// the cone, 1 = right edge); makeViewCamera(i, N) is makeViewCameraAt((i + 0.5) / N).
// Angular supersampling places cameras at random positions inside a view's interval.
ViewCamera makeViewCameraAt(const DisplayProfile& profile, const Framing& framing, double conePosition);

} // namespace lfd
