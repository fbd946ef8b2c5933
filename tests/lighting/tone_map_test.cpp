// Khronos PBR Neutral against values worked by hand from its reference implementation,
// and the 8-bit display levels (exposure, tone map, sRGB encode, rounding).
#include "tone_map.h"

#include <gtest/gtest.h>

namespace lfd::lighting {
namespace {

void expectColourNear(glm::vec3 a, glm::vec3 b)
{
    EXPECT_NEAR(a.r, b.r, 1e-5f);
    EXPECT_NEAR(a.g, b.g, 1e-5f);
    EXPECT_NEAR(a.b, b.b, 1e-5f);
}

TEST(ToneMap, PbrNeutralBelowTheShoulderOnlyRemovesTheToeOffset)
{
    expectColourNear(pbrNeutralToneMap(glm::vec3(0.0f)), glm::vec3(0.0f));
    // min channel x < 0.08: offset x - 6.25 x^2, so 0.05 -> 6.25 * 0.05^2.
    expectColourNear(pbrNeutralToneMap(glm::vec3(0.05f)), glm::vec3(0.015625f));
    // Above 0.08 the offset is 0.04; a peak below 0.76 is not compressed.
    expectColourNear(pbrNeutralToneMap(glm::vec3(0.5f)), glm::vec3(0.46f));
    expectColourNear(pbrNeutralToneMap({0.5f, 0.3f, 0.1f}), {0.46f, 0.26f, 0.06f});
}

TEST(ToneMap, PbrNeutralCompressesAndDesaturatesAboveTheShoulder)
{
    // Grey 1: offset 0.04 -> peak 0.96, new peak 1 - 0.24^2 / (0.96 + 0.24 - 0.76).
    expectColourNear(pbrNeutralToneMap(glm::vec3(1.0f)), glm::vec3(1.0f - 0.0576f / 0.44f));
    // (2, 0.5, 0.1): offset 0.04 -> (1.96, 0.46, 0.06), new peak 1 - 0.0576 / 1.44 = 0.96,
    // scaled by 0.96 / 1.96, then mixed towards 0.96 by g = 1 - 1 / (0.15 * 1.0 + 1).
    const float scale = 0.96f / 1.96f, g = 1.0f - 1.0f / 1.15f;
    expectColourNear(pbrNeutralToneMap({2.0f, 0.5f, 0.1f}),
               {0.96f, 0.46f * scale + (0.96f - 0.46f * scale) * g, 0.06f * scale + (0.96f - 0.06f * scale) * g});
    // A toe and a shoulder at once: min 0.02 -> offset 0.0175, peak 0.8825.
    expectColourNear(pbrNeutralToneMap({0.3f, 0.02f, 0.9f}), {0.272777f, 0.007559f, 0.841103f});
    // Bright values approach 1 and never exceed it.
    EXPECT_LT(pbrNeutralToneMap(glm::vec3(1e6f)).r, 1.0f);
    EXPECT_GT(pbrNeutralToneMap(glm::vec3(1e6f)).r, 0.9999f);
}

TEST(ToneMap, DisplayLevelsAreTheRoundedSrgbEncode)
{
    using Levels = std::array<uint8_t, 3>;
    EXPECT_EQ(displayLevels(glm::vec3(0.0f), 0.0f), (Levels{0, 0, 0}));
    EXPECT_EQ(displayLevels(glm::vec3(0.5f), 0.0f), (Levels{181, 181, 181}));  // 0.46 -> 180.6
    EXPECT_EQ(displayLevels(glm::vec3(0.62f), 0.0f), (Levels{200, 200, 200})); // 0.58
    EXPECT_EQ(displayLevels(glm::vec3(1.0f), 0.0f), (Levels{240, 240, 240}));
    EXPECT_EQ(displayLevels({2.0f, 0.5f, 0.1f}, 0.0f), (Levels{250, 154, 108}));
    // Exposure multiplies by 2^EV before tone mapping.
    EXPECT_EQ(displayLevels(glm::vec3(0.25f), 1.0f), displayLevels(glm::vec3(0.5f), 0.0f));
    EXPECT_EQ(displayLevels(glm::vec3(2.0f), -2.0f), displayLevels(glm::vec3(0.5f), 0.0f));
    // In the linear segment of the sRGB curve (min channel 0: no toe offset): 0.001 * 12.92
    // * 255 = 3.3.
    EXPECT_EQ(displayLevels({0.0f, 0.0f, 0.001f}, 0.0f), (Levels{0, 0, 3}));
}

} // namespace
} // namespace lfd::lighting
