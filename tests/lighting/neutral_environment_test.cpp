// The built-in neutral studio: deterministic, grey, at the documented level (a white
// Lambert surface facing up at sRGB ~200), and with structure a mirror shows.
#include "brdf_table.h"
#include "ibl_test_scenes.h"
#include "neutral_environment.h"
#include "prefilter.h"
#include "split_sum.h"
#include "tone_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace lfd::lighting {
namespace {

const Environment& studio()
{
    static const Environment e = neutralEnvironment();
    return e;
}

const PrefilteredEnvironment& prefilteredStudio()
{
    static const PrefilteredEnvironment p = prefilterEnvironment(studio(), PrefilterSettings::player());
    return p;
}

TEST(NeutralStudio, DeterministicGreyAndValid)
{
    const Environment& e = studio();
    EXPECT_EQ(e.width, kNeutralEnvironmentWidth);
    EXPECT_EQ(e.height, kNeutralEnvironmentHeight);
    EXPECT_NO_THROW(validateEnvironment(e, "neutral"));
    EXPECT_EQ(neutralEnvironment().rgb, e.rgb);
    for (size_t i = 0; i < e.rgb.size(); i += 3) {
        ASSERT_EQ(e.rgb[i], e.rgb[i + 1]);
        ASSERT_EQ(e.rgb[i], e.rgb[i + 2]);
    }
    // Brighter above the horizon than below; softboxes of radiance 3 at their centres.
    EXPECT_GT(sampleEnvironment(e, {0.3f, 0.5f, -0.8f}).r, 2.0f * sampleEnvironment(e, {0.3f, -0.5f, -0.8f}).r);
    const float key = sampleEnvironment(e, {-0.579f, 0.574f, 0.579f}).r; // 35 degrees up, 45 to the camera's left
    EXPECT_GT(key, 3.0f);
    EXPECT_LT(key, 3.5f);
}

TEST(NeutralStudio, WhiteLambertFacingUpLandsNearLevel200)
{
    const glm::vec3 up(0, 1, 0);
    const float irradianceOverPi = sampleCubeBilinear(prefilteredStudio().irradianceCube, up).g;
    const int level = displayLevels(glm::vec3(irradianceOverPi), 0.0f)[1];
    std::printf("white Lambert facing up: E/pi %.3f, sRGB level %d (SH9: %.3f)\n", irradianceOverPi, level,
                irradianceSh(prefilteredStudio().irradianceSh, up).g);
    EXPECT_GE(level, 190);
    EXPECT_LE(level, 210);
}

TEST(NeutralStudio, MirrorSphereShowsTheStudioRoughOneAGradient)
{
    const BrdfTable table = splitSumBrdfTable(32, 2048);
    for (const float roughness : {0.05f, 1.0f}) {
        int darkest = 255, brightest = 0;
        forEachSpherePixel(48, 0.2f, [&](glm::vec3 n) {
            const glm::vec3 radiance = splitSumIbl(prefilteredStudio(), table, {glm::vec3(0.95f), 1.0f, roughness}, n,
                                                   {0, 0, 1}, IrradianceSource::Cube);
            const int level = displayLevels(radiance, 0.0f)[1];
            darkest = std::min(darkest, level);
            brightest = std::max(brightest, level);
        });
        std::printf("metallic sphere, roughness %.2f: levels %d .. %d\n", roughness, darkest, brightest);
        EXPECT_GE(brightest - darkest, 8) << roughness; // the target: >= 8 levels of spread
        if (roughness < 0.5f) {
            EXPECT_GE(brightest, 235); // a softbox
            EXPECT_LE(darkest, 100);   // the floor
        }
    }
}

} // namespace
} // namespace lfd::lighting
