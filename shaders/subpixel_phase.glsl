// A panel subpixel's phase under the lens array in fixed point (formats/display_profiles.md
// section 2): the one GLSL definition, included by the EIA pass and gstd's panel model, with
// the same integer operations as lfd::fixedSubpixelPhase / fixedPhaseView
// (formats/include/lfd/subpixel_phase.h), so GPU and CPU give the same view index on every
// subpixel. Subpixel column k = 3x + i, pixel row l (0 = top).
//
// A phase is a uint64_t in 2^-64 lens periods (LFD_SUBPIXEL_PHASE_BITS): the sum of the
// profile's increments wraps around modulo 2^64, which is the fract(). Why not doubles:
// FP64 runs at 1/64 of the FP32 rate on desktop GPUs, and 64-bit integer adds and
// multiplies (GL_ARB_gpu_shader_int64, on every GL 4.5 GPU we target and on llvmpipe) are a
// few 32-bit operations; and the result is exact (docs/player/subpixel-phase.md).
// The including shader enables GL_ARB_gpu_shader_int64 before its first declaration.
#include "subpixel_phase_width.glsl"
#if LFD_SUBPIXEL_PHASE_BITS != 64
#error "the phase is the whole uint64_t: its wrap-around is the fract()"
#endif

// A 2^-64 fixed-point value handed over as uvec2(low word, high word) (glUniform2ui).
uint64_t fixedPhaseUniform(uvec2 words)
{
    return packUint2x32(words);
}

// The phase before inversion: perSubpixel * k + perRow * l + offset (mod 2^64).
uint64_t fixedRawSubpixelPhase(uint k, uint l, uint64_t perSubpixel, uint64_t perRow, uint64_t offset)
{
    return perSubpixel * uint64_t(k) + perRow * uint64_t(l) + offset;
}

// The phase after inversion (the profile's view order): -P mod 2^64, so 0 stays 0.
uint64_t fixedSubpixelPhase(uint64_t raw, bool invertPhase)
{
    return invertPhase ? 0UL - raw : raw;
}

// floor(phase * N / 2^64) in [0, N): the high word of the 96-bit product from two
// 32 x 32-bit products.
uint fixedPhaseView(uint64_t phase, uint viewCount)
{
    const uint64_t high = (phase >> 32) * uint64_t(viewCount);
    const uint64_t low = (phase & 0xFFFFFFFFUL) * uint64_t(viewCount);
    return uint((high + (low >> 32)) >> 32);
}

// frac(phase * N) in 2^-64 units: the product's low word.
uint64_t fixedPhaseViewFraction(uint64_t phase, uint viewCount)
{
    return phase * uint64_t(viewCount);
}

// A phase (or a view fraction) as a float in [0, 1], rounded to nearest.
float fixedPhaseToFloat(uint64_t phase)
{
    return ldexp(float(phase), -64);
}
