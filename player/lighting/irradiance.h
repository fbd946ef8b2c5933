// Diffuse irradiance of an environment, E(n) = integral of L(l) max(n.l, 0) dl, divided by
// pi (so a constant environment L gives E / pi = L and a white Lambert surface reflects
// E / pi), in two forms the shader can read:
//
// * SH9 (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance
//   Environment Maps"): the radiance projected on the real spherical harmonics of bands
//   0..2, each band scaled by the clamped cosine's A_l / pi (1, 2/3, 1/4) and by its basis
//   constant squared, so the shader evaluates a plain polynomial of the unit normal n:
//     E/pi = k0 + k1 y + k2 z + k3 x + k4 xy + k5 yz + k6 (3z^2 - 1) + k7 xz + k8 (x^2 - y^2)
//   (nine vec3 in a uniform block, no fetch). Band 2 cannot follow a small bright source:
//   for a distant point source the clamped cosine's bands 0..2 are 1/4 + x/2 + 5/32 (3x^2 - 1)
//   of x = cos(angle), off by 3/32 (9.4%) of the source's peak at its terminator and 1/16
//   on the far side, so under a sun the dark side gets light it should not.
// * a small cube (GL_LINEAR, seamless, no mips): E/pi summed exactly over the texels of a
//   coarse level of the environment's cube, per texel centre (cube_convolution.h).
#pragma once

#include "cube_map.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>

namespace lfd::lighting {

using ShIrradiance = std::array<glm::vec3, 9>; // k0..k8 of the polynomial above

// E/pi of the radiance cube level `radiance` (each texel a constant over its exact solid
// angle), as the polynomial's coefficients.
ShIrradiance shIrradianceFromCube(const CubeLevel& radiance);
// The polynomial at the unit normal n: E(n)/pi.
glm::vec3 irradianceSh(const ShIrradiance& k, glm::vec3 n);

// A cube of face `size` whose texel centres hold E/pi of `radiance`: the cosine-weighted
// mean of its texels; rows run on every core.
CubeLevel irradianceCubeFromCube(const CubeLevel& radiance, uint32_t size);

} // namespace lfd::lighting
