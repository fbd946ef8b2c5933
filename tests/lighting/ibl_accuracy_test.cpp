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
// worst 1). Each case prints the shaders' two lookups (SpecularLookup::LobeTaps) with the
// irradiance cube, the errors the bounds hold; the one lookup at the dominant direction
// they replaced; and the two lookups with SH9. The environments:
// * the neutral studio, on which the method's few free choices were made (lobe_tap_fit.h,
//   prefilter.h's wide level): every case meets the target but the metals at roughness
//   0.5, white 3.6 / 24 and gold 3.6 / 25 (one lookup: 6.3 / 30, 6.1 / 29): two isotropic
//   lookups cannot follow the real lobe's shape at n != v closely enough for a softbox's
//   25:1 edge (split_sum.h; chosen per ring of equal n.v against this very reference, two
//   lookups would still only reach 1.8 / 8);
// * validation, never used to choose anything:
//   - a sun and sky (a 1.5-degree disk 4-5 times brighter than the sky): dielectrics meet
//     it but the orange at roughness 0.5, whose worst pixel, at the sun's highlight, went
//     from 8 to 11 with two lookups (mean 1.43 -> 1.03); metals do not: the sun's edge in a
//     mirror, the lobe at roughness 0.5 (7.3 / 27, one lookup 11.0 / 46) and at roughness 1
//     the sun's terminator in the wide level's 4-texel faces (1.6 / 22, one lookup
//     2.8 / 19);
//   - soft lights (ibl_test_scenes.h, up to 8.5 on a 0.3 sky): roughness 0.05 and 1 meet
//     it, roughness 0.5 not (white metal 4.8 / 30, one lookup 11.0 / 63);
//   - outdoor (a hazy sun, clouds, a tree line): dielectrics and roughness 1 meet it,
//     roughness 0.5 metals not (white 2.9 / 14, one lookup 8.9 / 41).
// SH9 irradiance misses the target on the studios (ringing, irradiance.h): the cube is the
// form to use. The bounds below that are not the target are the measured values plus a
// margin, so a regression still fails.
#include "brdf_table.h"
#include "ibl_test_scenes.h"
#include "neutral_environment.h"
#include "parallel.h"
#include "prefilter.h"
#include "reference_ibl.h"
#include "split_sum.h"
#include "tone_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

struct CaseErrors {
    Errors taps;     // two lookups (SpecularLookup::LobeTaps), irradiance cube: the shaders'
    Errors dominant; // one lookup at the dominant direction, irradiance cube: the one replaced
    Errors sh;       // two lookups, SH9 irradiance
};

void accumulate(Errors& e, int error)
{
    e.mean += error;
    e.worst = std::max(e.worst, error);
}

CaseErrors sphereErrors(const Scene& scene, const PbrMaterial& material)
{
    std::vector<glm::vec3> normals;
    forEachSpherePixel(kPixels, kSilhouette, [&](glm::vec3 n) { normals.push_back(n); });
    std::vector<std::array<int, 3>> errors(normals.size());
    const glm::vec3 v(0, 0, 1);
    forEachBand(normals.size(), 16, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const glm::vec3 n = normals[i];
            const auto reference = displayLevels(
                referenceIbl(scene.environment, scene.distribution, material, n, v, kReferenceSamples, 7), 0.0f);
            const auto split = [&](IrradianceSource irradiance, SpecularLookup lookup) {
                return levelError(displayLevels(splitSumIbl(scene.prefiltered, scene.table, material, n, v, irradiance, lookup),
                                                0.0f),
                                  reference);
            };
            errors[i] = {split(IrradianceSource::Cube, SpecularLookup::LobeTaps),
                         split(IrradianceSource::Cube, SpecularLookup::DominantDirection),
                         split(IrradianceSource::Sh9, SpecularLookup::LobeTaps)};
        }
    });
    CaseErrors out;
    for (const auto& e : errors) {
        accumulate(out.taps, e[0]);
        accumulate(out.dominant, e[1]);
        accumulate(out.sh, e[2]);
    }
    for (Errors* e : {&out.taps, &out.dominant, &out.sh})
        e->mean /= double(errors.size());
    return out;
}

// One row of the table: a material and the bounds its errors (two lookups, irradiance
// cube) must keep.
struct Case {
    const char* colour;
    PbrMaterial material;
    double maxMean;
    int maxWorst;
};

void checkCases(const char* environment, const Scene& scene, const std::vector<Case>& cases)
{
    std::printf("%-11s %-7s %5s %5s | two lookups | one lookup  | SH9 (two)   | bound\n", "environment", "colour", "rough",
                "metal");
    for (const Case& c : cases) {
        const CaseErrors e = sphereErrors(scene, c.material);
        const bool target = c.maxMean <= 2.0 && c.maxWorst <= 8;
        std::printf("%-11s %-7s %5.2f %5.0f | %5.2f %5d | %5.2f %5d | %5.2f %5d | %s\n", environment, c.colour,
                    c.material.roughness, c.material.metallic, e.taps.mean, e.taps.worst, e.dominant.mean,
                    e.dominant.worst, e.sh.mean, e.sh.worst, target ? "target" : "NOT the target: measured + margin");
        EXPECT_LE(e.taps.mean, c.maxMean) << environment << " " << c.colour << " roughness " << c.material.roughness
                                          << " metallic " << c.material.metallic;
        EXPECT_LE(e.taps.worst, c.maxWorst) << environment << " " << c.colour << " roughness " << c.material.roughness
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
                   {"orange", {kOrange, 0.0f, 0.5f}, 2.0, 8}, // measured 1.20 / 8 (one lookup 1.80 / 12)
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.5f}, 4.0, 27}, // measured 3.61 / 24 (one lookup 6.34 / 30)
                   {"white", {kWhite, 1.0f, 1.0f}, 2.0, 8},  // measured 0.45 / 2 (one lookup 1.06 / 9)
                   {"gold", {kGold, 1.0f, 0.05f}, 2.0, 8},
                   {"gold", {kGold, 1.0f, 0.5f}, 4.0, 28}, // measured 3.56 / 25 (one lookup 6.09 / 29)
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
                   {"orange", {kOrange, 0.0f, 0.5f}, 1.2, 13}, // measured 1.03 / 11: the sun's highlight (one lookup 1.43 / 8)
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 2.0, 100}, // measured 1.66 / 92: the sun disk's edge
                   {"white", {kWhite, 1.0f, 0.5f}, 8.0, 30},   // measured 7.33 / 27 (one lookup 10.95 / 46)
                   {"white", {kWhite, 1.0f, 1.0f}, 2.0, 25},   // measured 1.61 / 22 (one lookup 2.84 / 19)
                   {"gold", {kGold, 1.0f, 0.05f}, 2.0, 100},   // measured 1.47 / 98
                   {"gold", {kGold, 1.0f, 0.5f}, 7.5, 29},     // measured 6.76 / 26 (one lookup 10.01 / 48)
                   {"gold", {kGold, 1.0f, 1.0f}, 2.0, 23},     // measured 1.53 / 20 (one lookup 2.69 / 19)
               });
}

TEST(IblAccuracy, SoftLights)
{
    const Scene scene(softLightsEnvironment(1));
    checkCases("soft-lights", scene,
               {
                   {"white", {kWhite, 0.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 0.5f}, 1.4, 15}, // measured 1.23 / 13 (one lookup 1.67 / 12)
                   {"white", {kWhite, 0.0f, 1.0f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.05f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.5f}, 3.0, 31}, // measured 2.65 / 28 (one lookup 3.85 / 30)
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 1.2, 17}, // measured 1.05 / 15 (one lookup the same)
                   {"white", {kWhite, 1.0f, 0.5f}, 5.3, 33},  // measured 4.78 / 30 (one lookup 11.02 / 63)
                   {"white", {kWhite, 1.0f, 1.0f}, 2.0, 8},
                   {"gold", {kGold, 1.0f, 0.05f}, 0.9, 11}, // measured 0.77 / 9 (one lookup the same)
                   {"gold", {kGold, 1.0f, 0.5f}, 5.0, 32},  // measured 4.55 / 29 (one lookup 10.58 / 57)
                   {"gold", {kGold, 1.0f, 1.0f}, 2.0, 8},
               });
}

TEST(IblAccuracy, Outdoor)
{
    const Scene scene(outdoorEnvironment());
    checkCases("outdoor", scene,
               {
                   {"white", {kWhite, 0.0f, 0.05f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 0.5f}, 2.0, 8},
                   {"white", {kWhite, 0.0f, 1.0f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.05f}, 2.0, 8},
                   {"orange", {kOrange, 0.0f, 0.5f}, 1.1, 14}, // measured 0.95 / 12 (one lookup 1.82 / 18)
                   {"orange", {kOrange, 0.0f, 1.0f}, 2.0, 8},
                   {"white", {kWhite, 1.0f, 0.05f}, 1.3, 32}, // measured 1.14 / 29: the sun glow (one lookup 1.12 / 29)
                   {"white", {kWhite, 1.0f, 0.5f}, 3.2, 16},  // measured 2.91 / 14 (one lookup 8.91 / 41)
                   {"white", {kWhite, 1.0f, 1.0f}, 2.0, 8},
                   {"gold", {kGold, 1.0f, 0.05f}, 1.0, 25}, // measured 0.83 / 22 (one lookup 0.81 / 22)
                   {"gold", {kGold, 1.0f, 0.5f}, 2.7, 16},  // measured 2.39 / 14 (one lookup 7.15 / 36)
                   {"gold", {kGold, 1.0f, 1.0f}, 2.0, 8},
               });
}

} // namespace
} // namespace lfd::lighting
