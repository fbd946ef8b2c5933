#include "camera_controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace lfd::player {

namespace {

// Yaw in (-180, 180], so hours of turning keep full precision.
double wrapDegrees(double deg)
{
    deg = std::fmod(deg, 360.0);
    if (deg > 180.0)
        deg -= 360.0;
    if (deg <= -180.0)
        deg += 360.0;
    return deg;
}

void requireFinite(const char* flag, double value)
{
    if (!std::isfinite(value))
        throw std::invalid_argument(std::string(flag) + ": must be a finite number");
}

} // namespace

double maxDepthiness(double viewConeDeg)
{
    return viewConeDeg > 0.0 ? std::min(4.0, kMaxScaledConeDeg / viewConeDeg) : 4.0;
}

void validateViewControls(const ViewControls& c, double viewConeDeg)
{
    requireFinite("--orbit", c.yawDeg);
    requireFinite("--orbit", c.pitchDeg);
    requireFinite("--pan", c.panMm.x);
    requireFinite("--pan", c.panMm.y);
    requireFinite("--focal-depth", c.focalDepthMm);
    char text[160];
    if (!(c.zoom >= kMinZoom && c.zoom <= kMaxZoom)) {
        std::snprintf(text, sizeof(text), "--zoom: expected %g..%g", kMinZoom, kMaxZoom);
        throw std::invalid_argument(text);
    }
    if (!(std::abs(c.pitchDeg) <= kMaxPitchDeg))
        throw std::invalid_argument("--orbit: pitch must be within +-" + std::to_string(int(kMaxPitchDeg)) + " degrees");
    const double maxD = maxDepthiness(viewConeDeg);
    if (!(c.depthiness >= 0.0 && c.depthiness <= maxD)) {
        std::snprintf(text, sizeof(text), "--depthiness: expected 0..%.2f for a %.1f degree view cone", maxD,
                      viewConeDeg);
        throw std::invalid_argument(text);
    }
}

std::optional<glm::dvec2> parseNumberPair(const std::string& text)
{
    const size_t comma = text.find(',');
    if (comma == std::string::npos)
        return std::nullopt;
    try {
        size_t usedA = 0, usedB = 0;
        const std::string a = text.substr(0, comma), b = text.substr(comma + 1);
        const double x = std::stod(a, &usedA), y = std::stod(b, &usedB);
        if (usedA != a.size() || usedB != b.size() || !std::isfinite(x) || !std::isfinite(y))
            return std::nullopt;
        return glm::dvec2(x, y);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

CameraControls::CameraControls(const ViewControls& initial, double sceneRadiusMm, double viewConeDeg)
    : initial_(initial), state_(initial), focalStepMm_(kFocalStepRadii * sceneRadiusMm),
      maxDepthiness_(maxDepthiness(viewConeDeg))
{
}

void CameraControls::orbit(double dxPixels, double dyPixels)
{
    state_.yawDeg = wrapDegrees(state_.yawDeg + kOrbitDegPerPixel * dxPixels);
    state_.pitchDeg = std::clamp(state_.pitchDeg + kOrbitDegPerPixel * dyPixels, -kMaxPitchDeg, kMaxPitchDeg);
}

void CameraControls::pan(double dxPixels, double dyPixels, double mmPerPixel)
{
    state_.panMm += glm::dvec2(dxPixels, -dyPixels) * mmPerPixel;
}

void CameraControls::zoom(double wheelSteps)
{
    state_.zoom = std::clamp(state_.zoom * std::pow(kZoomPerStep, wheelSteps), kMinZoom, kMaxZoom);
}

void CameraControls::moveFocalPlane(int steps)
{
    state_.focalDepthMm += steps * focalStepMm_;
}

void CameraControls::changeDepthiness(int steps)
{
    // Rounded to the step grid so repeated presses land on 0.9, 1.0, 1.1 exactly.
    const double d = std::round((state_.depthiness + steps * kDepthinessStep) / kDepthinessStep) * kDepthinessStep;
    state_.depthiness = std::clamp(d, 0.0, maxDepthiness_);
}

void CameraControls::toggleTurntable(double currentTurntableRad)
{
    const double currentDeg = currentTurntableRad * 180.0 / std::numbers::pi;
    state_.yawDeg = wrapDegrees(state_.yawDeg + (state_.turntable ? currentDeg : -currentDeg));
    state_.turntable = !state_.turntable;
}

} // namespace lfd::player
