// Environments and views the lighting tests share: a constant (furnace) environment, a
// high-contrast sun and sky, and a sphere seen by an orthographic camera.
#pragma once

#include "environment.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>

namespace lfd::lighting {

// Every texel `radiance`.
Environment constantEnvironment(glm::vec3 radiance, uint32_t width = 64, uint32_t height = 32);

// A clear sky (horizon (0.45, 0.5, 0.55) to zenith (0.12, 0.22, 0.45), ground (0.12, 0.1,
// 0.08)) and a sun 40 degrees up, 30 degrees from +Z towards +X, a disk of 1.5 degrees
// radius (0.3 degree soft edge) and radiance (2000, 1900, 1700): its irradiance, about 4.3
// at normal incidence, is 4 to 5 times the sky's. 1024 x 512.
Environment sunAndSkyEnvironment();

// The sun's direction in sunAndSkyEnvironment.
glm::vec3 sunDirection();

// Validation environments for the split sum (ibl_accuracy_test), never used to choose its
// method: 10 soft disks of 3 to 30 degrees radius and radiance 0.5 to 8.5 (tinted, edges
// blended over 15 to 65% of the radius) at directions drawn from `seed` (std::mt19937,
// portable: the raw 32-bit output, not a distribution), over a gradient sky (0.3 at the
// horizon to 0.1 at the zenith, bluish) and a darker ground. 1024 x 512.
Environment softLightsEnvironment(uint32_t seed);
// A procedural outdoor scene: a blue sky gradient with bright cloud bands, a hazy sun glow
// (no disk: 6 x cos^64 plus a wide cos^6 halo) 28 degrees up, a dark tree line along the
// horizon and a textured ground. 1024 x 512.
Environment outdoorEnvironment();

// The pixels of a unit sphere seen from +Z by an orthographic camera (view direction
// v = +Z for every pixel), `pixels` across: calls visit(n) for each pixel centre on the
// sphere with n.v >= minNDotV.
void forEachSpherePixel(uint32_t pixels, float minNDotV, const std::function<void(glm::vec3 n)>& visit);

} // namespace lfd::lighting
