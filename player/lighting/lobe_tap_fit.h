// The fit behind the lobe tap table (lobe_taps.h): for one (n.v, roughness), the two
// prefiltered lookups whose average gathers the same share of the glTF specular lobe as the
// lobe itself from every half-space of the sphere.
//
// The lobe: w(l) = D(h) Vis(n.l, n.v) (n.l) of brdf.h (Fresnel left out: it is the table's
// A and B), l = reflect(-v, h). At n != v it is not the isotropic lobe the prefilter stores
// around R: the reflection's Jacobian keeps its in-plane width but narrows it across the
// plane of incidence by n.v (l moves by 2 dh in the plane, 2 (n.v) dh across it), and the
// horizon and the (n.l) weight cut its far side and lengthen its side towards n. One
// isotropic lookup, whatever its direction and lod, cannot follow that: on the neutral
// studio (ibl_accuracy_test's sphere, white metal, roughness 0.5) even the direction and
// lod chosen per ring of equal n.v against the reference itself leave a mean / worst error
// of 3.2 / 12 levels; two lookups chosen that way (five numbers a ring) reach 1.8 / 8: a
// narrow "core" near R and a wider "halo" towards n.
//
// The lookups: each reads the cube at direction normalize(mix(n, R, k)) with the lod of
// alpha' = alpha 2^d (levelOfAlpha, prefilter.h), and gathers the lookup lobe of alpha'
// around that direction, idealised as a family continuous in alpha': the GGX lobe at
// n = v for alpha' <= 1 (the prefilter's levels) and, for alpha' in (1, 2], the mix of
// the alpha = 1 lobe and the wide level's with weight log2(alpha') (what trilinear reads
// between the last two levels). The runtime's trilinear mix of two GGX levels for an
// alpha' between them is the same approximation the one-lookup split sum makes.
//
// The distance: for 50 directions e (a Fibonacci set on the half of the sphere on one side
// of the plane of incidence; both lobes are symmetric about it) and the 7 offsets t where
// the lobe's projection l.e has its 5, 20, ..., 95% quantiles, the share of the two
// lookups' lobes (half each) in {l : l.e > t} against the lobe's own (1 - quantile), root
// mean square: a sliced Cramer-von Mises distance between the two as distributions on the
// sphere. It is the error both make at a sharp edge of contrast C (a softbox, a horizon),
// C times the share difference, so it weighs every edge orientation and position the lobe
// can meet, and no environment. Choices made on the neutral studio (white metal, roughness
// 0.5, mean / worst levels, in a prototype that fitted to the player's discrete levels):
// quantiles 5, 20, ..., 95%: 3.9 / 25; 2, 10, 25, 50, 75, 90, 98%: 4.1 / 28; 1 .. 99% with
// the relative error at a 25:1 edge: 5.0 / 42. A fit against the sphere's pixels over eight
// random environments (soft disks and rectangles, gradient skies) found the same core /
// halo structure and was worse on three of the four test environments.
//
// Search: Nelder-Mead (Nelder & Mead 1965) over (k0, log2 alpha'0, k1, log2 alpha'1), k in
// [0, 1.5] (between n and a little beyond R: allowing k < 0 let the fit split the lookups
// around n at roughness 1, which doubled the sun and sky's mean error there), log2 alpha'
// in [-4, 1] (LookupLobeShares), from the neighbours' solutions and a generic core / halo
// start. Equal weights: a free weight (fitted 0.47 to 0.74) was no better on any of the
// four test environments.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lfd::lighting {

// Shares of the lookup lobes in half-spaces, tabulated over log2 alpha' (-4 .. 1), the
// angle between the lobe's axis and the half-space's normal, and the offset t.
class LookupLobeShares {
public:
    LookupLobeShares();
    // The share of the lookup lobe of alpha' = 2^log2Alpha, axis a, in {l : l.e > t}, for
    // cosAxis = a.e (linear in each table coordinate).
    float above(float log2Alpha, float cosAxis, float t) const;

    // From the player's first GGX level (alpha 2^(2 - levels) = 1/16, prefilter.h): below
    // it a lookup reads the mirror level mixed with that level, a spike on a wide lobe that
    // is no GGX lobe, so the lookups stay at or above it; up to the wide level.
    static constexpr float kMinLog2Alpha = -4.0f;
    static constexpr float kMaxLog2Alpha = 1.0f;

private:
    std::vector<float> shares_;
};

// One half-space {l : l.e > t} and the share of the lobe in it; frame n = +Z, v in the
// xz plane with v.x > 0 (R at -x).
struct HalfSpaceShare {
    glm::vec3 e;
    float t;
    float share;
};

// The half-spaces of the distance for the lobe at (n.v, alpha).
std::vector<HalfSpaceShare> lobeHalfSpaces(float nDotV, float alpha);

// Two lookups: (k0, d0, k1, d1), lookup i at normalize(mix(n, R, k_i)) with alpha 2^d_i.
using LobeTaps = glm::vec4;

// The distance of the two lookups (weight 1/2 each) from the lobe whose half-spaces these are.
double lobeTapDistance(const LookupLobeShares& shares, const std::vector<HalfSpaceShare>& halfSpaces, float nDotV,
                       float alpha, LobeTaps taps);

// One lookup at the dominant direction (split_sum.h's SpecularLookup::DominantDirection)
// at alpha, as two equal taps.
LobeTaps dominantDirectionTaps(float roughness);

// The best two lookups for (n.v, roughness) from `starts`: tap 0 the one nearer R (the
// larger k). n.v is floored at kMinNDotV and alpha at 1e-3, as the shader does. Below
// alpha 2^kMinLog2Alpha (roughness 0.25: lobes narrower than the first GGX level, which
// two lookups cannot shape), dominantDirectionTaps.
LobeTaps fitLobeTaps(const LookupLobeShares& shares, float nDotV, float roughness, const std::vector<LobeTaps>& starts);

// The whole table: `size` x `size` texels laid out as the BRDF table (column = n.v, row =
// roughness, brdf_table.h), 4 floats each. Each row is fitted along n.v from 0.6 outwards,
// each texel starting from its neighbour's solution; a second pass restarts every texel
// from its four neighbours and keeps the best, so the table is smooth where the optimum
// is. Rows run on every core; deterministic.
std::vector<float> fitLobeTapTable(uint32_t size);

} // namespace lfd::lighting
