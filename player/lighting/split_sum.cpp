// The shader's split-sum evaluation on the CPU; see split_sum.h.
#include "split_sum.h"

#include "lobe_taps.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>

namespace lfd::lighting {

glm::vec3 splitSumIbl(const PrefilteredEnvironment& environment, const BrdfTable& table, const PbrMaterial& material,
                      glm::vec3 n, glm::vec3 v, IrradianceSource irradiance, SpecularLookup lookup)
{
    const float nDotV = std::max(glm::dot(n, v), kMinNDotV);
    const glm::vec3 r = reflectAbout(v, n);
    const float roughness = std::clamp(material.roughness, 0.0f, 1.0f);
    const float alpha = alphaFromRoughness(roughness);
    // The GGX levels; the last level of the chain is the wide one (prefilter.h).
    const uint32_t levels = uint32_t(environment.specular.levels.size()) - 1;
    glm::vec3 prefiltered;
    if (lookup == SpecularLookup::LobeTaps) {
        const glm::vec4 taps = sampleLobeTapTable(lobeTapTable(), nDotV, roughness);
        // Cube lookups need no unit direction (the face and (s, t) are ratios).
        const glm::vec3 core = glm::mix(n, r, taps.x), halo = glm::mix(n, r, taps.z);
        const float coreLod = levelOfAlpha(alpha * std::exp2(taps.y), levels);
        const float haloLod = levelOfAlpha(alpha * std::exp2(taps.w), levels);
        prefiltered = 0.5f * (sampleCubeTrilinear(environment.specular, core, coreLod) +
                              sampleCubeTrilinear(environment.specular, halo, haloLod));
    } else {
        const glm::vec3 dominant = glm::mix(n, r, (1.0f - alpha) * (std::sqrt(1.0f - alpha) + alpha));
        prefiltered = sampleCubeTrilinear(environment.specular, dominant, levelOfRoughness(roughness, levels));
    }
    const glm::vec3 abc = sampleBrdfTable(table, nDotV, roughness);
    const glm::vec3 f0 = specularF0(material);
    const glm::vec3 specular = prefiltered * (f0 * abc.x + abc.y);
    const glm::vec3 irradianceOverPi = irradiance == IrradianceSource::Sh9
                                           ? irradianceSh(environment.irradianceSh, n)
                                           : sampleCubeBilinear(environment.irradianceCube, n);
    const glm::vec3 diffuse = diffuseColor(material) * (glm::vec3(1.0f) - f0) * (1.0f - abc.z) * irradianceOverPi;
    return specular + diffuse;
}

} // namespace lfd::lighting
