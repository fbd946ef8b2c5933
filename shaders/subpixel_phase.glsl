// A panel subpixel's phase under the lens array (formats/display_profiles.md section 2):
// the one GLSL definition, included by the EIA pass and gstd's panel model, with the same
// operations in the same order as lfd::subpixelPhase (formats/src/display_profile.cpp), so
// GPU and CPU agree bit for bit. Subpixel column k = 3x + i, pixel row l (0 = top).
//
// note: double precision. With single precision the argument perSubpixel * k reaches
// 3W / X ~ 480 for the prototype, where a float ulp (3e-5) is ~1.5e-3 of a view interval
// at 48 views, so subpixels near a view boundary would pick a different view than the CPU
// reference. `precise` forbids fused multiply-adds, which the CPU (x86-64 SSE2,
// -ffp-contract=off in ISO C++ mode) does not use either.

// The phase before inversion: fract(perSubpixel * k + perRow * l + offset), in [0, 1).
double rawSubpixelPhase(uint k, uint l, double perSubpixel, double perRow, double phaseOffset)
{
    precise double phase = perSubpixel * double(k) + perRow * double(l) + phaseOffset;
    phase -= floor(phase);
    // 1 is the same lens position as 0 (x - floor(x) can round up to 1 for tiny negative x).
    return phase >= 1.0LF ? 0.0LF : phase;
}

// The view coordinate / N: the raw phase, reversed where the profile inverts it.
double subpixelPhase(uint k, uint l, double perSubpixel, double perRow, double phaseOffset, bool invertPhase)
{
    double phase = rawSubpixelPhase(k, l, perSubpixel, perRow, phaseOffset);
    if (invertPhase)
        phase = 1.0LF - phase;
    return phase >= 1.0LF ? 0.0LF : phase;
}
