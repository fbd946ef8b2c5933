// The environment prefiltered once for the split sum (Karis 2013, "Real Shading in Unreal
// Engine 4"): a cube map whose mip level l holds the radiance convolved with the GGX lobe of
// roughness roughnessOfLevel(l) around the lookup direction, under Karis' assumption
// n = v = R:
//   prefiltered(R) = sum L(l_i) w_i / sum w_i,  h_i ~ D(h) (n.h),  l_i = reflect(-R, h_i),
//   w_i = Vis(n.l_i, n.v = 1) (n.l_i)
// note: Karis weights by n.l alone; the extra Vis (the Smith term of brdf.h at n.v = 1)
// makes the weights D Vis (n.l) of the real lobe at normal incidence, so there the split
// sum is exact but for Fresnel. Measured on the neutral studio (ibl_accuracy_test's
// sphere, white metal, one lookup at the dominant direction, split_sum.h): roughness 1 mean
// / worst error 3.9 / 16 -> 1.1 / 9 levels, roughness 0.5 7.6 / 25 -> 6.3 / 30.
// Two ways to evaluate it, by level size:
// * faces up to directFaceSize: exactly, as a sum over every texel of the source level of
//   directSourceSize (cube_convolution.h; at n = v the weight depends on n.l alone), so a
//   sun is weighed exactly where sampling caught more or less of it depending on where the
//   samples fell (metallic, roughness 1, under a sun: mean error 8.6 -> 2.8 levels). A
//   source as coarse as the level itself (8 texels for roughness 1) moves a sun by up to
//   half a texel: 6.3 levels.
// * larger faces (the sharp lobes, where a full sum would cost 6 size^2 x 6 size^2):
//   filtered importance sampling (Krivanek & Colbert 2008, "Real-time Shading with Filtered
//   Importance Sampling"): each sample reads the source's box mip chain at the lod whose
//   texel solid angle matches the sample's, 1 / (samples * pdf(l)), plus `lodBias`, with 4
//   times the samples per level (samplesOfLevel: a wider lobe needs more; the level has a
//   quarter of the texels). Against a brute-force sum on the neutral studio the player's
//   level 1 (16 samples) is off by 4% on average, 14% at worst, level 2 (64) by 4% / 16%:
//   this method's error, which falls slowly with more samples (256: 1% / 5% and 1% / 3%,
//   at 4 to 16 times the cost). The paper's bias of +1 blurs the softboxes: 21% / 52% on
//   level 1, so the bias is 0.
// Level 0 (roughness 0) is the source itself, the environment resampled
// (cube_from_environment.h).
//
// The wide level: after the GGX levels, level `levels` (face faceSize >> levels, summed
// exactly from the directSourceSize source) holds a lobe wider than alpha = 1, the glTF
// lobe at alpha = 1 seen at n.v = kWideLobeNDotV (0.2):
//   w(l) = Vis(n.l, 0.2, alpha = 1) (n.l) = 0.5 (n.l) / (n.l + 0.2)
// At alpha = 1 (D = 1 / pi, Vis = 0.5 / (n.l + n.v)) the lobe of any n.v is
// (n.l) / (n.l + n.v), symmetric about n: level levels - 1 holds n.v = 1, this level
// n.v = 0.2, and a lookup between them (lod levels - 1 .. levels) spans the rough lobe from
// normal incidence to grazing, which widens it towards a uniform hemisphere that no GGX
// level holds (ibl_accuracy_test: white metal at roughness 1 on the neutral studio,
// mean / worst 1.06 / 9 levels -> 0.45 / 2 with this level and lobe_taps.h's lookups).
// 0.2 is the test sphere's silhouette (n.v below it is not judged); it was chosen over 0.1
// and 0.05, which put that sphere's mean error 15% and 30% higher (one lookup at the lod
// that matches the lobe's mean n.l, 8-texel faces). Its faces (4 texels for the player) are
// too coarse to hold the sums at their texel centres: their values are fitted for bilinear
// reads (cube_least_squares.h). The lookup lod of a lobe alpha' (up to 2 for
// this level) is levelOfAlpha.
//
// Levels and roughness: level 0 is the mirror; level l >= 1 holds GGX alpha
//   alpha_l = 2^(l + 1 - levels)    (alpha = roughness^2; the last level alpha = 1)
// so each level's lobe spans about as many of its own texels as the next one (the mip chain
// halves the resolution as alpha doubles) and a near-mirror roughness reads level 0 almost
// alone. (Levels linear in roughness put 25% of the roughness-0.2 level into roughness
// 0.05, whose halo around every softbox cost 2.9 / 29 levels mean / worst on the test
// sphere, white metal, against 0.9 / 6 here.) The shader's lod for roughness r:
//   alpha = max(r^2, 1e-3), a1 = 2^(2 - levels)
//   lod = alpha < a1 ? (alpha - 1e-3) / (a1 - 1e-3) : 1 + log2(alpha / a1)
// (levelOfRoughness), read with textureLod(cube, direction, lod), GL_LINEAR_MIPMAP_LINEAR,
// seamless; the GGX levels end at lod levels - 1 (alpha 1), the wide level below it is
// lod `levels`. The diffuse irradiance comes as SH9 or a small cube (irradiance.h). Every array
// is ready for upload: float RGB, GL's face order and rows (cube_map.h), to RGBA16F or
// R11F_G11F_B10F.
#pragma once

#include "cube_map.h"
#include "environment.h"
#include "irradiance.h"

#include <cstdint>

namespace lfd::lighting {

// n.v of the wide level's lobe (see the header comment).
constexpr float kWideLobeNDotV = 0.2f;

struct PrefilterSettings {
    uint32_t faceSize = 256;            // level 0's face, a power of two
    uint32_t levels = 6;                // GGX levels, 2 .. log2(faceSize): level l has faceSize >> l,
                                        // and the wide level (index `levels`) faceSize >> levels
    uint32_t samplesPerTexel = 16;      // GGX samples per texel of level 1, 4 times as many per level
    uint32_t maxSamplesPerTexel = 512;  // ... up to this many
    float lodBias = 0.0f;               // filtered importance sampling's bias (in mip levels)
    uint32_t directFaceSize = 32;       // levels with faces up to this are convolved exactly,
    uint32_t directSourceSize = 32;     // ... from the source level of this face (or theirs, if larger)
    uint32_t irradianceSourceSize = 32; // the source cube level (face size) irradiance sums
    uint32_t irradianceFaceSize = 16;   // the irradiance cube's face

    // The player's: prefiltered at start-up, read by mvr, mvr-layered and lfdpr. 256
    // faces, 6 levels (roughness 0, 0.25, 0.35, 0.5, 0.71, 1; faces 256 .. 8) and the
    // wide level (face 4).
    static PrefilterSettings player();
    // gstd's: 512 faces, 8 levels (roughness 0, 0.125, 0.18, 0.25, 0.35, 0.5, 0.71, 1;
    // faces 512 .. 4) and the wide level (face 2), up to 1024 samples, rough levels summed
    // from a 64-texel source, a 32-texel irradiance cube.
    static PrefilterSettings reference();

    uint32_t samplesOfLevel(uint32_t level) const;
};

// Level <-> roughness, as in the header comment (the GGX levels: lod 0 .. levels - 1).
float roughnessOfLevel(uint32_t level, uint32_t levels);
float levelOfRoughness(float roughness, uint32_t levels);
// The lod that reads a lobe of GGX alpha' (>= 1e-3; the mapping of levelOfRoughness in
// alpha): alpha' in (1, 2] reaches into the wide level, lod levels - 1 + log2(alpha'),
// which holds the mix of the alpha = 1 lobe and the wide one; clamped to [0, levels].
float levelOfAlpha(float alpha, uint32_t levels);

struct PrefilteredEnvironment {
    CubeMap specular;          // settings.levels + 1 levels, level l of face faceSize >> l
    ShIrradiance irradianceSh; // E / pi as the SH9 polynomial
    CubeLevel irradianceCube;  // E / pi at texel centres, face irradianceFaceSize
};

// Throws std::invalid_argument (one line) for settings outside the ranges above or an
// environment validateEnvironment refuses. Deterministic: the same bytes on any number of
// cores.
PrefilteredEnvironment prefilterEnvironment(const Environment& environment, const PrefilterSettings& settings);

// One GGX level of face `size` for `roughness` from `source` (a mip chain down to 1 x 1,
// level 0 the radiance at full resolution) by filtered importance sampling, as
// prefilterEnvironment makes the levels larger than directFaceSize; rows run on every core.
CubeLevel prefilterGgxLevel(const CubeMap& source, float roughness, uint32_t size, uint32_t samples, float lodBias);
// The same level convolved exactly from `source` (a cube level, usually of face `size`).
CubeLevel convolveGgxLevel(const CubeLevel& source, float roughness, uint32_t size);
// The wide level of face `size`, convolved exactly from `source`.
CubeLevel convolveWideLevel(const CubeLevel& source, uint32_t size);

} // namespace lfd::lighting
