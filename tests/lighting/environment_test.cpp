// The equirectangular convention (Blender / three.js / glTF Sample Viewer: centre column
// +X, u = 0.75 at +Z, row 0 at +Y), its round trip, bilinear reads across the seam and at
// the poles, the rotation flag's direction, box halving and validation.
#include "environment.h"
#include "ibl_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lfd::lighting {
namespace {

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Environment, AxesLandWhereBlenderAndThreeJsPutThem)
{
    // Horizon row (v = 0.5): centre +X, three quarters +Z, one quarter -Z, edges -X.
    expectNear(directionFromEquirect({0.5f, 0.5f}), {1, 0, 0});
    expectNear(directionFromEquirect({0.75f, 0.5f}), {0, 0, 1});
    expectNear(directionFromEquirect({0.25f, 0.5f}), {0, 0, -1});
    expectNear(directionFromEquirect({0.0f, 0.5f}), {-1, 0, 0});
    expectNear(directionFromEquirect({1.0f, 0.5f}), {-1, 0, 0});
    // Row 0 is the zenith, the last row the nadir.
    expectNear(directionFromEquirect({0.3f, 0.0f}), {0, 1, 0});
    expectNear(directionFromEquirect({0.3f, 1.0f}), {0, -1, 0});
    // 45 degrees up, facing +Z.
    const float s = std::sqrt(0.5f);
    expectNear(directionFromEquirect({0.75f, 0.25f}), {0, s, s});

    const glm::vec2 plusZ = equirectFromDirection({0, 0, 2});
    EXPECT_FLOAT_EQ(plusZ.x, 0.75f);
    EXPECT_FLOAT_EQ(plusZ.y, 0.5f);
    const glm::vec2 up = equirectFromDirection({0, 1, 0});
    EXPECT_FLOAT_EQ(up.x, 0.5f); // the pole's azimuth is defined, not NaN
    EXPECT_FLOAT_EQ(up.y, 0.0f);
}

TEST(Environment, TurningRightMovesRightInTheImage)
{
    // Looking along +X with +Y up, +Z is on the right (right-handed), and so is u = 0.75:
    // the panorama is not mirrored when seen from inside.
    const glm::vec3 forward(1, 0, 0), up(0, 1, 0);
    const glm::vec3 right = glm::cross(forward, up);
    EXPECT_GT(equirectFromDirection(glm::normalize(forward + 0.1f * right)).x, 0.5f);
}

TEST(Environment, MappingRoundTrips)
{
    for (float u = 0.01f; u < 1.0f; u += 0.049f)
        for (float v = 0.02f; v < 1.0f; v += 0.047f) {
            const glm::vec2 back = equirectFromDirection(directionFromEquirect({u, v}));
            EXPECT_NEAR(back.x, u, 2e-6f);
            EXPECT_NEAR(back.y, v, 2e-6f);
        }
}

TEST(Environment, BilinearReadsWrapAcrossTheSeamAndClampAtThePoles)
{
    Environment e = constantEnvironment(glm::vec3(0.0f), 4, 2);
    // Column 0 is 1, column 3 is 3: u = 0 (the seam) lies halfway between their centres.
    for (uint32_t y = 0; y < 2; ++y) {
        e.rgb[(y * 4 + 0) * 3] = 1.0f;
        e.rgb[(y * 4 + 3) * 3] = 3.0f;
    }
    EXPECT_FLOAT_EQ(sampleEnvironment(e, directionFromEquirect({0.0f, 0.5f})).r, 2.0f);
    EXPECT_FLOAT_EQ(sampleEnvironment(e, directionFromEquirect({0.125f, 0.5f})).r, 1.0f);
    // Above row 0's centre the read clamps to row 0.
    e.rgb[(0 * 4 + 1) * 3 + 1] = 5.0f;
    EXPECT_FLOAT_EQ(sampleEnvironmentUv(e, {0.375f, 0.01f}).g, 5.0f);
    EXPECT_FLOAT_EQ(sampleEnvironmentUv(e, {0.375f, 0.5f}).g, 2.5f);
}

TEST(Environment, RotationTurnsTheEnvironmentAboutPlusY)
{
    // +90 degrees moves what was at +X (the image centre) to -Z: looking along -Z then
    // reads the environment at +X.
    const glm::mat3 m = environmentFromScene(90.0f);
    expectNear(m * glm::vec3(0, 0, -1), {1, 0, 0});
    expectNear(m * glm::vec3(0, 1, 0), {0, 1, 0});
    expectNear(environmentFromScene(0.0f) * glm::vec3(0.3f, 0.4f, 0.5f), {0.3f, 0.4f, 0.5f});
    expectNear(environmentFromScene(-90.0f) * glm::vec3(0, 0, 1), {1, 0, 0});
}

TEST(Environment, HalvingAveragesBoxesAndKeepsOddEdges)
{
    Environment e = constantEnvironment(glm::vec3(0.0f), 5, 3);
    for (uint32_t i = 0; i < 15; ++i)
        e.rgb[i * 3] = float(i);
    const Environment half = halveEnvironment(e);
    ASSERT_EQ(half.width, 2u);
    ASSERT_EQ(half.height, 1u);
    // Texel (0, 0): columns 0-1 of rows 0-2 (the odd last row joins): 0 1 5 6 10 11.
    EXPECT_FLOAT_EQ(half.texel(0, 0).r, (0 + 1 + 5 + 6 + 10 + 11) / 6.0f);
    // Texel (1, 0): columns 2-4 (the odd last column joins) of rows 0-2.
    EXPECT_FLOAT_EQ(half.texel(1, 0).r, (2 + 3 + 4 + 7 + 8 + 9 + 12 + 13 + 14) / 9.0f);
}

TEST(Environment, ValidationNamesTheProblem)
{
    Environment e = constantEnvironment(glm::vec3(1.0f), 4, 2);
    EXPECT_NO_THROW(validateEnvironment(e, "e"));
    e.rgb[7] = std::nanf("");
    EXPECT_THROW(validateEnvironment(e, "e"), std::invalid_argument);
    e.rgb[7] = -1.0f;
    try {
        validateEnvironment(e, "sky.hdr");
        FAIL();
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("sky.hdr"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("(2, 0)"), std::string::npos);
    }
    e.rgb.pop_back();
    EXPECT_THROW(validateEnvironment(e, "e"), std::invalid_argument);
    EXPECT_THROW(validateEnvironment(constantEnvironment(glm::vec3(1.0f), 1, 1), "e"), std::invalid_argument);
}

} // namespace
} // namespace lfd::lighting
