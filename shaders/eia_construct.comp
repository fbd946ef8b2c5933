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

// Reconstruction modes (C++: lfd::player::Reconstruction, checked by a test), paper
// section 4: Gaussian filters integrated with EIA_SAMPLES random Gaussian samples (the
// offsets come from C++, lfd::player::reconstructionSamples, seeded, the same for every
// subpixel, so the filter is fixed and reproducible) and averaged in linear light.
//   spatial: 2.25 view-pixel diameter (sigma 0.375, truncated at 3 sigma) around the
//            subpixel's screen position, each sample a bilinear fetch of the view;
//   view:    support of 2 view intervals (sigma 1/3, truncated at 3 sigma) around the
//            subpixel's view coordinate phase * N, each sample the nearest view there;
//   view-spatial: both at once (samples offset in x, y and view).
#include "eia_bindings.glsl"
// The mode is compiled in (C++ builds one program per mode, prepending "#define EIA_MODE
// n"), not a uniform: llvmpipe runs an untaken branch under an all-off lane mask at full
// cost, so a uniform `mode` made nearest-view EIAs pay for the 8-sample filter too.
#ifndef EIA_MODE
#define EIA_MODE EIA_MODE_NONE
#endif

layout(local_size_x = EIA_LOCAL_SIZE, local_size_y = EIA_LOCAL_SIZE) in;

// N views, RGBA8 (sRGB-encoded values, passed through untouched), layer = view, GL row 0 =
// bottom. Read with texelFetch: no filtering, so the result is bit-exact with the CPU.
layout(binding = EIA_UNIT_VIEWS) uniform sampler2DArray views;
// Panel-size RGBA8 output, GL row 0 = bottom (panel row l = H - 1 - GL row).
layout(binding = EIA_IMAGE_EIA, rgba8) uniform writeonly image2D eia;

layout(location = EIA_LOC_PANEL_SIZE) uniform uvec2 panelSize;     // W, H in pixels
layout(location = EIA_LOC_VIEW_SIZE) uniform uvec2 viewSize;       // view width, height in pixels
layout(location = EIA_LOC_VIEW_COUNT) uniform uint viewCount;      // N
layout(location = EIA_LOC_PER_SUBPIXEL) uniform double perSubpixel; // SubpixelMapping
layout(location = EIA_LOC_PER_ROW) uniform double perRow;
layout(location = EIA_LOC_PHASE_OFFSET) uniform double phaseOffset;
layout(location = EIA_LOC_INVERT_PHASE) uniform bool invertPhase;
layout(location = EIA_LOC_SUBPIXELS_BGR) uniform bool subpixelsBgr;
// Filter samples: x, y in view pixels (image order: +y down), z in view intervals.
layout(location = EIA_LOC_SAMPLES) uniform vec3 samples[EIA_SAMPLES];
// sRGB-encoded byte -> linear value, from C++ (so the CPU reference decodes identically).
layout(location = EIA_LOC_LINEAR_FROM_BYTE) uniform float linearFromByte[256];

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

// floor(a / b) for unsigned a, b > 0 with a < 2^31, exactly: a float quotient (within a
// few ulps of the true one, so off by at most one below 2^24) corrected by one integer
// multiply each way. Why not a / b: integer division has no vector instruction, so
// llvmpipe divides lane by lane (two divisions per subpixel made them the bulk of the
// EIA pass); this is a handful of vector operations.
uint floorDivide(uint a, uint b)
{
    uint q = uint(float(a) / float(b));
    q -= (q * b > a) ? 1u : 0u;
    q += ((q + 1u) * b <= a) ? 1u : 0u;
    return q;
}

// The view texel under subpixel (k, l): the view pixel containing its screen position,
// in exact integer arithmetic (floor((k + 0.5) / 3W * viewWidth) without rounding).
ivec2 viewTexelUnder(uint k, uint l)
{
    const uint x = floorDivide((2u * k + 1u) * viewSize.x, 6u * panelSize.x);
    const uint rowFromTop = floorDivide((2u * l + 1u) * viewSize.y, 2u * panelSize.y);
    return ivec2(int(x), int(viewSize.y - 1u - rowFromTop));
}

// Nearest view: the subpixel takes its channel from view floor(phase * N).
float nearestView(uint k, uint l, uint channel, double phase)
{
    const uint view = min(viewCount - 1u, uint(floor(phase * double(viewCount))));
    return texelFetch(views, ivec3(viewTexelUnder(k, l), int(view)), 0)[channel];
}

// The view a sample at view coordinate c lands in (views clamp at the cone's ends).
uint viewAt(double c)
{
    return uint(clamp(floor(c), 0.0LF, double(viewCount - 1u)));
}

// Linear value of channel `channel` of view texel (x, image row y), clamped to the view.
float linearTexel(int x, int y, uint view, uint channel)
{
    x = clamp(x, 0, int(viewSize.x) - 1);
    y = clamp(y, 0, int(viewSize.y) - 1);
    const float v = texelFetch(views, ivec3(x, int(viewSize.y) - 1 - y, int(view)), 0)[channel];
    return linearFromByte[uint(round(v * 255.0))];
}

// Bilinear fetch (linear light) at view-pixel position p (image order, pixel centres at
// integer + 0.5), edge texels repeated.
float bilinear(vec2 p, uint view, uint channel)
{
    const vec2 f = p - vec2(0.5);
    const vec2 base = floor(f);
    const vec2 a = f - base;
    const int x = int(base.x), y = int(base.y);
    const float top = mix(linearTexel(x, y, view, channel), linearTexel(x + 1, y, view, channel), a.x);
    const float bottom = mix(linearTexel(x, y + 1, view, channel), linearTexel(x + 1, y + 1, view, channel), a.x);
    return mix(top, bottom, a.y);
}

#include "srgb.glsl"

// Linear -> sRGB-encoded value, quantised to the 8-bit level the image stores.
float encodeSrgb(float linear)
{
    const float e = linearToSrgb(vec3(linear)).x;
    return round(clamp(e, 0.0, 1.0) * 255.0) / 255.0;
}

// The Gaussian reconstructions: EIA_SAMPLES samples averaged in linear light.
float filtered(uint k, uint l, uint channel, double phase)
{
    const double c = phase * double(viewCount);
    // The subpixel's screen position in view pixels: ((2k + 1) w / 6W, (2l + 1) h / 2H).
    const vec2 p = vec2(float((2u * k + 1u) * viewSize.x) / float(6u * panelSize.x),
                        float((2u * l + 1u) * viewSize.y) / float(2u * panelSize.y));
    const ivec2 texel = viewTexelUnder(k, l);
    const int imageRow = int(viewSize.y) - 1 - texel.y;
    float sum = 0.0;
    for (int s = 0; s < EIA_SAMPLES; ++s) {
#if EIA_MODE == EIA_MODE_SPATIAL
        const uint view = viewAt(c);
#else
        const uint view = viewAt(c + double(samples[s].z));
#endif
#if EIA_MODE == EIA_MODE_VIEW
        sum += linearTexel(texel.x, imageRow, view, channel);
#else
        sum += bilinear(p + samples[s].xy, view, channel);
#endif
    }
    return encodeSrgb(sum / float(EIA_SAMPLES));
}

float subpixelValue(uint k, uint l, uint channel)
{
    const double phase = subpixelPhase(k, l);
#if EIA_MODE == EIA_MODE_NONE
    return nearestView(k, l, channel, phase);
#else
    return filtered(k, l, channel, phase);
#endif
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
