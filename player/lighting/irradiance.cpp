// Diffuse irradiance as SH9 and as a small cube; see irradiance.h.
#include "irradiance.h"

#include "cube_convolution.h"

#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {


// The nine polynomials of the real SH basis, bands 0..2 (Ramamoorthi & Hanrahan 2001,
// eq. 3, without their constants).
std::array<double, 9> shPolynomials(glm::dvec3 d)
{
    return {1.0, d.y, d.z, d.x, d.x * d.y, d.y * d.z, 3.0 * d.z * d.z - 1.0, d.x * d.z, d.x * d.x - d.y * d.y};
}

// Per coefficient: the basis constant squared (projection and evaluation each carry one)
// times the clamped cosine's band factor A_l / pi (1, 2/3, 1/4; R&H 2001, eq. 8).
std::array<double, 9> shWeights()
{
    using std::numbers::pi;
    const double y0 = 0.5 * std::sqrt(1.0 / pi), y1 = std::sqrt(3.0 / (4.0 * pi));
    const double y2 = 0.5 * std::sqrt(15.0 / pi), y20 = 0.25 * std::sqrt(5.0 / pi), y22 = 0.25 * std::sqrt(15.0 / pi);
    const double a1 = 2.0 / 3.0, a2 = 0.25;
    return {y0 * y0,      a1 * y1 * y1,   a1 * y1 * y1, a1 * y1 * y1,  a2 * y2 * y2,
            a2 * y2 * y2, a2 * y20 * y20, a2 * y2 * y2, a2 * y22 * y22};
}

} // namespace

ShIrradiance shIrradianceFromCube(const CubeLevel& radiance)
{
    // Project: sum over texels of L Y_i omega (the polynomial part of Y_i here, its
    // constant in shWeights).
    std::array<glm::dvec3, 9> sums{};
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < radiance.size; ++y)
            for (uint32_t x = 0; x < radiance.size; ++x) {
                const glm::dvec3 weighted =
                    glm::dvec3(radiance.texel(face, x, y)) * cubeTexelSolidAngle(x, y, radiance.size);
                const std::array<double, 9> p = shPolynomials(glm::dvec3(cubeTexelDirection(face, x, y, radiance.size)));
                for (size_t i = 0; i < 9; ++i)
                    sums[i] += p[i] * weighted;
            }
    const std::array<double, 9> w = shWeights();
    ShIrradiance k;
    for (size_t i = 0; i < 9; ++i)
        k[i] = glm::vec3(sums[i] * w[i]);
    return k;
}

glm::vec3 irradianceSh(const ShIrradiance& k, glm::vec3 n)
{
    return k[0] + k[1] * n.y + k[2] * n.z + k[3] * n.x + k[4] * (n.x * n.y) + k[5] * (n.y * n.z) +
           k[6] * (3.0f * n.z * n.z - 1.0f) + k[7] * (n.x * n.z) + k[8] * (n.x * n.x - n.y * n.y);
}

CubeLevel irradianceCubeFromCube(const CubeLevel& radiance, uint32_t size)
{
    // Normalised by the sum of cos omega (pi, up to the texels' discretisation): E / pi.
    return convolveCube(radiance, size, [](double cosine) { return cosine; });
}

} // namespace lfd::lighting
