// The lobe tap table: where and how wide the shader's two specular lookups read the
// prefiltered cube, per (n.v, roughness), so that their average follows the glTF lobe at
// n != v, which one isotropic lookup cannot (lobe_tap_fit.h: the fit and why).
//
// Texel (k0, d0, k1, d1), laid out and read exactly as the BRDF table (brdf_table.h:
// column = n.v, row = roughness, GL_LINEAR, GL_CLAMP_TO_EDGE at brdfTableCoordinate; upload
// as RGBA16F). Lookup i reads
//   direction mix(n, R, k_i),  R = reflect(-v, n),  k_i in [0, 1.5]   (no unit vector needed)
//   lod       levelOfAlpha(alpha 2^d_i, levels)   (prefilter.h; alpha = max(r^2, 1e-3))
// and the specular radiance is their mean times (F0 A + B). Tap 0 is the "core", nearer R
// and narrower: at roughness 0.5, k0 from 0.7 at grazing n.v to 1.2 near normal incidence,
// d0 from -1.6 to -0.5; tap 1 the "halo" towards n, about as wide as the lobe: k1 0.2 to
// 0.55, d1 -0.1 to +0.7. At n = v both read about R at alpha, the split sum's exact case; at
// roughness 1 both read n and reach into the wide level (prefilter.h) at grazing n.v; below
// roughness 0.25 (alpha under the first GGX level's 1/16) both are the one lookup at the
// dominant direction (dominantDirectionTaps, lobe_tap_fit.h). The table is fitted offline by
// lfd_lobe_tap_gen and compiled in (lobe_taps_data.inc, 32 x 32).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lfd::lighting {

struct LobeTapTable {
    uint32_t size = 0;
    std::vector<float> taps; // size * size * 4: (k0, d0, k1, d1), row = roughness, column = n.v

    glm::vec4 texel(uint32_t column, uint32_t row) const
    {
        const float* p = taps.data() + (size_t(row) * size + column) * 4;
        return {p[0], p[1], p[2], p[3]};
    }
};

// The fitted table (lobe_taps_data.inc), built once.
const LobeTapTable& lobeTapTable();

// (k0, d0, k1, d1) as GL_LINEAR with GL_CLAMP_TO_EDGE reads it at brdfTableCoordinate.
glm::vec4 sampleLobeTapTable(const LobeTapTable& table, float nDotV, float roughness);

} // namespace lfd::lighting
