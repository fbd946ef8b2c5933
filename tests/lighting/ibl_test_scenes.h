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

// The pixels of a unit sphere seen from +Z by an orthographic camera (view direction
// v = +Z for every pixel), `pixels` across: calls visit(n) for each pixel centre on the
// sphere with n.v >= minNDotV.
void forEachSpherePixel(uint32_t pixels, float minNDotV, const std::function<void(glm::vec3 n)>& visit);

} // namespace lfd::lighting
