// Framing (where the scene sits in the display volume) and the per-view cameras.
// Conventions are in framing.h; derivations are in the comments below and in
// formats/display_profiles.md.
#include "lfd/framing.h"

#include "number_text.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lfd {

namespace {

// Near plane floor, and the margin of the near/far planes around the scene sphere.
constexpr double kMinNearMm = 1.0;
constexpr double kDepthMargin = 1.05;

// Radius of the fitted sphere in display mm.
double sceneRadiusMm(const Framing& framing) { return framing.sceneRadius * framing.mmPerUnit; }

// Upper bound of sqrt(d^2 + s^2) / d^2 over the ball of radius rho about the origin, with
// d = D - z the depth below the camera line and s = lateral offset from a camera
// axis at most `offset` away (the eye offset e; 0 for the vertical axis).
// The rate grows with |s| and shrinks with d, so its maximum lies on the ball's boundary
// in the plane through the axis, where (after mirroring so that s adds up)
//   d = D - rho cos(theta),   |s| <= offset + rho sin(theta),   theta in [0, pi].
// The maximum can sit at theta = 0 (nearest point) or off it (wide cones, close viewers),
// so bound it interval by interval: on [theta0, theta1] use the smallest d and the
// largest |s| - an upper bound, tight to ~0.1% with kIntervals intervals.
double maxObliqueRate(double D, double rho, double offset) {
    constexpr int kIntervals = 4096;
    double best = 0.0;
    for (int j = 0; j < kIntervals; ++j) {
        const double theta0 = std::numbers::pi * j / kIntervals;
        const double theta1 = std::numbers::pi * (j + 1) / kIntervals;
        const double cosMax = std::cos(theta0); // cos decreases on [0, pi]
        const double sinMax = (theta0 <= 0.5 * std::numbers::pi && theta1 >= 0.5 * std::numbers::pi)
                                  ? 1.0
                                  : std::max(std::sin(theta0), std::sin(theta1));
        // note: nothing nearer than the near plane (>= 1 mm) is drawn.
        const double d = std::max(D - rho * cosMax, kMinNearMm);
        const double s = offset + rho * sinMax;
        best = std::max(best, std::sqrt(d * d + s * s) / (d * d));
    }
    return best;
}

// The largest sphere radius (mm, centred on the screen) that fits the display (fill 1):
// vertically the screen's height; horizontally the sphere must stay inside every view's
// frustum, and a camera at the cone's edge, e = -D tan(cone / 2), sees the right screen
// edge along a plane whose distance from the screen centre is
// D (W / 2) / sqrt(D^2 + (W / 2 - e)^2) - on a portrait panel seen from a wide cone that
// is well below W / 2 (Looking Glass Portrait: 54.09 instead of 60.21 mm), so a wide scene
// fitted to the screen width alone is cut off in the outer views.
double fittedRadiusMm(const DisplayProfile& profile) {
    const double D = profile.viewingDistanceMm;
    const double halfWidth = 0.5 * profile.screenWidthMm, halfHeight = 0.5 * profile.screenHeightMm;
    const double coneEdge = D * std::tan(0.5 * profile.viewConeDeg * std::numbers::pi / 180.0);
    const double insideFrustum = D * halfWidth / std::hypot(D, halfWidth + coneEdge);
    // note: a profile without a viewing distance (D = 0) keeps the plain half width.
    return std::min(halfHeight, D > 0.0 ? insideFrustum : halfWidth);
}

} // namespace

Framing fitSceneToDisplay(const DisplayProfile& profile, const SceneBounds& bounds, double fill) {
    if (!std::isfinite(fill) || fill <= 0.0)
        throw std::invalid_argument("fitSceneToDisplay: fill must be > 0, got " +
                                    detail::formatNumber(fill));
    Framing framing;
    framing.fill = fill;
    framing.sceneCenter = glm::dvec3(bounds.center);
    // note: an empty or single-point scene has r = 0; any scale frames it, use 1.
    const double r = double(bounds.radius);
    framing.sceneRadius = (std::isfinite(r) && r > 0.0) ? r : 1.0;
    framing.mmPerUnit = fill * fittedRadiusMm(profile) / framing.sceneRadius;
    return framing;
}

glm::dmat4 displayFromScene(const Framing& framing, double turntableAngle) {
    // p_display = mmPerUnit * R_y(angle) * (p_scene - c), read right to left.
    const glm::dmat4 centredFromScene = glm::translate(glm::dmat4(1.0), -framing.sceneCenter);
    const glm::dmat4 rotatedFromCentred =
        glm::rotate(glm::dmat4(1.0), turntableAngle, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dmat4 displayFromRotated =
        glm::scale(glm::dmat4(1.0), glm::dvec3(framing.mmPerUnit));
    return displayFromRotated * rotatedFromCentred * centredFromScene;
}

glm::dvec2 viewPixelSizeMm(const DisplayProfile& profile) {
    return {profile.screenWidthMm / double(profile.viewWidth),
            profile.screenHeightMm / double(profile.viewHeight)};
}

double minViewPixelWorld(const DisplayProfile& profile, const Framing& framing) {
    // A display point P = (x, y, z) seen from the eye E = (e, 0, D) lands on the screen
    // plane (z = 0, where the view pixels are p_x x p_y mm) at
    //   X_s = e + (x - e) D / d,   Y_s = y D / d,   d = D - z (depth below the camera).
    // Moving P along a unit vector u = (u_x, u_y, u_z) (so dd = -u_z):
    //   dX_s = D/d (u_x + (x - e)/d u_z),   dY_s = D/d (u_y + y/d u_z)
    // and by Cauchy-Schwarz one mm of edge covers at most
    //   D sqrt(d^2 + (x - e)^2) / (d^2 p_x)   horizontal pixels,
    //   D sqrt(d^2 + y^2) / (d^2 p_y)         vertical pixels.
    // For a point on the camera axis this is the footprint D / (d p) of framing.h; the
    // square root is the obliquity of edges running in depth off the axis, which the
    // plain footprint misses (it shrinks the bound by 8% on a Looking Glass Portrait; for
    // the prototype the on-axis vertical pixel still rules).
    // An edge inside the fitted sphere spans at most its length times the largest rate
    // over the sphere, every turntable angle (the sphere is invariant) and every camera
    // of any view count (|e| <= D tan(cone/2)); see maxObliqueRate for that maximum.
    const double D = profile.viewingDistanceMm;
    const double rho = sceneRadiusMm(framing);
    const double eMax = D * std::tan(0.5 * glm::radians(profile.viewConeDeg));
    const glm::dvec2 pixelMm = viewPixelSizeMm(profile);
    const double worldX = pixelMm.x / (D * maxObliqueRate(D, rho, eMax));
    const double worldY = pixelMm.y / (D * maxObliqueRate(D, rho, 0.0));
    return std::min(worldX, worldY) / framing.mmPerUnit;
}

ViewCamera makeViewCamera(const DisplayProfile& profile, const Framing& framing,
                          uint32_t viewIndex, uint32_t viewCount) {
    if (viewCount == 0 || viewIndex >= viewCount)
        throw std::invalid_argument("makeViewCamera: view index " + std::to_string(viewIndex) +
                                    " out of range for " + std::to_string(viewCount) + " views");
    return makeViewCameraAt(profile, framing, (double(viewIndex) + 0.5) / double(viewCount));
}

ViewCamera makeViewCameraAt(const DisplayProfile& profile, const Framing& framing, double conePosition) {
    if (!(conePosition >= 0.0 && conePosition <= 1.0))
        throw std::invalid_argument("makeViewCameraAt: cone position " + std::to_string(conePosition) +
                                    " outside [0, 1]");
    const double D = profile.viewingDistanceMm;
    const double W = profile.screenWidthMm;
    const double H = profile.screenHeightMm;

    // Step 1: eye on the camera line, view 0 leftmost; the angles split the cone into N
    // equal intervals and take their centres.
    const double cone = glm::radians(profile.viewConeDeg);
    const double t = conePosition - 0.5;
    ViewCamera camera;
    camera.eye = glm::dvec3(D * std::tan(cone * t), 0.0, D);

    // Step 2: the view axes are the display axes (looking down -z) - the cameras are
    // shifted, never rotated (no toe-in), so every view shares the screen plane.
    camera.viewFromDisplay = glm::translate(glm::dmat4(1.0), -camera.eye);

    // Step 3: near/far around the fitted sphere, which spans depths D -+ rho.
    const double rho = sceneRadiusMm(framing);
    const double zNear = std::max(kMinNearMm, D - kDepthMargin * rho);
    const double zFar = std::max(D + kDepthMargin * rho, zNear + kMinNearMm);

    // Step 4: off-axis frustum through the screen rectangle. In view space the screen is
    // [-W/2 - e, W/2 - e] x [-H/2, H/2] at depth D; by similar triangles the near-plane
    // window is that rectangle scaled by zNear / D. The screen rectangle then maps to
    // NDC [-1, 1]^2 in every view (zero parallax at z = 0).
    const double s = zNear / D;
    const double e = camera.eye.x;
    camera.clipFromView = glm::frustumRH_NO((-0.5 * W - e) * s, (0.5 * W - e) * s, -0.5 * H * s,
                                            0.5 * H * s, zNear, zFar);
    camera.clipFromDisplay = camera.clipFromView * camera.viewFromDisplay;
    return camera;
}

} // namespace lfd
