// The ground truth the split sum is judged against: Monte Carlo integration of
//   L_o(v) = integral over the hemisphere of f(l, v) L(l) (n.l) dl
// for the glTF BRDF of brdf.h against the unfiltered environment (bilinear reads of the
// equirectangular image at full resolution, sampleEnvironment), with no split-sum, n = v = R
// or irradiance approximation. Three strategies, `samples` points each, combined by
// multiple importance sampling with the balance heuristic (Veach & Guibas 1995, "Optimally
// Combining Sampling Techniques for Monte Carlo Rendering"): GGX half vectors (the specular
// lobe), cosine-weighted directions (the diffuse lobe) and the environment's luminance
// (EnvironmentDistribution: small bright sources). Each strategy's points are a Hammersley
// set shifted by a random offset drawn from `seed` (Cranley-Patterson rotation), so the
// result is deterministic for a seed and its error falls close to 1 / samples.
#pragma once

#include "brdf.h"
#include "environment.h"
#include "environment_distribution.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace lfd::lighting {

// Outgoing radiance towards unit v from a surface with unit normal n (linear, before
// exposure); `distribution` must be built from `environment`.
glm::vec3 referenceIbl(const Environment& environment, const EnvironmentDistribution& distribution,
                       const PbrMaterial& material, glm::vec3 n, glm::vec3 v, uint32_t samples, uint64_t seed);

} // namespace lfd::lighting
