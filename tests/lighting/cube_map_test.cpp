// Cube maps in GL's convention (OpenGL 4.5 table 8.19): directions per face against
// hand-worked values, round trips, exact texel solid angles, seamless bilinear filtering
// across an edge, trilinear levels and box halving.
#include "cube_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lfd::lighting {
namespace {

void expectDirection(glm::vec3 actual, glm::vec3 expected)
{
    expected = glm::normalize(expected);
    EXPECT_NEAR(actual.x, expected.x, 1e-6f);
    EXPECT_NEAR(actual.y, expected.y, 1e-6f);
    EXPECT_NEAR(actual.z, expected.z, 1e-6f);
}

TEST(CubeMap, FaceCentresAreTheAxesInGlOrder)
{
    expectDirection(cubeDirection(0, 0.5f, 0.5f), {1, 0, 0});
    expectDirection(cubeDirection(1, 0.5f, 0.5f), {-1, 0, 0});
    expectDirection(cubeDirection(2, 0.5f, 0.5f), {0, 1, 0});
    expectDirection(cubeDirection(3, 0.5f, 0.5f), {0, -1, 0});
    expectDirection(cubeDirection(4, 0.5f, 0.5f), {0, 0, 1});
    expectDirection(cubeDirection(5, 0.5f, 0.5f), {0, 0, -1});
}

TEST(CubeMap, FaceCornersAsTable819WorksThemOut)
{
    // (s, t) = (0, 0) is sc = tc = -1; (1, 0) is sc = +1, tc = -1. From table 8.19:
    // +X: sc = -rz, tc = -ry   -X: sc = rz, tc = -ry   +Y: sc = rx, tc = rz
    // -Y: sc = rx, tc = -rz    +Z: sc = rx, tc = -ry   -Z: sc = -rx, tc = -ry
    expectDirection(cubeDirection(0, 0, 0), {1, 1, 1});
    expectDirection(cubeDirection(0, 1, 0), {1, 1, -1});
    expectDirection(cubeDirection(1, 0, 0), {-1, 1, -1});
    expectDirection(cubeDirection(1, 1, 0), {-1, 1, 1});
    expectDirection(cubeDirection(2, 0, 0), {-1, 1, -1});
    expectDirection(cubeDirection(2, 1, 1), {1, 1, 1});
    expectDirection(cubeDirection(3, 0, 0), {-1, -1, 1});
    expectDirection(cubeDirection(3, 1, 1), {1, -1, -1});
    expectDirection(cubeDirection(4, 0, 0), {-1, 1, 1});
    expectDirection(cubeDirection(4, 1, 0), {1, 1, 1});
    expectDirection(cubeDirection(5, 0, 0), {1, 1, -1});
    expectDirection(cubeDirection(5, 1, 0), {-1, 1, -1});
    // A point off the diagonals: +Z face, s = 0.75, t = 0.25 -> sc = 0.5, tc = -0.5.
    expectDirection(cubeDirection(4, 0.75f, 0.25f), {0.5f, 0.5f, 1});
    EXPECT_THROW(cubeDirection(6, 0.5f, 0.5f), std::invalid_argument);
}

TEST(CubeMap, CoordinateFromDirectionInvertsCubeDirection)
{
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (float s = 0.05f; s < 1.0f; s += 0.1f)
            for (float t = 0.05f; t < 1.0f; t += 0.1f) {
                const CubeCoordinate c = cubeCoordinateFromDirection(cubeDirection(face, s, t) * 3.0f);
                ASSERT_EQ(c.face, face);
                EXPECT_NEAR(c.s, s, 1e-6f);
                EXPECT_NEAR(c.t, t, 1e-6f);
            }
    // Hand-worked: (2, -1, 0.5) has major axis +X, sc = -0.5 / 2, tc = 1 / 2.
    const CubeCoordinate c = cubeCoordinateFromDirection({2.0f, -1.0f, 0.5f});
    EXPECT_EQ(c.face, 0u);
    EXPECT_FLOAT_EQ(c.s, 0.5f * (-0.25f + 1.0f));
    EXPECT_FLOAT_EQ(c.t, 0.5f * (0.5f + 1.0f));
}

TEST(CubeMap, TexelSolidAnglesSumToTheSphere)
{
    for (uint32_t size : {1u, 3u, 16u}) {
        double sum = 0.0;
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                sum += 6.0 * cubeTexelSolidAngle(x, y, size);
        EXPECT_NEAR(sum, 4.0 * std::numbers::pi, 1e-12) << size;
    }
    // A 1x1 face is a sixth of the sphere; the centre texel of a big face is about
    // (2 / size)^2 steradians, the corner texel less.
    EXPECT_NEAR(cubeTexelSolidAngle(0, 0, 1), 4.0 * std::numbers::pi / 6.0, 1e-12);
    EXPECT_NEAR(cubeTexelSolidAngle(500, 500, 1000), 4e-6, 1e-9);
    EXPECT_LT(cubeTexelSolidAngle(0, 0, 1000), 0.25 * cubeTexelSolidAngle(500, 500, 1000) * 2.0);
}

TEST(CubeMap, TexelCentresMapBackToTheirTexel)
{
    const uint32_t size = 8;
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                const CubeCoordinate c = cubeCoordinateFromDirection(cubeTexelDirection(face, x, y, size));
                EXPECT_EQ(c.face, face);
                EXPECT_EQ(uint32_t(c.s * size), x);
                EXPECT_EQ(uint32_t(c.t * size), y);
            }
}

TEST(CubeMap, BilinearInsideAFaceInterpolatesTexels)
{
    CubeLevel level(2);
    level.setTexel(4, 0, 0, glm::vec3(1.0f));
    level.setTexel(4, 1, 0, glm::vec3(2.0f));
    level.setTexel(4, 0, 1, glm::vec3(3.0f));
    level.setTexel(4, 1, 1, glm::vec3(4.0f));
    // The +Z face's centre lies between its four texels; a texel centre reads that texel.
    EXPECT_FLOAT_EQ(sampleCubeBilinear(level, {0, 0, 1}).r, 2.5f);
    EXPECT_FLOAT_EQ(sampleCubeBilinear(level, cubeTexelDirection(4, 1, 0, 2)).g, 2.0f);
}

TEST(CubeMap, SeamlessBilinearReadsTheNeighbourFaceAcrossAnEdge)
{
    // On the edge between +X (s = 1) and -Z (s = 0), halfway up: the four taps are +X's
    // last column and -Z's first column, rows 0 and 1, with weights 1/4 each.
    CubeLevel level(2);
    for (uint32_t y = 0; y < 2; ++y) {
        level.setTexel(0, 1, y, glm::vec3(1.0f));
        level.setTexel(5, 0, y, glm::vec3(3.0f));
    }
    EXPECT_FLOAT_EQ(sampleCubeBilinear(level, {1.0f, 0.0f, -1.0f}).r, 2.0f);
    // Just inside +X the -Z texels still contribute (clamp-to-edge would give 1 here).
    const float inside = sampleCubeBilinear(level, {1.0f, 0.0f, -0.9f}).r;
    EXPECT_GT(inside, 1.5f);
    EXPECT_LT(inside, 2.0f);
}

TEST(CubeMap, SeamlessBilinearIsContinuousAroundTheCube)
{
    // Texels hold their centre's direction: the filtered value follows the direction
    // everywhere, edges included, within the bilinear error of a 16-texel face.
    const uint32_t size = 16;
    CubeLevel level(size);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                level.setTexel(face, x, y, cubeTexelDirection(face, x, y, size));
    float worst = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        const float z = 1.0f - 2.0f * (float(i) + 0.5f) / 20000.0f, phi = 2.39996323f * float(i);
        const float r = std::sqrt(1.0f - z * z);
        const glm::vec3 d(r * std::cos(phi), z, r * std::sin(phi));
        worst = std::max(worst, glm::length(sampleCubeBilinear(level, d) - d));
    }
    EXPECT_LT(worst, 0.03f); // a texel is up to 0.125 rad wide; the mix of its neighbours is far closer
}

TEST(CubeMap, TrilinearMixesLevelsAndClampsTheLod)
{
    CubeMap cube;
    cube.levels.emplace_back(2);
    cube.levels.emplace_back(1);
    std::fill(cube.levels[0].rgb.begin(), cube.levels[0].rgb.end(), 1.0f);
    std::fill(cube.levels[1].rgb.begin(), cube.levels[1].rgb.end(), 5.0f);
    const glm::vec3 d(0.3f, -0.2f, 0.9f);
    EXPECT_FLOAT_EQ(sampleCubeTrilinear(cube, d, 0.25f).r, 2.0f);
    EXPECT_FLOAT_EQ(sampleCubeTrilinear(cube, d, -1.0f).r, 1.0f);
    EXPECT_FLOAT_EQ(sampleCubeTrilinear(cube, d, 7.0f).r, 5.0f);
}

TEST(CubeMap, HalvingAveragesTwoByTwoBoxesPerFace)
{
    CubeLevel level(2);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        for (uint32_t i = 0; i < 4; ++i)
            level.setTexel(face, i % 2, i / 2, glm::vec3(float(face * 4 + i)));
    const CubeLevel half = halveCubeLevel(level);
    ASSERT_EQ(half.size, 1u);
    for (uint32_t face = 0; face < kCubeFaces; ++face)
        EXPECT_FLOAT_EQ(half.texel(face, 0, 0).b, float(face * 4) + 1.5f);
    EXPECT_THROW(halveCubeLevel(half), std::logic_error);
}

} // namespace
} // namespace lfd::lighting
