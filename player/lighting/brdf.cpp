// The glTF BRDF as shaders/pbr_shading.glsl evaluates it; see brdf.h.
#include "brdf.h"
#include "pi.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::lighting {

namespace {
}

float alphaFromRoughness(float roughness)
{
    return std::max(roughness * roughness, kMinAlpha);
}

glm::vec3 specularF0(const PbrMaterial& material)
{
    return glm::mix(glm::vec3(0.04f), material.baseColor, material.metallic);
}

glm::vec3 diffuseColor(const PbrMaterial& material)
{
    return material.baseColor * (1.0f - material.metallic);
}

float ggxDistribution(float nDotH, float alpha)
{
    const float a2 = alpha * alpha;
    const float d = nDotH * nDotH * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

float smithVisibility(float nDotL, float nDotV, float alpha)
{
    const float a2 = alpha * alpha;
    const float visV = nDotL * std::sqrt(nDotV * nDotV * (1.0f - a2) + a2);
    const float visL = nDotV * std::sqrt(nDotL * nDotL * (1.0f - a2) + a2);
    return visV + visL > 0.0f ? 0.5f / (visV + visL) : 0.0f;
}

float schlickWeight(float vDotH)
{
    const float m = 1.0f - vDotH;
    const float m2 = m * m;
    return m2 * m2 * m;
}

glm::vec3 evaluateBrdf(const PbrMaterial& material, glm::vec3 n, glm::vec3 v, glm::vec3 l)
{
    const float nDotL = glm::dot(n, l);
    if (nDotL <= 0.0f)
        return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(v + l);
    const float nDotV = std::max(glm::dot(n, v), kMinNDotV);
    const float nDotH = std::max(glm::dot(n, h), 0.0f);
    const float vDotH = std::max(glm::dot(v, h), 0.0f);
    const float alpha = alphaFromRoughness(material.roughness);
    const glm::vec3 f0 = specularF0(material);
    const glm::vec3 fresnel = f0 + (glm::vec3(1.0f) - f0) * schlickWeight(vDotH);
    const glm::vec3 diffuse = (glm::vec3(1.0f) - fresnel) * diffuseColor(material) / kPi;
    const glm::vec3 specular = fresnel * (ggxDistribution(nDotH, alpha) * smithVisibility(nDotL, nDotV, alpha));
    return diffuse + specular;
}

} // namespace lfd::lighting
