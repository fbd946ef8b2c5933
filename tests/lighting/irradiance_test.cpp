// Diffuse irradiance E / pi as SH9 and as a small cube: furnace, an environment linear in
// the direction (whose E / pi SH9 represents exactly), the polynomial's form, and SH9's
// ringing under a point-like source, which the cube does not have.
#include "irradiance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace lfd::lighting {
namespace {

CubeLevel cubeOf(uint32_t size, const std::function<glm::vec3(glm::vec3)>& radiance)
{
    CubeLevel level(size);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                level.setTexel(face, x, y, radiance(cubeTexelDirection(face, x, y, size)));
    return level;
}

std::vector<glm::vec3> testNormals()
{
    std::vector<glm::vec3> normals;
    for (int i = 0; i < 200; ++i) {
        const float z = 1.0f - 2.0f * (float(i) + 0.5f) / 200.0f, phi = 2.39996323f * float(i);
        const float r = std::sqrt(1.0f - z * z);
        normals.emplace_back(r * std::cos(phi), z, r * std::sin(phi));
    }
    return normals;
}

TEST(Irradiance, FurnaceGivesTheRadianceBack)
{
    const glm::vec3 radiance(0.25f, 1.0f, 4.0f);
    const CubeLevel source = cubeOf(16, [&](glm::vec3) { return radiance; });
    const ShIrradiance sh = shIrradianceFromCube(source);
    const CubeLevel cube = irradianceCubeFromCube(source, 8);
    for (const glm::vec3 n : testNormals()) {
        const glm::vec3 a = irradianceSh(sh, n), b = sampleCubeBilinear(cube, n);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a[c], radiance[c], 1e-3f * radiance[c]);
            EXPECT_NEAR(b[c], radiance[c], 1e-5f * radiance[c]);
        }
    }
}

TEST(Irradiance, LinearEnvironmentIsExact)
{
    // L(d) = a + b (d.w): E / pi = a + (2/3) b (n.w) (the clamped cosine's band-1 factor).
    const glm::vec3 w = glm::normalize(glm::vec3(1, 2, 3));
    const float a = 1.0f, b = 0.5f;
    const CubeLevel source = cubeOf(32, [&](glm::vec3 d) { return glm::vec3(a + b * glm::dot(d, w)); });
    const ShIrradiance sh = shIrradianceFromCube(source);
    const CubeLevel cube = irradianceCubeFromCube(source, 32);
    for (const glm::vec3 n : testNormals()) {
        const float expected = a + 2.0f / 3.0f * b * glm::dot(n, w);
        EXPECT_NEAR(irradianceSh(sh, n).g, expected, 1e-3f);
        EXPECT_NEAR(sampleCubeBilinear(cube, n).g, expected, 2e-3f);
    }
}

TEST(Irradiance, ShPolynomialTerms)
{
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
    const float expected[9] = {1.0f,          n.y,           n.z,       n.x,
                               n.x * n.y,     n.y * n.z,     3.0f * n.z * n.z - 1.0f,
                               n.x * n.z,     n.x * n.x - n.y * n.y};
    for (size_t i = 0; i < 9; ++i) {
        ShIrradiance k{};
        k[i] = glm::vec3(1.0f, 2.0f, 0.0f);
        EXPECT_FLOAT_EQ(irradianceSh(k, n).r, expected[i]) << i;
        EXPECT_FLOAT_EQ(irradianceSh(k, n).g, 2.0f * expected[i]) << i;
    }
}

TEST(Irradiance, ShRingsUnderAPointSourceTheCubeDoesNot)
{
    // One bright texel: bands 0..2 of the clamped cosine are 1/4 + x/2 + 5/32 (3x^2 - 1),
    // 1/16 at the far side against 17/16 facing it (Ramamoorthi & Hanrahan 2001).
    CubeLevel source(32);
    source.setTexel(4, 16, 16, glm::vec3(1000.0f));
    const glm::vec3 towards = cubeTexelDirection(4, 16, 16, 32);
    const ShIrradiance sh = shIrradianceFromCube(source);
    const float facing = irradianceSh(sh, towards).r, away = irradianceSh(sh, -towards).r;
    EXPECT_NEAR(away / facing, 1.0f / 17.0f, 0.002f);
    const CubeLevel cube = irradianceCubeFromCube(source, 16);
    EXPECT_EQ(sampleCubeBilinear(cube, -towards).r, 0.0f);
    EXPECT_GT(sampleCubeBilinear(cube, towards).r, 0.0f);
}

} // namespace
} // namespace lfd::lighting
