// The split-sum table against an independent integration (a midpoint rule over the
// hemisphere in cos(theta) and phi, no importance sampling), its known limits, its layout
// and GL_LINEAR reads.
#include "brdf.h"
#include "brdf_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lfd::lighting {
namespace {

constexpr double kPi = std::numbers::pi;

// (A, B, C) by brute force: every cell of an n x n grid in (cos theta, phi) has the same
// solid angle 2 pi / n^2.
glm::dvec3 bruteForceTerms(float nDotV, float roughness, int n)
{
    const float alpha = alphaFromRoughness(roughness);
    const glm::vec3 v(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const double cosTheta = (i + 0.5) / n, sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        for (int j = 0; j < n; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / n;
            const glm::vec3 l(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
            const glm::vec3 h = glm::normalize(v + l);
            const double fc = schlickWeight(std::max(glm::dot(v, h), 0.0f));
            const double specular = double(ggxDistribution(h.z, alpha)) * smithVisibility(l.z, nDotV, alpha) * l.z;
            sum += glm::dvec3((1.0 - fc) * specular, fc * specular, fc * l.z / kPi);
        }
    }
    return sum * (2.0 * kPi / (double(n) * n));
}

TEST(BrdfTable, MatchesABruteForceIntegration)
{
    for (const auto& [nDotV, roughness] : {std::pair{0.9f, 0.5f}, std::pair{0.3f, 0.8f}, std::pair{0.6f, 0.3f},
                                           std::pair{0.15f, 1.0f}}) {
        const glm::vec3 table = splitSumTerms(nDotV, roughness, 4096);
        const glm::dvec3 brute = bruteForceTerms(nDotV, roughness, 1500);
        EXPECT_NEAR(table.x, brute.x, 0.004) << nDotV << " " << roughness;
        EXPECT_NEAR(table.y, brute.y, 0.002) << nDotV << " " << roughness;
        EXPECT_NEAR(table.z, brute.z, 0.002) << nDotV << " " << roughness;
    }
}

TEST(BrdfTable, KnownLimits)
{
    // A mirror seen head-on reflects everything (A -> 1) with no Fresnel rise (B -> 0).
    const glm::vec3 mirror = splitSumTerms(1.0f, 0.0f, 1024);
    EXPECT_NEAR(mirror.x, 1.0f, 1e-3f);
    EXPECT_NEAR(mirror.y, 0.0f, 1e-4f);
    // C at n.v = 1: (1/pi) integral of (1 - cos(theta / 2))^5 cos(theta) over the hemisphere
    // (h halves the angle between v = n and l), by a 1D midpoint rule.
    double c = 0.0;
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) / steps * kPi / 2.0;
        c += std::pow(1.0 - std::cos(theta / 2.0), 5.0) * std::cos(theta) * std::sin(theta);
    }
    c *= 2.0 * (kPi / 2.0) / steps;
    EXPECT_NEAR(mirror.z, c, 1e-4);
    // C does not depend on roughness.
    EXPECT_FLOAT_EQ(splitSumTerms(0.4f, 0.1f, 256).z, splitSumTerms(0.4f, 0.9f, 256).z);
}

TEST(BrdfTable, NeverCreatesEnergy)
{
    const BrdfTable table = splitSumBrdfTable(16, 256);
    for (uint32_t row = 0; row < 16; ++row)
        for (uint32_t column = 0; column < 16; ++column) {
            const glm::vec3 t = table.texel(column, row);
            EXPECT_GE(t.x, 0.0f);
            EXPECT_GE(t.y, 0.0f);
            EXPECT_LE(t.x + t.y, 1.0f + 2e-3f) << column << "," << row;
            EXPECT_LE(t.z, 1.0f);
        }
    // Head-on, rougher surfaces lose more to masking and shadowing.
    EXPECT_GT(table.texel(15, 4).x + table.texel(15, 4).y, table.texel(15, 15).x + table.texel(15, 15).y);
}

TEST(BrdfTable, LayoutAndLinearReads)
{
    const uint32_t size = 8;
    const BrdfTable table = splitSumBrdfTable(size, 128);
    ASSERT_EQ(table.abc.size(), size_t(size * size * 3));
    // Texel (column i, row j) holds n.v = i / 7, roughness = j / 7; column 0 at the n.v floor.
    const glm::vec3 t = table.texel(3, 5);
    const glm::vec3 direct = splitSumTerms(3.0f / 7.0f, 5.0f / 7.0f, 128);
    EXPECT_FLOAT_EQ(t.x, direct.x);
    EXPECT_FLOAT_EQ(t.z, direct.z);
    EXPECT_FLOAT_EQ(table.texel(0, 2).y, splitSumTerms(kMinNDotV, 2.0f / 7.0f, 128).y);
    // The texture coordinate puts those values at texel centres: (x * 7 + 0.5) / 8.
    EXPECT_FLOAT_EQ(brdfTableCoordinate(0.0f, 1.0f, size).x, 0.5f / 8.0f);
    EXPECT_FLOAT_EQ(brdfTableCoordinate(0.0f, 1.0f, size).y, 7.5f / 8.0f);
    EXPECT_FLOAT_EQ(brdfTableCoordinate(3.0f / 7.0f, 0.5f, size).x, 3.5f / 8.0f);
    // GL_LINEAR reads: a texel's own value at its point, the mean halfway between two.
    EXPECT_FLOAT_EQ(sampleBrdfTable(table, 3.0f / 7.0f, 5.0f / 7.0f).x, t.x);
    const glm::vec3 half = sampleBrdfTable(table, 3.5f / 7.0f, 5.0f / 7.0f);
    EXPECT_NEAR(half.y, 0.5f * (table.texel(3, 5).y + table.texel(4, 5).y), 1e-6f);
    // Outside [0, 1] the read clamps to the edge.
    EXPECT_FLOAT_EQ(sampleBrdfTable(table, 1.5f, -1.0f).x, table.texel(7, 0).x);
    EXPECT_THROW(splitSumBrdfTable(1, 16), std::invalid_argument);
}

} // namespace
} // namespace lfd::lighting
