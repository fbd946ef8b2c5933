#version 450
// EIA construction (formats/display_profiles.md section 2): one invocation per panel pixel writes its three
// subpixels. Subpixel column k = 3x + i (physical order on the panel), pixel row l (0 =
// top of the panel). Its phase under the lens array follows the profile's SubpixelMapping
// (van Berkel 1999 in affine form), exactly as lfd::subpixelPhase computes it on the CPU:
//   phase = fract(perSubpixel * k + perRow * l + offset),  1 - phase if inverted,
// and the subpixel shows channel i (RGB stripe) or 2 - i (BGR) of the views around
// phase * N. Each view covers the whole screen, so the view pixel read is the one under
// the subpixel's screen position (u, v) = ((k + 0.5) / 3W, (l + 0.5) / H).
// The phase is computed in double precision (shaders/subpixel_phase.glsl says why).

// Reconstruction modes (C++: lfd::player::Reconstruction, checked by a test), paper
// section 4, in linear light, computed exactly (no random samples: no fixed noise pattern,
// one or two fetches per subpixel):
//   spatial: the view prefiltered by eia_prefilter.comp (a 3-tap kernel of variance
//            sigma^2, sigma = 0.375 view pixels), read bilinearly at the subpixel's
//            screen position: tent * kernel, the spread of the paper's 2.25 view-pixel
//            Gaussian applied to the bilinear image;
//   view:    linear between the two view centres around the subpixel's view coordinate
//            c = phase * N: a tent over the paper's support of 2 view intervals (the
//            views at the cone's ends repeat);
//   view-spatial: both, one trilinear fetch of the prefiltered views (z = view).
#include "eia_bindings.glsl"
// The mode is compiled in (C++ builds one program per mode, prepending "#define EIA_MODE
// n"), not a uniform: llvmpipe runs an untaken branch under an all-off lane mask at full
// cost, so a uniform `mode` made nearest-view EIAs pay for the 8-sample filter too.
#ifndef EIA_MODE
#define EIA_MODE EIA_MODE_NONE
#endif

layout(local_size_x = EIA_LOCAL_SIZE, local_size_y = EIA_LOCAL_SIZE) in;

// N views, layer = view, GL row 0 = bottom, read with texelFetch (no filtering): in mode
// none as stored (sRGB-encoded values passed through untouched, bit-exact with the CPU),
// in mode view through an sRGB texture view (linear values).
layout(binding = EIA_UNIT_VIEWS) uniform sampler2DArray views;
// Spatial modes: the views prefiltered in linear light (eia_prefilter.comp), RGBA16F, a 3D
// texture (z = view) with trilinear filtering, edges clamped.
layout(binding = EIA_UNIT_PREFILTERED) uniform sampler3D prefiltered;
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

#include "subpixel_phase.glsl"

double subpixelPhase(uint k, uint l)
{
    return subpixelPhase(k, l, perSubpixel, perRow, phaseOffset, invertPhase);
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

#include "srgb.glsl"

// Linear -> sRGB-encoded value, quantised to the 8-bit level the image stores.
float encodeSrgb(float linear)
{
    const float e = linearToSrgb(vec3(linear)).x;
    return round(clamp(e, 0.0, 1.0) * 255.0) / 255.0;
}

// View v clamped to the cone (the cone's ends repeat their views).
uint clampedView(int v)
{
    return uint(clamp(v, 0, int(viewCount) - 1));
}

float filtered(uint k, uint l, uint channel, double phase)
{
    const double c = phase * double(viewCount);
#if EIA_MODE == EIA_MODE_VIEW
    // The view centres around c: views floor(c - 1/2) and the next, weighted linearly.
    const double below = floor(c - 0.5LF);
    const float a = float(c - 0.5LF - below);
    const ivec2 texel = viewTexelUnder(k, l);
    const float v0 = texelFetch(views, ivec3(texel, int(clampedView(int(below)))), 0)[channel];
    const float v1 = texelFetch(views, ivec3(texel, int(clampedView(int(below) + 1))), 0)[channel];
    return encodeSrgb(mix(v0, v1, a));
#else
    // The subpixel's screen position in view pixels: ((2k + 1) w / 6W, (2l + 1) h / 2H).
    const vec2 p = vec2(float((2u * k + 1u) * viewSize.x) / float(6u * panelSize.x),
                        float((2u * l + 1u) * viewSize.y) / float(2u * panelSize.y));
#if EIA_MODE == EIA_MODE_SPATIAL
    const float z = (float(clampedView(int(floor(c)))) + 0.5) / float(viewCount); // the view's centre
#else
    const float z = float(c / double(viewCount)); // linear between the two view centres around c
#endif
    const vec3 uvw = vec3(p.x / float(viewSize.x), 1.0 - p.y / float(viewSize.y), z);
    return encodeSrgb(textureLod(prefiltered, uvw, 0.0)[channel]);
#endif
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
