// The viewer's camera controls as one small state machine, shared by the window (mouse and
// keys) and the headless flags: orbit, zoom, pan, focal plane, depthiness, turntable and
// reset act on a ViewControls (frame.h) that the frame pipeline turns into cameras.
//
//   left drag         orbit: kOrbitDegPerPixel per window pixel (right: front moves right,
//                     down: front moves down; pitch clamped to +-kMaxPitchDeg)
//   right/middle drag pan along the screen plane, following the cursor (mm per window pixel
//   (or Shift+left)   given by the window: screen width / shown EIA width)
//   wheel             zoom by kZoomPerStep per notch (up: larger), within [kMinZoom, kMaxZoom]
//   [ / ]             focal plane: ] brings the zero-parallax plane kFocalStepRadii scene
//                     radii nearer the viewer (the scene moves back), [ the other way
//   - / =             depthiness (view-cone scale) down / up by kDepthinessStep, within
//                     [0, maxDepthiness]: 0 is flat, 1 the profile's cone
//   T                 turntable on/off, keeping the current angle (no jump)
//   Home, Backspace   reset to the start-up state (the command line's values)
#pragma once

#include "frame.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace lfd::player {

inline constexpr double kOrbitDegPerPixel = 0.3;
inline constexpr double kMaxPitchDeg = 89.0;
inline constexpr double kZoomPerStep = 1.1;
inline constexpr double kMinZoom = 0.1;
inline constexpr double kMaxZoom = 10.0;
inline constexpr double kFocalStepRadii = 0.1;
inline constexpr double kDepthinessStep = 0.1;
// The scaled cone must stay below this (cameras at D tan(cone / 2) run off to infinity at 180).
inline constexpr double kMaxScaledConeDeg = 170.0;

// Largest depthiness for a profile's cone: min(4, kMaxScaledConeDeg / cone).
double maxDepthiness(double viewConeDeg);

// Throws std::invalid_argument naming the flag (--zoom, --depthiness, --orbit, ...) when a
// value is out of range or not finite.
void validateViewControls(const ViewControls& controls, double viewConeDeg);

// "A,B" -> (A, B) for --orbit and --pan; nullopt when not two finite numbers.
std::optional<glm::dvec2> parseNumberPair(const std::string& text);

class CameraControls {
public:
    // `sceneRadiusMm`: the fitted scene's radius on the display (focal-plane step size).
    CameraControls(const ViewControls& initial, double sceneRadiusMm, double viewConeDeg);

    const ViewControls& state() const { return state_; }

    void orbit(double dxPixels, double dyPixels);
    // Window y runs down, display y up: the scene follows the cursor.
    void pan(double dxPixels, double dyPixels, double mmPerPixel);
    void zoom(double wheelSteps);
    void moveFocalPlane(int steps);
    void changeDepthiness(int steps);
    // `currentTurntableRad`: the angle the turntable has now (turntableAngle(time, period)).
    // Off: that angle moves into the yaw; on: the yaw gives it back, so nothing jumps.
    void toggleTurntable(double currentTurntableRad);
    void reset() { state_ = initial_; }

    // Interaction clock for the responsive preview: input at `now` seconds keeps
    // interacting(now') true while now' - now < holdSeconds.
    void noteInput(double now) { lastInput_ = now; }
    bool interacting(double now, double holdSeconds) const { return now - lastInput_ < holdSeconds; }

private:
    ViewControls initial_, state_;
    double focalStepMm_, maxDepthiness_;
    double lastInput_ = -1e300;
};

} // namespace lfd::player
