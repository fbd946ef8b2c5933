// The Monte Carlo reference: white furnaces against the split-sum table (for a constant
// environment the split sum is exact), determinism, convergence under a sun, and the
// environment distribution it samples lights from.
#include "brdf_table.h"
#include "ibl_test_scenes.h"
#include "reference_ibl.h"
#include "tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lfd::lighting {
namespace {

glm::vec3 tilted(float nDotV)
{
    return {std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV};
}

TEST(ReferenceIbl, WhiteFurnaceMetalIsTheTablesAPlusB)
{
    // F0 = 1: F = 1, so the integral of f (n.l) against L = 1 is the specular lobe's energy.
    const Environment furnace = constantEnvironment(glm::vec3(1.0f));
    const EnvironmentDistribution distribution(furnace);
    for (const float roughness : {0.05f, 0.5f, 1.0f})
        for (const float nDotV : {1.0f, 0.6f, 0.2f}) {
            const glm::vec3 n(0, 0, 1), v = tilted(nDotV);
            const glm::vec3 reference = referenceIbl(furnace, distribution, {glm::vec3(1.0f), 1.0f, roughness}, n, v, 2048, 1);
            const glm::vec3 terms = splitSumTerms(nDotV, roughness, 8192);
            EXPECT_NEAR(reference.g, terms.x + terms.y, 0.003f) << roughness << " " << nDotV;
        }
}

TEST(ReferenceIbl, WhiteFurnaceDielectricIsSpecularPlusFresnelWeightedLambert)
{
    // F0 = 0.04: 0.04 A + B from the specular lobe, (1 - 0.04)(1 - C) from the diffuse one.
    const Environment furnace = constantEnvironment(glm::vec3(1.0f));
    const EnvironmentDistribution distribution(furnace);
    for (const float roughness : {0.05f, 0.5f, 1.0f})
        for (const float nDotV : {0.9f, 0.3f}) {
            const glm::vec3 reference =
                referenceIbl(furnace, distribution, {glm::vec3(1.0f), 0.0f, roughness}, {0, 0, 1}, tilted(nDotV), 2048, 2);
            const glm::vec3 t = splitSumTerms(nDotV, roughness, 8192);
            EXPECT_NEAR(reference.r, 0.04f * t.x + t.y + 0.96f * (1.0f - t.z), 0.004f) << roughness << " " << nDotV;
        }
}

TEST(ReferenceIbl, DeterministicPerSeedAndConvergedUnderASun)
{
    const Environment sky = sunAndSkyEnvironment();
    const EnvironmentDistribution distribution(sky);
    const PbrMaterial material{{0.9f, 0.35f, 0.1f}, 0.0f, 0.5f};
    const glm::vec3 v(0, 0, 1);
    for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.4f, 0.6f, 0.7f)),
                              glm::normalize(glm::vec3(-0.7f, -0.2f, 0.6f))}) {
        const glm::vec3 a = referenceIbl(sky, distribution, material, n, v, 512, 7);
        EXPECT_EQ(a, referenceIbl(sky, distribution, material, n, v, 512, 7));
        // 512 points per strategy are within one display level of 8 times as many.
        const auto coarse = displayLevels(a, 0.0f);
        const auto fine = displayLevels(referenceIbl(sky, distribution, material, n, v, 4096, 8), 0.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(std::abs(int(coarse[size_t(c)]) - int(fine[size_t(c)])), 1) << c;
    }
}

TEST(EnvironmentDistribution, DensityIntegratesToOneAndFollowsTheSun)
{
    const Environment sky = sunAndSkyEnvironment();
    const EnvironmentDistribution distribution(sky);
    const double pi = std::numbers::pi;
    double total = 0.0;
    for (uint32_t y = 0; y < sky.height; ++y) {
        const double solidAngle = 2.0 * pi / sky.width * pi / sky.height * std::sin(pi * (y + 0.5) / sky.height);
        for (uint32_t x = 0; x < sky.width; ++x)
            total += distribution.pdf({(float(x) + 0.5f) / float(sky.width), (float(y) + 0.5f) / float(sky.height)}) * solidAngle;
    }
    EXPECT_NEAR(total, 1.0, 1e-3);
    // The sun holds about half the light: about half the samples land within 3 degrees of it,
    // each with the density pdf() gives for its direction.
    int nearSun = 0;
    const int samples = 4096;
    for (int i = 0; i < samples; ++i) {
        const EnvironmentDistribution::Sample s =
            distribution.sample({(float(i) + 0.5f) / float(samples), std::fmod(float(i) * 0.618034f, 1.0f)});
        EXPECT_FLOAT_EQ(s.pdf, distribution.pdf(s.uv));
        EXPECT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
        nearSun += glm::dot(s.direction, sunDirection()) > std::cos(3.0f * float(pi) / 180.0f);
    }
    EXPECT_GT(nearSun, samples * 4 / 10);
    EXPECT_LT(nearSun, samples * 8 / 10);
}

TEST(EnvironmentDistribution, BlackEnvironmentIsSampledBySolidAngle)
{
    const EnvironmentDistribution distribution(constantEnvironment(glm::vec3(0.0f), 64, 32));
    for (const glm::vec2 uv : {glm::vec2(0.3f, 0.5f), glm::vec2(0.9f, 0.2f)})
        EXPECT_NEAR(distribution.pdf(uv), 1.0 / (4.0 * std::numbers::pi), 2e-3);
}

} // namespace
} // namespace lfd::lighting
