// The shader's split-sum evaluation on the CPU; see split_sum.h.
#include "split_sum.h"

#include "sampling.h"

#include <algorithm>
#include <cmath>

namespace lfd::lighting {

glm::vec3 splitSumIbl(const PrefilteredEnvironment& environment, const BrdfTable& table, const PbrMaterial& material,
                      glm::vec3 n, glm::vec3 v, IrradianceSource irradiance)
{
    const float nDotV = std::max(glm::dot(n, v), kMinNDotV);
    const glm::vec3 r = reflectAbout(v, n);
    const float alpha = alphaFromRoughness(material.roughness);
    const glm::vec3 dominant = glm::mix(n, r, (1.0f - alpha) * (std::sqrt(1.0f - alpha) + alpha));
    const uint32_t levels = uint32_t(environment.specular.levels.size());
    const glm::vec3 prefiltered =
        sampleCubeTrilinear(environment.specular, dominant, levelOfRoughness(material.roughness, levels));
    const glm::vec3 abc = sampleBrdfTable(table, nDotV, material.roughness);
    const glm::vec3 f0 = specularF0(material);
    const glm::vec3 specular = prefiltered * (f0 * abc.x + abc.y);
    const glm::vec3 irradianceOverPi = irradiance == IrradianceSource::Sh9
                                           ? irradianceSh(environment.irradianceSh, n)
                                           : sampleCubeBilinear(environment.irradianceCube, n);
    const glm::vec3 diffuse = diffuseColor(material) * (glm::vec3(1.0f) - f0) * (1.0f - abc.z) * irradianceOverPi;
    return specular + diffuse;
}

} // namespace lfd::lighting
