#version 450
// EIA construction (formats/display_profiles.md section 2): one invocation per panel pixel writes its three
// subpixels. Subpixel column k = 3x + i (physical order on the panel), pixel row l (0 =
// top of the panel). Its phase under the lens array follows the profile's SubpixelMapping
// (van Berkel 1999 in affine form), exactly as lfd::subpixelPhase computes it on the CPU:
//   phase = fract(perSubpixel * k + perRow * l + offset),  1 - phase if inverted,
// and the subpixel shows channel i (RGB stripe) or 2 - i (BGR) of the views around
// phase * N. Each view covers the whole screen, so the view pixel read is the one under
// the subpixel's screen position (u, v) = ((k + 0.5) / 3W, (l + 0.5) / H).
//
// note: the phase is computed in double precision. With single precision the argument
// perSubpixel * k reaches 3W / X ~ 480 for the prototype, where a float ulp (3e-5) is
// ~1.5e-3 of a view interval at 48 views, so subpixels near a view boundary would pick a
// different view than the CPU reference. `precise` forbids fused multiply-adds, which
// the CPU (x86-64 SSE2, -ffp-contract=off in ISO C++ mode) does not use either.

// Reconstruction modes (C++: lfd::player::Reconstruction, checked by a test). Only
// nearest view exists so far; the Gaussian modes of the paper's section 4 (spatial: 2.25
// view-pixel diameter, view: support of 2 view intervals, view-spatial; 8 random Gaussian
// samples each) become further cases of subpixelValue().
#define EIA_MODE_NONE 0

#define EIA_LOCAL_SIZE 8
layout(local_size_x = EIA_LOCAL_SIZE, local_size_y = EIA_LOCAL_SIZE) in;

// N views, RGBA8 (sRGB-encoded values, passed through untouched), layer = view, GL row 0 =
// bottom. Read with texelFetch: no filtering, so the result is bit-exact with the CPU.
layout(binding = 0) uniform sampler2DArray views;
// Panel-size RGBA8 output, GL row 0 = bottom (panel row l = H - 1 - GL row).
layout(binding = 0, rgba8) uniform writeonly image2D eia;

uniform uvec2 panelSize;   // W, H in pixels
uniform uvec2 viewSize;    // view width, height in pixels
uniform uint viewCount;    // N
uniform double perSubpixel; // SubpixelMapping
uniform double perRow;
uniform double phaseOffset;
uniform bool invertPhase;
uniform bool subpixelsBgr;
uniform uint mode;         // EIA_MODE_*

// Same operations, in the same order, as lfd::subpixelPhase (formats/src/display_profile.cpp).
double subpixelPhase(uint k, uint l)
{
    precise double phase = perSubpixel * double(k) + perRow * double(l) + phaseOffset;
    phase -= floor(phase);
    if (invertPhase)
        phase = 1.0LF - phase;
    // 1 is the same lens position as 0 (x - floor(x) can round up to 1 for tiny negative x).
    if (phase >= 1.0LF)
        phase = 0.0LF;
    return phase;
}

// The view texel under subpixel (k, l): the view pixel containing its screen position,
// in exact integer arithmetic (floor((k + 0.5) / 3W * viewWidth) without rounding).
ivec2 viewTexelUnder(uint k, uint l)
{
    const uint x = ((2u * k + 1u) * viewSize.x) / (6u * panelSize.x);
    const uint rowFromTop = ((2u * l + 1u) * viewSize.y) / (2u * panelSize.y);
    return ivec2(int(x), int(viewSize.y - 1u - rowFromTop));
}

// Nearest view: the subpixel takes its channel from view floor(phase * N).
float nearestView(uint k, uint l, uint channel, double phase)
{
    const uint view = min(viewCount - 1u, uint(floor(phase * double(viewCount))));
    return texelFetch(views, ivec3(viewTexelUnder(k, l), int(view)), 0)[channel];
}

float subpixelValue(uint k, uint l, uint channel)
{
    const double phase = subpixelPhase(k, l);
    switch (mode) {
    case EIA_MODE_NONE:
    default:
        return nearestView(k, l, channel, phase);
    }
}

void main()
{
    const uvec2 pixel = gl_GlobalInvocationID.xy; // x, GL row
    if (any(greaterThanEqual(pixel, panelSize)))
        return;
    const uint l = panelSize.y - 1u - pixel.y; // panel row, 0 = top

    vec4 rgba = vec4(0.0, 0.0, 0.0, 1.0);
    for (uint i = 0u; i < 3u; ++i) {
        const uint channel = subpixelsBgr ? 2u - i : i;
        rgba[channel] = subpixelValue(3u * pixel.x + i, l, channel);
    }
    imageStore(eia, ivec2(pixel), rgba);
}
