// The prefilter: settings, the roughness <-> level mapping, the furnace (every level and
// both irradiance forms give a constant environment back), levels against a brute-force
// sum over the environment's pixels, determinism, and the time it takes.
#include "brdf.h"
#include "cube_convolution.h"
#include "cube_from_environment.h"
#include "ibl_test_scenes.h"
#include "neutral_environment.h"
#include "prefilter.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>

namespace lfd::lighting {
namespace {

TEST(Prefilter, SettingsAreChecked)
{
    const Environment e = constantEnvironment(glm::vec3(1.0f));
    auto refused = [&](auto change) {
        PrefilterSettings s = PrefilterSettings::player();
        change(s);
        EXPECT_THROW(prefilterEnvironment(e, s), std::invalid_argument);
    };
    refused([](PrefilterSettings& s) { s.faceSize = 100; });
    refused([](PrefilterSettings& s) { s.levels = 1; });
    refused([](PrefilterSettings& s) { s.levels = 9; }); // 256: 8 GGX levels and the wide level
    refused([](PrefilterSettings& s) { s.samplesPerTexel = 0; });
    refused([](PrefilterSettings& s) { s.maxSamplesPerTexel = 8; });
    refused([](PrefilterSettings& s) { s.directSourceSize = 48; });
    refused([](PrefilterSettings& s) { s.irradianceSourceSize = 512; });
    EXPECT_THROW(prefilterEnvironment(Environment{}, PrefilterSettings::player()), std::invalid_argument);
}

TEST(Prefilter, RoughnessOfEachLevel)
{
    // Level l >= 1 holds alpha = 2^(l + 1 - levels): 6 levels -> roughness 0, 0.25,
    // 0.354, 0.5, 0.707, 1.
    const float expected[6] = {0.0f, 0.25f, std::sqrt(0.125f), 0.5f, std::sqrt(0.5f), 1.0f};
    for (uint32_t l = 0; l < 6; ++l) {
        EXPECT_FLOAT_EQ(roughnessOfLevel(l, 6), expected[l]);
        EXPECT_NEAR(levelOfRoughness(expected[l], 6), float(l), 1e-5f) << l;
    }
    // Below level 1 the lod is linear in alpha from the BRDF's floor: roughness 0.05 reads
    // level 0 with 2.4% of level 1.
    EXPECT_FLOAT_EQ(levelOfRoughness(0.05f, 6), (0.0025f - 1e-3f) / (0.0625f - 1e-3f));
    float previous = -1.0f;
    for (float r = 0.0f; r <= 1.0f; r += 0.01f) {
        const float lod = levelOfRoughness(r, 8);
        EXPECT_GE(lod, previous);
        previous = lod;
    }
    EXPECT_FLOAT_EQ(levelOfRoughness(2.0f, 8), 7.0f);
    // levelOfAlpha is the same mapping in alpha, on into the wide level: alpha 2 reads it
    // alone, alpha sqrt(2) half of it.
    EXPECT_FLOAT_EQ(levelOfAlpha(0.25f, 6), 3.0f);
    EXPECT_FLOAT_EQ(levelOfAlpha(1.0f, 6), 5.0f);
    EXPECT_FLOAT_EQ(levelOfAlpha(std::sqrt(2.0f), 6), 5.5f);
    EXPECT_FLOAT_EQ(levelOfAlpha(2.0f, 6), 6.0f);
    EXPECT_FLOAT_EQ(levelOfAlpha(8.0f, 6), 6.0f);
    EXPECT_FLOAT_EQ(levelOfAlpha(1e-4f, 6), 0.0f);
    EXPECT_EQ(PrefilterSettings::player().samplesOfLevel(1), 16u);
    EXPECT_EQ(PrefilterSettings::player().samplesOfLevel(2), 64u);
    EXPECT_EQ(PrefilterSettings::player().samplesOfLevel(3), 256u);
    EXPECT_EQ(PrefilterSettings::player().samplesOfLevel(9), 512u);
}

TEST(Prefilter, FurnaceEveryLevelAndBothIrradiancesGiveTheRadianceBack)
{
    const glm::vec3 radiance(0.5f, 2.0f, 8.0f);
    PrefilterSettings s = PrefilterSettings::player();
    s.faceSize = 64;
    s.levels = 6; // levels 1-2 (faces 32, 16) sampled, 3-5 (8 .. 2) summed, the wide level 1 x 1
    s.directFaceSize = 8;
    s.irradianceSourceSize = 16;
    const PrefilteredEnvironment p = prefilterEnvironment(constantEnvironment(radiance), s);
    ASSERT_EQ(p.specular.levels.size(), 7u);
    for (size_t l = 0; l < 7; ++l) {
        const CubeLevel& level = p.specular.levels[l];
        ASSERT_EQ(level.size, 64u >> l);
        for (size_t i = 0; i < level.rgb.size(); ++i)
            ASSERT_NEAR(level.rgb[i], radiance[int(i % 3)], 1e-3f * radiance[int(i % 3)]) << "level " << l;
    }
    for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, -2, 3))})
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(irradianceSh(p.irradianceSh, n)[c], radiance[c], 1e-3f * radiance[c]);
            EXPECT_NEAR(sampleCubeBilinear(p.irradianceCube, n)[c], radiance[c], 1e-5f * radiance[c]);
        }
}

// The mean of the environment around n weighted by kernel(n.l), by brute force: every
// pixel of the equirectangular image, weighted by the kernel and its solid angle.
template <typename Kernel>
glm::dvec3 bruteForceLobe(const Environment& e, glm::vec3 n, Kernel kernel)
{
    glm::dvec3 sum(0.0);
    double weights = 0.0;
    for (uint32_t y = 0; y < e.height; ++y) {
        const double pi = std::numbers::pi;
        const double solidAngle = 2.0 * pi / e.width * pi / e.height * std::sin(pi * (y + 0.5) / e.height);
        for (uint32_t x = 0; x < e.width; ++x) {
            const glm::vec3 l = directionFromEquirect({(float(x) + 0.5f) / float(e.width), (float(y) + 0.5f) / float(e.height)});
            const float nDotL = glm::dot(n, l);
            if (nDotL <= 0.0f)
                continue;
            const double w = kernel(nDotL) * solidAngle;
            sum += w * glm::dvec3(e.texel(x, y));
            weights += w;
        }
    }
    return sum / weights;
}

// The GGX lobe at n = v = R: D Vis (n.l).
auto ggxLobe(float roughness)
{
    const float alpha = alphaFromRoughness(roughness);
    return [alpha](float nDotL) {
        const float nDotH = std::sqrt((1.0f + nDotL) / 2.0f);
        return double(ggxDistribution(nDotH, alpha)) * smithVisibility(nDotL, 1.0f, alpha) * nDotL;
    };
}

TEST(Prefilter, LevelsMatchABruteForceLobe)
{
    // The neutral studio at 512 x 256 (the brute force sums every pixel), both kinds of
    // level: filtered importance sampling (faces 128, 64) and direct sums (32 and less).
    Environment studio = halveEnvironment(neutralEnvironment());
    const PrefilterSettings s = PrefilterSettings::player();
    const PrefilteredEnvironment p = prefilterEnvironment(studio, s);
    ASSERT_EQ(p.specular.levels.size(), s.levels + 1);
    for (uint32_t l = 1; l < s.levels; ++l) {
        const CubeLevel& level = p.specular.levels[l];
        ASSERT_EQ(level.size, s.faceSize >> l);
        double meanError = 0.0, worstError = 0.0;
        int count = 0;
        for (uint32_t face = 0; face < kCubeFaces; ++face)
            for (uint32_t i = 0; i < 3; ++i) {
                const uint32_t x = (level.size * (2 * i + 1)) / 6, y = (level.size * (5 - 2 * i)) / 6;
                const glm::vec3 n = cubeTexelDirection(face, x, y, level.size);
                const double expected = bruteForceLobe(studio, n, ggxLobe(roughnessOfLevel(l, s.levels))).g;
                const double error = std::abs(level.texel(face, x, y).g - expected) / expected;
                meanError += error;
                worstError = std::max(worstError, error);
                ++count;
            }
        meanError /= count;
        std::printf("level %u (face %u, roughness %.3f): mean %.2f%%, worst %.2f%%\n", l, level.size,
                    roughnessOfLevel(l, s.levels), 100.0 * meanError, 100.0 * worstError);
        // Direct sums are exact but for the 32-texel source; sampled levels carry filtered
        // importance sampling's error (16 and 64 samples: measured 4% / 14% and 4% / 16%;
        // the paper's bias of +1 would give 21% / 52% on level 1).
        const bool direct = level.size <= s.directFaceSize;
        EXPECT_LT(meanError, direct ? 0.003 : 0.06) << "level " << l;
        EXPECT_LT(worstError, direct ? 0.01 : 0.2) << "level " << l;
    }
}

TEST(Prefilter, TheWideLevelReadsItsLobe)
{
    // The wide level (prefilter.h: 0.5 (n.l) / (n.l + 0.2)), 4 x 4 faces fitted for
    // bilinear reads: read between its texel centres (the centres of a 7-texel face), the
    // neutral studio and the sun and sky (256 x 128) against the brute-force lobe, and
    // against what the exact sums at its texel centres would read.
    const auto wideLobe = [](float nDotL) { return double(nDotL) / (nDotL + 0.2); };
    for (const auto& [name, environment, maxWorst] :
         {std::tuple{"neutral", halveEnvironment(halveEnvironment(neutralEnvironment())), 0.15},
          std::tuple{"sun+sky", halveEnvironment(halveEnvironment(sunAndSkyEnvironment())), 0.7}}) {
        const PrefilterSettings s = PrefilterSettings::player();
        const PrefilteredEnvironment p = prefilterEnvironment(environment, s);
        const CubeLevel& wide = p.specular.levels[s.levels];
        ASSERT_EQ(wide.size, 4u);
        const CubeLevel centres = convolveCube(cubeFromEnvironment(environment, 32), 4, [](double nDotL) {
            return double(smithVisibility(float(nDotL), kWideLobeNDotV, 1.0f)) * nDotL;
        });
        double meanError = 0.0, worstError = 0.0, centresMean = 0.0;
        int count = 0;
        for (uint32_t face = 0; face < kCubeFaces; ++face)
            for (uint32_t y = 0; y < 7; ++y)
                for (uint32_t x = 0; x < 7; ++x) {
                    const glm::vec3 n = cubeTexelDirection(face, x, y, 7);
                    const double expected = bruteForceLobe(environment, n, wideLobe).g;
                    const double error = std::abs(sampleCubeBilinear(wide, n).g - expected) / expected;
                    meanError += error;
                    worstError = std::max(worstError, error);
                    centresMean += std::abs(sampleCubeBilinear(centres, n).g - expected) / expected;
                    ++count;
                }
        meanError /= count;
        centresMean /= count;
        std::printf("wide level, %s: mean %.2f%% (exact sums at the centres: %.2f%%), worst %.2f%%\n", name,
                    100.0 * meanError, 100.0 * centresMean, 100.0 * worstError);
        // Worst at the sun's terminator, where the lobe bends within a texel.
        EXPECT_LT(meanError, 0.8 * centresMean) << name;
        EXPECT_LT(worstError, maxWorst) << name;
    }
}

TEST(Prefilter, LevelZeroIsTheResampledEnvironmentAndRunsAreIdentical)
{
    const Environment sky = sunAndSkyEnvironment();
    PrefilterSettings s = PrefilterSettings::player();
    s.faceSize = 64;
    s.directSourceSize = 16;
    s.irradianceSourceSize = 16;
    const PrefilteredEnvironment a = prefilterEnvironment(sky, s), b = prefilterEnvironment(sky, s);
    EXPECT_EQ(a.specular.levels[0].rgb, cubeFromEnvironment(sky, 64).rgb);
    for (size_t l = 0; l < a.specular.levels.size(); ++l)
        EXPECT_EQ(a.specular.levels[l].rgb, b.specular.levels[l].rgb) << l;
    EXPECT_EQ(a.irradianceCube.rgb, b.irradianceCube.rgb);
    for (size_t i = 0; i < 9; ++i)
        EXPECT_EQ(a.irradianceSh[i], b.irradianceSh[i]);
}

TEST(Prefilter, TimeForTheNeutralStudio)
{
    // Reported, not asserted (the machine is shared): the player prefilters at start-up.
    const Environment studio = neutralEnvironment();
    for (const auto& [name, settings] : {std::pair{"player", PrefilterSettings::player()},
                                         std::pair{"reference", PrefilterSettings::reference()}}) {
        const auto start = std::chrono::steady_clock::now();
        const PrefilteredEnvironment p = prefilterEnvironment(studio, settings);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s prefilter (face %u, %u levels): %.3f s\n", name, settings.faceSize, settings.levels, seconds);
        ::testing::Test::RecordProperty(std::string(name) + "_prefilter_ms", int(seconds * 1000.0));
        EXPECT_EQ(p.specular.levels.size(), settings.levels + 1); // and the wide level
    }
}

} // namespace
} // namespace lfd::lighting
