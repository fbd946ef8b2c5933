// The accuracy target for image-based lighting: on a sphere at roughness 0.05 /
// 0.5 / 1.0 and metallic 0 / 1, the split sum (splitSumIbl, what the shaders evaluate)
// against a Monte Carlo integration of the same BRDF and environment (referenceIbl), after
// exposure 0, PBR Neutral and the 8-bit sRGB encode: mean |error| <= 2 levels, worst <= 8,
// the silhouette excluded. Per pixel the error is the largest of the three channels'.
//
// Set-up: a unit sphere seen from +Z by an orthographic camera, 32 x 32 pixels; the
// silhouette is every pixel with n.v < 0.2 (the outer 2% of the radius, about the outer
// pixel ring of a sphere 50 pixels across). Player prefilter settings, a 32 x 32 table, the
// reference at 512 points per strategy (within one level of 4096 everywhere: mean 0.5,
// worst 1). Each case prints its row; the two environments:
// * the neutral studio: every case meets the target but metallic and coloured dielectric
//   at roughness 0.5, where the split sum's isotropic n = v = R lobe cannot follow the
//   stretched reflection of a softbox (the same with an exact prefilter: it is not the
//   prefilter's error), and white metal at roughness 1, one level over in the dark
//   floor's reflection at n.v 0.23;
// * a sun and sky (a 1.5-degree disk 4-5 times brighter than the sky): dielectrics meet it
//   with the irradiance cube; metals do not (the sun's edge in a mirror, and the split
//   sum's lobe at roughness 0.5 and 1).
// SH9 irradiance misses the target on both (ringing, irradiance.h): the cube is the form
// to use. The bounds below that are not the target are the measured values plus a margin,
// so a regression still fails.
#include "brdf_table.h"
#include "ibl_test_scenes.h"
#include "neutral_environment.h"
#include "parallel_bands.h"
#include "prefilter.h"
#include "reference_ibl.h"
#include "split_sum.h"
#include "tone_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace lfd::lighting {
namespace {

constexpr uint32_t kPixels = 32;
constexpr float kSilhouette = 0.2f;
constexpr uint32_t kReferenceSamples = 512;

struct Errors {
    double mean = 0.0;
    int worst = 0;
};

struct Scene {
    Environment environment;
    EnvironmentDistribution distribution;
    PrefilteredEnvironment prefiltered;
    BrdfTable table;

    explicit Scene(Environment e)
        : environment(std::move(e)), distribution(environment),
          prefiltered(prefilterEnvironment(environment, PrefilterSettings::player())), table(splitSumBrdfTable(32, 2048))
    {
    }
};

int levelError(const std::array<uint8_t, 3>& a, const std::array<uint8_t, 3>& b)
{
    int worst = 0;
    for (size_t c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a[c]) - int(b[c])));
    return worst;
}

// Errors of the split sum with the irradiance cube and with SH9.
std::pair<Errors, Errors> sphereErrors(const Scene& scene, const PbrMaterial& material)
{
    std::vector<glm::vec3> normals;
    forEachSpherePixel(kPixels, kSilhouette, [&](glm::vec3 n) { normals.push_back(n); });
    std::vector<std::pair<int, int>> errors(normals.size());
    const glm::vec3 v(0, 0, 1);
    metrics::forEachBand(normals.size(), 16, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const glm::vec3 n = normals[i];
            const auto reference = displayLevels(
                referenceIbl(scene.environment, scene.distribution, material, n, v, kReferenceSamples, 7), 0.0f);
            const auto cube = displayLevels(
                splitSumIbl(scene.prefiltered, scene.table, material, n, v, IrradianceSource::Cube), 0.0f);
            const auto sh = displayLevels(
                splitSumIbl(scene.prefiltered, scene.table, material, n, v, IrradianceSource::Sh9), 0.0f);
            errors[i] = {levelError(cube, reference), levelError(sh, reference)};
        }
    });
    Errors cube, sh;
    for (const auto& [c, s] : errors) {
        cube.mean += c;
        sh.mean += s;
        cube.worst = std::max(cube.worst, c);
        sh.worst = std::max(sh.worst, s);
    }
    cube.mean /= double(errors.size());
    sh.mean /= double(errors.size());
    return {cube, sh};
}

// One row of the table: a material and the bounds its cube-irradiance errors must keep.
struct Case {
    const char* colour;
    PbrMaterial material;
    double maxMean;
    int maxWorst;
};

void checkCases(const char* environment, const Scene& scene, const std::vector<Case>& cases)
{
    std::printf("%-10s %-10s %5s %4s | cube mean worst | SH9 mean worst | bound\n", "environment", "colour",
                "rough", "metal");
    for (const Case& c : cases) {
        const auto [cube, sh] = sphereErrors(scene, c.material);
        const bool target = c.maxMean <= 2.0 && c.maxWorst <= 8;
        std::printf("%-10s %-10s %5.2f %4.0f | %9.2f %5d | %8.2f %5d | %s\n", environment, c.colour, c.material.roughness,
                    c.material.metallic, cube.mean, cube.worst, sh.mean, sh.worst,
                    target ? "target" : "NOT the target: measured + margin");
        EXPECT_LE(cube.mean, c.maxMean) << environment << " " << c.colour << " roughness " << c.material.roughness
                                        << " metallic " << c.material.metallic;
        EXPECT_LE(cube.worst, c.maxWorst) << environment << " " << c.colour << " roughness " << c.material.roughness
                                          << " metallic " << c.material.metallic;
    }
}

constexpr glm::vec3 kWhite(0.9f), kOrange(0.9f, 0.35f, 0.1f), kGold(1.0f, 0.77f, 0.34f);

TEST(IblAccuracy, NeutralStudio)
{
    const Scene scene(neutralEnvironment());
    checkCases("neutral", scene,
               {
                   {"white", {kWhite, 0.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 0.5f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 1.0f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.05f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.5f}, 2.3, 14}, // measured 1.81 / 12
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.5f}, 7.0, 33}, // measured 6.32 / 30
                   {"white", {kWhite, 1.0f, 1.0f}, 2.0, 10}, // measured 1.04 / 9: the floor's reflection at n.v 0.23
                   {"gold", {kGold, 1.0f, 0.05f}, 2.0, 8},
                   {"gold", {kGold, 1.0f, 0.5f}, 7.0, 33}, // measured 6.09 / 30
                   {"gold", {kGold, 1.0f, 1.0f}, 2.0, 8},
               });
}

TEST(IblAccuracy, SunAndSky)
{
    const Scene scene(sunAndSkyEnvironment());
    checkCases("sun+sky", scene,
               {
                   {"white", {kWhite, 0.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 0.5f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 1.0f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.05f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.5f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 2.0, 100}, // measured 1.66 / 92: the sun disk's edge
                   {"white", {kWhite, 1.0f, 0.5f}, 12.0, 50},  // measured 10.96 / 45
                   {"white", {kWhite, 1.0f, 1.0f}, 3.3, 22},   // measured 2.85 / 19
                   {"gold", {kGold, 1.0f, 0.05f}, 2.0, 100},   // measured 1.47 / 98
                   {"gold", {kGold, 1.0f, 0.5f}, 11.0, 50},    // measured 10.00 / 47
                   {"gold", {kGold, 1.0f, 1.0f}, 3.3, 22},     // measured 2.72 / 19
               });
}

} // namespace
} // namespace lfd::lighting
