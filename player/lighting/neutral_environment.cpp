// The neutral studio's geometry and radiances; see neutral_environment.h.
#include "neutral_environment.h"

#include "parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180.0f;

// A flat rectangular light seen from the centre: inside where the gnomonic coordinates
// (d.right / d.forward, d.up / d.forward) lie within tan(halfWidth) x tan(halfHeight),
// with edges blended over +-kSoftEdge degrees of angle.
struct Softbox {
    float azimuthDegrees;   // around +Y, 0 = +Z (towards the default camera), 90 = +X
    float elevationDegrees; // above the horizon
    float halfWidthDegrees;
    float halfHeightDegrees;
    float radiance;
};

constexpr float kSoftEdgeDegrees = 6.0f;

// Key (upper left of the camera), fill strip (low right), rim (high behind). With the room
// below, a white Lambert surface facing up sees E / pi = 0.636, sRGB level 203 after PBR
// Neutral at exposure 0 (test NeutralStudio.WhiteLambertFacingUpLandsNearLevel200).
constexpr std::array<Softbox, 3> kSoftboxes = {{
    {-45.0f, 35.0f, 22.0f, 14.0f, 3.0f},
    {60.0f, 10.0f, 8.0f, 24.0f, 3.0f},
    {180.0f, 55.0f, 28.0f, 8.0f, 3.0f},
}};

// The room: floor radiance, wall radiance at the horizon, ceiling radiance at the zenith,
// and the horizon's blend half-width.
constexpr float kFloor = 0.06f;
constexpr float kWall = 0.12f;
constexpr float kCeiling = 0.25f;
constexpr float kHorizonDegrees = 4.0f;

float smoothStep(float edge0, float edge1, float x)
{
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float softboxRadiance(const Softbox& box, glm::vec3 d)
{
    const float azimuth = box.azimuthDegrees * kDegree, elevation = box.elevationDegrees * kDegree;
    const glm::vec3 forward(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                            std::cos(elevation) * std::cos(azimuth));
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    const float z = glm::dot(d, forward);
    if (z <= 0.0f)
        return 0.0f;
    const float across = std::atan(std::abs(glm::dot(d, right)) / z) / kDegree;
    const float along = std::atan(std::abs(glm::dot(d, up)) / z) / kDegree;
    const auto inside = [](float angle, float half) {
        return 1.0f - smoothStep(half - kSoftEdgeDegrees, half + kSoftEdgeDegrees, angle);
    };
    return box.radiance * inside(across, box.halfWidthDegrees) * inside(along, box.halfHeightDegrees);
}

float roomRadiance(glm::vec3 d)
{
    const float elevation = std::asin(std::clamp(d.y, -1.0f, 1.0f)) / kDegree;
    const float walls = kWall + (kCeiling - kWall) * std::max(d.y, 0.0f);
    return kFloor + (walls - kFloor) * smoothStep(-kHorizonDegrees, kHorizonDegrees, elevation);
}

} // namespace

Environment neutralEnvironment()
{
    Environment environment;
    environment.width = kNeutralEnvironmentWidth;
    environment.height = kNeutralEnvironmentHeight;
    environment.rgb.resize(size_t(environment.width) * environment.height * 3);
    forEachBand(environment.height, 8, [&](size_t, size_t begin, size_t end) {
        for (size_t y = begin; y < end; ++y)
            for (uint32_t x = 0; x < environment.width; ++x) {
                const glm::vec3 d = directionFromEquirect(
                    {(float(x) + 0.5f) / float(environment.width), (float(y) + 0.5f) / float(environment.height)});
                float radiance = roomRadiance(d);
                for (const Softbox& box : kSoftboxes)
                    radiance += softboxRadiance(box, d);
                float* out = environment.rgb.data() + (y * environment.width + x) * 3;
                out[0] = out[1] = out[2] = radiance;
            }
    });
    return environment;
}

} // namespace lfd::lighting
