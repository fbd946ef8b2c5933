// The split-sum evaluation of image-based lighting (Karis 2013, "Real Shading in Unreal
// Engine 4"), as the shaders evaluate it, operation for operation, so a GL test can hold
// the shader to this CPU mirror and this mirror to the Monte Carlo reference:
//   n.v      = max(n.v, 1e-4),  R = reflect(-v, n) = 2 (n.v) n - v,  alpha = max(r^2, 1e-3)
//   D        = mix(n, R, (1 - alpha) (sqrt(1 - alpha) + alpha))    (not normalised)
//   specular = prefiltered(D, lod = levelOfRoughness(roughness)) * (F0 A + B)
//   diffuse  = diffuseColor (1 - F0) (1 - C) E(n) / pi
//   radiance = specular + diffuse      (occlusion, applied by the caller, scales both)
// with (A, B, C) from the BRDF table at (n.v, roughness) (brdf_table.h) and E / pi from the
// SH9 polynomial or the irradiance cube (irradiance.h). D is the specular lobe's dominant
// direction (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based Rendering",
// section 4.9.3, getSpecularDominantDir, fed GGX's alpha): a rough lobe's reflection leans
// from R towards n, and the prefiltered lobe is centred on its lookup direction. Against
// the Monte Carlo reference on the neutral studio (ibl_accuracy_test's sphere, white
// metal) the mean / worst error at roughness 1 falls from 13.6 / 45 levels (lookup at R)
// to 1.1 / 9, at roughness 0.5 the worst from 57 to 30 (the mean 5.7 -> 6.3); near
// roughness 0 the lookup is R. Directions are in the environment's frame: with
// --environment-rotation, the caller turns n and v by environmentFromScene first
// (environment.h).
//
// Filtering: the CPU reads the specular cube as GL's textureLod with
// GL_LINEAR_MIPMAP_LINEAR and seamless cube filtering (sampleCubeTrilinear; the only
// difference is at the cube's 8 corners, where GL leaves the fourth tap to the driver), the
// irradiance cube as GL_LINEAR (seamless), and the table as GL_LINEAR with
// GL_CLAMP_TO_EDGE, with exact float weights where a GPU may quantise them (commonly to 8
// bits of fraction; expected well below one 8-bit level, not measured here).
#pragma once

#include "brdf.h"
#include "brdf_table.h"
#include "prefilter.h"

#include <glm/glm.hpp>

namespace lfd::lighting {

// Which diffuse irradiance the shader reads.
enum class IrradianceSource { Sh9, Cube };

// Outgoing radiance (linear, before exposure and tone mapping) towards v from a surface with
// unit normal n, lit by the prefiltered environment. The specular levels must be those
// of prefilterEnvironment (levelOfRoughness's mapping).
glm::vec3 splitSumIbl(const PrefilteredEnvironment& environment, const BrdfTable& table, const PbrMaterial& material,
                      glm::vec3 n, glm::vec3 v, IrradianceSource irradiance);

} // namespace lfd::lighting
