// Sample points and the directions they map to, shared by the split-sum table, the
// prefilter and the Monte Carlo reference: Hammersley points, GGX half vectors (Walter et
// al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 35-36, as Karis
// 2013 "Real Shading in Unreal Engine 4" samples them), cosine-weighted directions, and an
// orthonormal frame around a normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"). Tangent-space vectors have the normal along +Z.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace lfd::lighting {

// Point i of the n-point Hammersley set: (i / n, radical inverse of i in base 2).
glm::vec2 hammersley(uint32_t i, uint32_t n);

// The half vector h (tangent space) with density D(h) (n.h) for GGX's alpha.
glm::vec3 ggxHalfVector(glm::vec2 xi, float alpha);
// A direction with density cos(theta) / pi (tangent space).
glm::vec3 cosineDirection(glm::vec2 xi);

// Columns: tangent, bitangent, n (unit): world = worldFromTangent(n) * tangentVector.
glm::mat3 worldFromTangent(glm::vec3 n);

// The mirror of v about h: 2 (v.h) h - v (GLSL's reflect(-v, h)).
inline glm::vec3 reflectAbout(glm::vec3 v, glm::vec3 h)
{
    return 2.0f * glm::dot(v, h) * h - v;
}

} // namespace lfd::lighting
