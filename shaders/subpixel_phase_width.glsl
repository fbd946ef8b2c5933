// The width of the fixed-point subpixel phase (formats/display_profiles.md section 2): a
// phase is an unsigned integer in units of 2^-LFD_SUBPIXEL_PHASE_BITS lens periods. Shared,
// as this one file, by the shaders (shaders/subpixel_phase.glsl) and by C++
// (formats/include/lfd/subpixel_phase.h includes it; the file holds nothing but this
// #define, so both preprocessors read it). Both sides rely on it being 64: the phase is the
// whole 64-bit word, so the integer wrap-around of the increments' sum is the fract().
#define LFD_SUBPIXEL_PHASE_BITS 64
