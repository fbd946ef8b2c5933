// The subpixel phase in fixed point (formats/display_profiles.md section 2, "Fixed-point
// phase"; docs/player/subpixel-phase.md says why): the one definition on the CPU, used by
// lfd::subpixelPhase / subpixelView, the CPU EIA reference and gstd's CPU paths. The GPU
// twin is shaders/subpixel_phase.glsl, operation for operation, so both give the same
// view index on every subpixel.
//
// A phase is a uint64_t in units of 2^-64 lens periods (LFD_SUBPIXEL_PHASE_BITS, shared
// with the shaders). The profile's three increments are converted once, each to its
// fraction in those units; per subpixel the phase is
//   P(k, l) = perSubpixel * k + perRow * l + offset   (mod 2^64: unsigned wrap-around is
//                                                      the fract(), nothing can overflow)
//   inverted: P = -P (mod 2^64, so 0 stays 0)
//   view    = floor(P * N / 2^64)                      (always in [0, N))
// Every increment of magnitude >= 2^-12 (a lens under 4096 subpixels) converts exactly, so
// P is then the exact phase of the profile's double-precision mapping, not an approximation.
#pragma once

#include "lfd/display_profile.h"

#include "subpixel_phase_width.glsl" // LFD_SUBPIXEL_PHASE_BITS

#include <cmath>
#include <cstdint>

namespace lfd {

inline constexpr int kSubpixelPhaseBits = LFD_SUBPIXEL_PHASE_BITS;
static_assert(kSubpixelPhaseBits == 64, "the phase is the whole uint64_t: its wrap-around is the fract()");

// SubpixelMapping's increments as fractions of a lens period in 2^-64 units.
struct FixedSubpixelMapping {
    uint64_t perSubpixel = 0;
    uint64_t perRow = 0;
    uint64_t offset = 0;
    bool invert = false;
};

// fract(x) * 2^64, rounded to the nearest integer (ties to even), mod 2^64. Exact when x is
// 0 or |x| >= 2^-12 (every bit of the double then lies at or above 2^-64). x must be finite.
uint64_t fixedPhaseFromDouble(double x);

// The mapping converted once per profile.
FixedSubpixelMapping fixedSubpixelMapping(const SubpixelMapping& mapping);

// The phase before inversion of subpixel column k (0..3W-1) on pixel row l (0 = top).
inline uint64_t fixedRawSubpixelPhase(const FixedSubpixelMapping& m, uint32_t k, uint32_t l) {
    return m.perSubpixel * k + m.perRow * l + m.offset;
}

// The phase after inversion (the profile's view order).
inline uint64_t fixedSubpixelPhase(const FixedSubpixelMapping& m, uint32_t k, uint32_t l) {
    const uint64_t raw = fixedRawSubpixelPhase(m, k, l);
    return m.invert ? uint64_t(0) - raw : raw;
}

// floor(phase * N / 2^64): the high word of the 96-bit product, from two 32 x 32-bit
// products (no 128-bit type on the GPU; the sum cannot overflow for any N < 2^32).
inline uint32_t fixedPhaseView(uint64_t phase, uint32_t viewCount) {
    const uint64_t high = (phase >> 32) * viewCount;
    const uint64_t low = (phase & 0xFFFFFFFFull) * viewCount;
    return uint32_t((high + (low >> 32)) >> 32);
}

// The view coordinate's fraction, frac(phase * N) in 2^-64 units (the product's low word).
inline uint64_t fixedPhaseViewFraction(uint64_t phase, uint32_t viewCount) { return phase * viewCount; }

// The phase as a double in [0, 1): its top 53 bits (truncated, so never 1).
inline double fixedPhaseToDouble(uint64_t phase) { return std::ldexp(double(phase >> 11), -53); }

// The phase (or a view fraction) as a float, rounded to nearest; GLSL's float(uint64_t)
// times 2^-64, as shaders/subpixel_phase.glsl converts it.
inline float fixedPhaseToFloat(uint64_t phase) { return std::ldexp(float(phase), -64); }

// The pixel stride s (1 .. maxStride) along a row over which the phase comes back nearest
// to itself: 3 s perSubpixel closest to a whole number of lens periods, the smallest such s
// on ties. Pixels s apart then show the same view up to a drift of that distance times N
// views. Returns 1 where even the best stride drifts more than maxDriftViews. The EIA pass
// orders its invocations by it (eia_construct.comp, lensOrderedColumn).
uint32_t samePhasePixelStride(const DisplayProfile& profile, uint32_t maxStride, double maxDriftViews);

} // namespace lfd
