// The glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, appendix B), term for term
// as shaders/pbr_shading.glsl evaluates it: the one BRDF the split-sum table, the
// prefilter and the Monte Carlo reference integrate.
//   alpha = max(roughness^2, 1e-3), F0 = mix(0.04, baseColor, metallic),
//   diffuseColor = baseColor (1 - metallic),
//   f(l, v) = (1 - F) diffuseColor / pi + F D Vis, with
//   D   = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)                         (GGX)
//   Vis = 0.5 / (n.l sqrt((n.v)^2 (1 - alpha^2) + alpha^2) + n.v sqrt((n.l)^2 (1 - alpha^2) + alpha^2))
//                                                         (Smith, height-correlated)
//   F   = F0 + (1 - F0) (1 - v.h)^5                                             (Schlick)
// and n.v clamped to at least 1e-4, as the shader does.
#pragma once

#include <glm/glm.hpp>

namespace lfd::lighting {

struct PbrMaterial {
    glm::vec3 baseColor{1.0f}; // linear
    float metallic = 0.0f;
    float roughness = 1.0f; // perceptual
};

// The shader's floors on n.v (pbr_shading.glsl: max(dot(n, v), 1e-4)) and on alpha.
constexpr float kMinNDotV = 1e-4f;
constexpr float kMinAlpha = 1e-3f;

float alphaFromRoughness(float roughness);
glm::vec3 specularF0(const PbrMaterial& material);
glm::vec3 diffuseColor(const PbrMaterial& material);

float ggxDistribution(float nDotH, float alpha);
float smithVisibility(float nDotL, float nDotV, float alpha);
// (1 - v.h)^5, Schlick's Fresnel weight: F = F0 + (1 - F0) schlickWeight.
float schlickWeight(float vDotH);

// f(l, v) for unit n, v, l; 0 where n.l <= 0.
glm::vec3 evaluateBrdf(const PbrMaterial& material, glm::vec3 n, glm::vec3 v, glm::vec3 l);

} // namespace lfd::lighting
