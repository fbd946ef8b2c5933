// The CPU mirror of the shaders' split sum: exact for a constant environment (against the
// Monte Carlo reference, both specular lookups and both irradiance forms), a mirror reads
// the reflected direction, a surface at roughness 1 reads along its normal (into the wide
// level at grazing n.v with two lookups), and a rotated environment turns the lookups.
#include "brdf_table.h"
#include "ibl_test_scenes.h"
#include "lobe_taps.h"
#include "prefilter.h"
#include "reference_ibl.h"
#include "sampling.h"
#include "split_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lfd::lighting {
namespace {

PrefilterSettings smallSettings()
{
    PrefilterSettings s = PrefilterSettings::player();
    s.faceSize = 64;
    s.levels = 5;
    s.directFaceSize = 8;
    s.directSourceSize = 16;
    s.irradianceSourceSize = 16;
    return s;
}

TEST(SplitSum, ConstantEnvironmentMatchesTheReference)
{
    const glm::vec3 radiance(0.8f, 1.0f, 1.3f);
    const Environment furnace = constantEnvironment(radiance);
    const EnvironmentDistribution distribution(furnace);
    const PrefilteredEnvironment p = prefilterEnvironment(furnace, smallSettings());
    const BrdfTable table = splitSumBrdfTable(32, 2048);
    for (const PbrMaterial& m : {PbrMaterial{{0.9f, 0.35f, 0.1f}, 0.0f, 0.3f}, PbrMaterial{{1.0f, 0.8f, 0.4f}, 1.0f, 0.7f},
                                 PbrMaterial{{0.5f, 0.5f, 0.5f}, 0.5f, 0.05f}})
        for (const float nDotV : {0.95f, 0.5f, 0.25f}) {
            const glm::vec3 n = glm::normalize(glm::vec3(0.2f, 0.3f, 1.0f));
            const glm::vec3 v = worldFromTangent(n) * glm::vec3(std::sqrt(1.0f - nDotV * nDotV), 0.0f, nDotV);
            const glm::vec3 reference = referenceIbl(furnace, distribution, m, n, v, 2048, 3);
            for (const IrradianceSource source : {IrradianceSource::Sh9, IrradianceSource::Cube})
                for (const SpecularLookup lookup : {SpecularLookup::LobeTaps, SpecularLookup::DominantDirection}) {
                    const glm::vec3 split = splitSumIbl(p, table, m, n, v, source, lookup);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(split[c], reference[c], 0.01f * reference[c]) << m.roughness << " " << nDotV;
                }
        }
}

// An environment of six colours, one per major axis.
Environment sixColours()
{
    Environment e = constantEnvironment(glm::vec3(0.0f), 256, 128);
    const glm::vec3 colours[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    for (uint32_t y = 0; y < e.height; ++y)
        for (uint32_t x = 0; x < e.width; ++x) {
            const glm::vec3 d = directionFromEquirect({(float(x) + 0.5f) / 256.0f, (float(y) + 0.5f) / 128.0f});
            const glm::vec3 c = colours[cubeCoordinateFromDirection(d).face];
            std::copy(&c.x, &c.x + 3, e.rgb.begin() + std::ptrdiff_t((size_t(y) * e.width + x) * 3));
        }
    return e;
}

TEST(SplitSum, AMirrorReadsTheReflectedDirection)
{
    const PrefilteredEnvironment p = prefilterEnvironment(sixColours(), smallSettings());
    const BrdfTable table = splitSumBrdfTable(32, 2048);
    const PbrMaterial mirror{glm::vec3(1.0f), 1.0f, 0.0f};
    // Seen from +Z, a normal halfway between +Z and +Y reflects +Y (face 2: (0, 0, 1)).
    const glm::vec3 up = splitSumIbl(p, table, mirror, glm::normalize(glm::vec3(0, 1, 1)), {0, 0, 1}, IrradianceSource::Cube);
    EXPECT_NEAR(up.b, 1.0f, 0.01f);
    EXPECT_NEAR(up.r, 0.0f, 0.01f);
    // Towards -X (face 1: (0, 1, 0)).
    const glm::vec3 left = splitSumIbl(p, table, mirror, glm::normalize(glm::vec3(-1, 0, 1)), {0, 0, 1}, IrradianceSource::Cube);
    EXPECT_NEAR(left.g, 1.0f, 0.01f);
    EXPECT_NEAR(left.b, 0.0f, 0.01f);
}

TEST(SplitSum, RoughnessOneReadsAlongTheNormal)
{
    // alpha = 1: the lobe is symmetric about n. One lookup: the dominant direction's weight
    // (1 - alpha)(...) is 0, so it reads n at the last GGX level. Two: the table's
    // directions are n (k = 0) and their widths reach into the wide level at grazing n.v.
    const PrefilteredEnvironment p = prefilterEnvironment(sixColours(), smallSettings());
    const BrdfTable table = splitSumBrdfTable(32, 2048);
    const PbrMaterial rough{glm::vec3(1.0f), 1.0f, 1.0f};
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.8f, 0.6f)), v(0, 0, 1);
    const glm::vec3 ab = sampleBrdfTable(table, glm::dot(n, v), 1.0f);
    const glm::vec3 one = sampleCubeTrilinear(p.specular, n, 4.0f) * (ab.x + ab.y);
    const glm::vec3 splitOne = splitSumIbl(p, table, rough, n, v, IrradianceSource::Cube, SpecularLookup::DominantDirection);
    const glm::vec4 taps = sampleLobeTapTable(lobeTapTable(), glm::dot(n, v), 1.0f);
    EXPECT_NEAR(taps.x, 0.0f, 1e-3f);
    EXPECT_NEAR(taps.z, 0.0f, 1e-3f);
    EXPECT_GT(0.5f * (taps.y + taps.w), 0.1f); // n.v = 0.6: a quarter of the way to the wide level
    const glm::vec3 two = 0.5f * (sampleCubeTrilinear(p.specular, n, levelOfAlpha(std::exp2(taps.y), 5)) +
                                  sampleCubeTrilinear(p.specular, n, levelOfAlpha(std::exp2(taps.w), 5))) *
                          (ab.x + ab.y);
    const glm::vec3 splitTwo = splitSumIbl(p, table, rough, n, v, IrradianceSource::Cube, SpecularLookup::LobeTaps);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(splitOne[c], one[c], 1e-6f);
        EXPECT_NEAR(splitTwo[c], two[c], 2e-3f * two[c]); // k is 0 to within 1e-3
    }
}

TEST(SplitSum, RotatingTheEnvironmentRotatesTheLookup)
{
    // With the environment turned by 90 degrees about +Y, a mirror facing the camera at
    // +Z reflects what was at +X (face 0: red).
    const PrefilteredEnvironment p = prefilterEnvironment(sixColours(), smallSettings());
    const BrdfTable table = splitSumBrdfTable(32, 2048);
    const glm::mat3 rotation = environmentFromScene(90.0f);
    const glm::vec3 n(0, 0, -1), v(0, 0, -1); // a surface seen from -Z reflects -Z ...
    const glm::vec3 seen = splitSumIbl(p, table, {glm::vec3(1.0f), 1.0f, 0.0f}, rotation * n, rotation * v,
                                       IrradianceSource::Cube);
    EXPECT_NEAR(seen.r, 1.0f, 0.01f); // ... which now shows +X
    EXPECT_NEAR(seen.g, 0.0f, 0.01f);
}

} // namespace
} // namespace lfd::lighting
