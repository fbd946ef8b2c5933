// GGX prefiltering per level (filtered importance sampling, or an exact sum for the small
// levels) and the whole prefilter; see prefilter.h.
#include "prefilter.h"

#include "brdf.h"
#include "cube_convolution.h"
#include "cube_least_squares.h"
#include "cube_from_environment.h"
#include "parallel.h"
#include "sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lfd::lighting {

namespace {

// One sample of the GGX lobe around n = v = +Z: its direction, weight Vis (n.l) and source lod.
struct LobeSample {
    glm::vec3 l;
    float weight;
    float lod;
};

std::vector<LobeSample> lobeSamples(float roughness, uint32_t samples, uint32_t sourceSize, float lodBias)
{
    const float alpha = alphaFromRoughness(roughness);
    // Solid angle of one source texel, on average over the cube.
    const double texelSolidAngle = 4.0 * std::numbers::pi / (6.0 * double(sourceSize) * sourceSize);
    std::vector<LobeSample> lobe;
    for (uint32_t i = 0; i < samples; ++i) {
        const glm::vec3 h = ggxHalfVector(hammersley(i, samples), alpha);
        const glm::vec3 l = reflectAbout(glm::vec3(0.0f, 0.0f, 1.0f), h);
        if (l.z <= 0.0f)
            continue;
        // With n = v, pdf(l) = D (n.h) / (4 v.h) = D / 4; the sample stands for 1 / (N pdf).
        const double pdf = ggxDistribution(h.z, alpha) / 4.0;
        const double sampleSolidAngle = 1.0 / (double(samples) * pdf);
        const double lod = 0.5 * std::log2(sampleSolidAngle / texelSolidAngle) + lodBias;
        lobe.push_back({l, smithVisibility(l.z, 1.0f, alpha) * l.z, float(std::max(lod, 0.0))});
    }
    return lobe;
}

CubeMap sourceMipChain(CubeLevel base)
{
    CubeMap chain;
    chain.levels.push_back(std::move(base));
    while (chain.levels.back().size > 1)
        chain.levels.push_back(halveCubeLevel(chain.levels.back()));
    return chain;
}

void validateSettings(const PrefilterSettings& s)
{
    const auto fail = [](const std::string& what) { throw std::invalid_argument("prefilter settings: " + what); };
    if (s.faceSize == 0 || !std::has_single_bit(s.faceSize))
        fail("faceSize " + std::to_string(s.faceSize) + " is not a power of two");
    // The wide level after the GGX levels needs a face of at least one texel.
    const uint32_t maxLevels = uint32_t(std::countr_zero(s.faceSize));
    if (s.levels < 2 || s.levels > maxLevels)
        fail("levels " + std::to_string(s.levels) + " outside 2.." + std::to_string(maxLevels));
    if (s.samplesPerTexel == 0 || s.maxSamplesPerTexel < s.samplesPerTexel)
        fail("samplesPerTexel " + std::to_string(s.samplesPerTexel) + " is 0 or over maxSamplesPerTexel " +
             std::to_string(s.maxSamplesPerTexel));
    for (const auto& [name, size] : {std::pair{"irradianceSourceSize", s.irradianceSourceSize},
                                      std::pair{"directSourceSize", s.directSourceSize}})
        if (!std::has_single_bit(size) || size > s.faceSize)
            fail(std::string(name) + " " + std::to_string(size) + " is not a power of two up to faceSize");
    if (s.irradianceFaceSize == 0)
        fail("irradianceFaceSize is 0");
    if (!std::isfinite(s.lodBias))
        fail("lodBias is not finite");
}

// The source level a directly convolved level l sums: directSourceSize, or l's own if larger.
uint32_t directSourceLevel(const PrefilterSettings& s, uint32_t level)
{
    return std::min(level, uint32_t(std::countr_zero(s.faceSize / s.directSourceSize)));
}

} // namespace

PrefilterSettings PrefilterSettings::player()
{
    return PrefilterSettings{};
}

PrefilterSettings PrefilterSettings::reference()
{
    PrefilterSettings s;
    s.faceSize = 512;
    s.levels = 8;
    s.maxSamplesPerTexel = 1024;
    s.directSourceSize = 64;
    s.irradianceFaceSize = 32;
    return s;
}

uint32_t PrefilterSettings::samplesOfLevel(uint32_t level) const
{
    const uint32_t quadruplings = std::min(level > 0 ? level - 1 : 0u, 15u);
    return uint32_t(std::min<uint64_t>(uint64_t(samplesPerTexel) << (2 * quadruplings), maxSamplesPerTexel));
}

float roughnessOfLevel(uint32_t level, uint32_t levels)
{
    if (level == 0)
        return 0.0f;
    return std::sqrt(std::exp2(float(level + 1) - float(levels)));
}

float levelOfRoughness(float roughness, uint32_t levels)
{
    return std::min(levelOfAlpha(alphaFromRoughness(std::clamp(roughness, 0.0f, 1.0f)), levels), float(levels - 1));
}

float levelOfAlpha(float alpha, uint32_t levels)
{
    // Level 0 stands for the BRDF's smallest alpha (1e-3, brdf.h), level 1 for alpha1.
    const float alpha1 = std::exp2(2.0f - float(levels));
    const float lod = alpha < alpha1 ? (alpha - kMinAlpha) / (alpha1 - kMinAlpha) : 1.0f + std::log2(alpha / alpha1);
    return std::clamp(lod, 0.0f, float(levels));
}

CubeLevel prefilterGgxLevel(const CubeMap& source, float roughness, uint32_t size, uint32_t samples, float lodBias)
{
    const std::vector<LobeSample> lobe = lobeSamples(roughness, samples, source.levels[0].size, lodBias);
    CubeLevel level(size);
    forEachBand(size_t(kCubeFaces) * size, 1, [&](size_t, size_t begin, size_t end) {
        for (size_t row = begin; row < end; ++row) {
            const uint32_t face = uint32_t(row / size), y = uint32_t(row % size);
            for (uint32_t x = 0; x < size; ++x) {
                const glm::mat3 worldFromLobe = worldFromTangent(cubeTexelDirection(face, x, y, size));
                glm::vec3 sum(0.0f);
                float weight = 0.0f;
                for (const LobeSample& s : lobe) {
                    sum += s.weight * sampleCubeTrilinear(source, worldFromLobe * s.l, s.lod);
                    weight += s.weight;
                }
                level.setTexel(face, x, y, weight > 0.0f ? sum / weight : glm::vec3(0.0f));
            }
        }
    });
    return level;
}

CubeLevel convolveGgxLevel(const CubeLevel& source, float roughness, uint32_t size)
{
    // At n = v, h = normalize(n + l) has n.h = sqrt((1 + n.l) / 2): the lobe is a function
    // of n.l alone.
    const float alpha = alphaFromRoughness(roughness);
    return convolveCube(source, size, [alpha](double nDotL) {
        const float nDotH = float(std::sqrt((1.0 + nDotL) / 2.0));
        return double(ggxDistribution(nDotH, alpha)) * smithVisibility(float(nDotL), 1.0f, alpha) * nDotL;
    });
}

CubeLevel convolveWideLevel(const CubeLevel& source, uint32_t size)
{
    // D is constant at alpha = 1: the lobe is Vis (n.l) at n.v = kWideLobeNDotV. A face of
    // up to 8 texels (the player's is 4, gstd's 2) is summed exactly at 4 times its size and
    // fitted for bilinear reads (cube_least_squares.h); a larger one holds the sums at its
    // texel centres, as the GGX levels do.
    const auto kernel = [](double nDotL) {
        return double(smithVisibility(float(nDotL), kWideLobeNDotV, 1.0f)) * nDotL;
    };
    if (size > 8)
        return convolveCube(source, size, kernel);
    return leastSquaresCubeLevel(convolveCube(source, 4 * size, kernel), size);
}

PrefilteredEnvironment prefilterEnvironment(const Environment& environment, const PrefilterSettings& settings)
{
    validateSettings(settings);
    validateEnvironment(environment, "environment");
    const CubeMap source = sourceMipChain(cubeFromEnvironment(environment, settings.faceSize));
    PrefilteredEnvironment out;
    out.specular.levels.push_back(source.levels[0]);
    for (uint32_t l = 1; l < settings.levels; ++l) {
        const float roughness = roughnessOfLevel(l, settings.levels);
        const uint32_t size = settings.faceSize >> l;
        out.specular.levels.push_back(size <= settings.directFaceSize
                                          ? convolveGgxLevel(source.levels[directSourceLevel(settings, l)], roughness, size)
                                          : prefilterGgxLevel(source, roughness, size, settings.samplesOfLevel(l),
                                                              settings.lodBias));
    }
    out.specular.levels.push_back(convolveWideLevel(source.levels[directSourceLevel(settings, settings.levels)],
                                                    settings.faceSize >> settings.levels));
    const uint32_t irradianceLevel = uint32_t(std::countr_zero(settings.faceSize / settings.irradianceSourceSize));
    const CubeLevel& irradianceSource = source.levels[irradianceLevel];
    out.irradianceSh = shIrradianceFromCube(irradianceSource);
    out.irradianceCube = irradianceCubeFromCube(irradianceSource, settings.irradianceFaceSize);
    return out;
}

} // namespace lfd::lighting
