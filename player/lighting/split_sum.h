// The split-sum evaluation of image-based lighting (Karis 2013, "Real Shading in Unreal
// Engine 4"), as the shaders evaluate it, operation for operation, so a GL test can hold
// the shader to this CPU mirror and this mirror to the Monte Carlo reference:
//   n.v      = max(n.v, 1e-4),  R = reflect(-v, n) = 2 (n.v) n - v,  alpha = max(r^2, 1e-3)
//   (k0, d0, k1, d1) = the lobe tap table at (n.v, r)                   (lobe_taps.h)
//   D_i      = mix(n, R, k_i),  lod_i = levelOfAlpha(alpha 2^d_i, L)   (prefilter.h; D_i not
//              normalised: a cube lookup needs no unit direction, k_i in [0, 1.5] keeps it off 0)
//   specular = (prefiltered(D_0, lod_0) + prefiltered(D_1, lod_1)) / 2 * (F0 A + B)
//   diffuse  = diffuseColor (1 - F0) (1 - C) E(n) / pi
//   radiance = specular + diffuse      (occlusion, applied by the caller, scales both)
// with (A, B, C) from the BRDF table at (n.v, r) (brdf_table.h), E / pi from the SH9
// polynomial or the irradiance cube (irradiance.h) and L the prefilter's GGX levels (the
// chain's last level, lod L, is the wide level). Directions are in the environment's
// frame: with --environment-rotation, the caller turns n and v by environmentFromScene
// first (environment.h).
//
// Why two lookups: the prefilter stores the GGX lobe under Karis' n = v = R, isotropic
// about its axis; the real lobe at n != v is narrowed across the plane of incidence by n.v,
// cut by the horizon and lengthened towards n (lobe_tap_fit.h). One lookup cannot follow
// it at any direction and lod: on the neutral studio (ibl_accuracy_test's sphere) a metal
// at roughness 0.5 kept a mean / worst error of 6.3 / 30 levels with the lookup at the
// dominant direction (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based
// Rendering", section 4.9.3, fed GGX's alpha) and 3.2 / 12 with the direction and lod
// chosen per ring of equal n.v against the reference itself. Two, a narrow core near R and
// a wider halo towards n, fitted to the lobe (not to an environment) in the table, bring it
// to 3.6 / 24, and 2.9 / 14 on an outdoor scene it was not fitted on (8.9 / 41 with one);
// at roughness 1, where the lobe widens towards a uniform hemisphere at grazing n.v, the
// halo reads into the wide level (1.06 / 9 -> 0.45 / 2). Below roughness 0.25 both are the
// one lookup at the dominant direction (a shader may skip the second fetch there). The
// one lookup remains as SpecularLookup::DominantDirection to measure against:
//   D = mix(n, R, (1 - alpha) (sqrt(1 - alpha) + alpha)),  lod = levelOfRoughness(r, L)
//
// Filtering: the CPU reads the specular cube as GL's textureLod with
// GL_LINEAR_MIPMAP_LINEAR and seamless cube filtering (sampleCubeTrilinear; the only
// difference is at the cube's 8 corners, where GL leaves the fourth tap to the driver), the
// irradiance cube as GL_LINEAR (seamless), and both tables as GL_LINEAR with
// GL_CLAMP_TO_EDGE, with exact float weights where a GPU may quantise them (commonly to 8
// bits of fraction; expected well below one 8-bit level, not measured here), and the lobe
// tap table as floats where the GPU holds RGBA16F (k to 1e-3, d to 1/1000 of a level).
#pragma once

#include "brdf.h"
#include "brdf_table.h"
#include "prefilter.h"

#include <glm/glm.hpp>

namespace lfd::lighting {

// Which diffuse irradiance the shader reads.
enum class IrradianceSource { Sh9, Cube };

// Which specular lookup: the shaders' two lookups from the lobe tap table, or the one
// lookup at the dominant direction they replaced (kept to measure against).
enum class SpecularLookup { LobeTaps, DominantDirection };

// Outgoing radiance (linear, before exposure and tone mapping) towards v from a surface with
// unit normal n, lit by the prefiltered environment (prefilterEnvironment's levels: the
// GGX levels and the wide level last).
glm::vec3 splitSumIbl(const PrefilteredEnvironment& environment, const BrdfTable& table, const PbrMaterial& material,
                      glm::vec3 n, glm::vec3 v, IrradianceSource irradiance,
                      SpecularLookup lookup = SpecularLookup::LobeTaps);

} // namespace lfd::lighting
