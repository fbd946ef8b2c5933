#version 450
#extension GL_ARB_gpu_shader_int64 : require
// EIA construction (formats/display_profiles.md section 2): one invocation per panel pixel writes its three
// subpixels. Subpixel column k = 3x + i (physical order on the panel), pixel row l (0 =
// top of the panel). Its phase under the lens array follows the profile's SubpixelMapping
// (van Berkel 1999 in affine form), exactly as lfd::fixedSubpixelPhase computes it on the CPU:
//   phase = fract(perSubpixel * k + perRow * l + offset),  1 - phase if inverted,
// and the subpixel shows channel i (RGB stripe) or 2 - i (BGR) of the views around
// phase * N. Each view covers the whole screen, so the view pixel read is the one under
// the subpixel's screen position (u, v) = ((k + 0.5) / 3W, (l + 0.5) / H).
// The phase is computed in 64-bit fixed point (shaders/subpixel_phase.glsl says why).

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
// Each subpixel reads one channel: R16F planes, one per channel (see `prefiltered`).
#include "eia_bindings.glsl"
// The mode is compiled in (C++ builds one program per mode, prepending "#define EIA_MODE
// n"), not a uniform: llvmpipe runs an untaken branch under an all-off lane mask at full
// cost, so a uniform `mode` made nearest-view EIAs pay for the 8-sample filter too.
#ifndef EIA_MODE
#define EIA_MODE EIA_MODE_NONE
#endif

layout(local_size_x = EIA_LOCAL_SIZE, local_size_y = EIA_LOCAL_SIZE) in;

// N views, layer = view, GL row 0 = bottom, read with texelFetch (no filtering) as stored:
// sRGB-encoded values, in mode none passed through untouched (bit-exact with the CPU), in
// mode view decoded through linearFromByte.
layout(binding = EIA_UNIT_VIEWS) uniform sampler2DArray views;
// Spatial modes: the views prefiltered in linear light (eia_prefilter.comp), one R16F
// plane per channel side by side (x = channel * w + view x), edges clamped: an array (layer
// = view) read bilinearly in mode spatial, a 3D texture (z = view) read trilinearly in
// view-spatial. Why single-channel planes: llvmpipe filters every channel of a texel, so
// an RGBA16F fetch of which a subpixel uses one channel made the EIA pass 1.35x as long;
// and why two targets: one trilinear fetch beats two bilinear ones, but a bilinear fetch
// beats a trilinear one on a view centre.
#if EIA_MODE == EIA_MODE_VIEW_SPATIAL
layout(binding = EIA_UNIT_PREFILTERED) uniform sampler3D prefiltered;
#else
layout(binding = EIA_UNIT_PREFILTERED) uniform sampler2DArray prefiltered;
#endif
// Panel-size RGBA8 output, GL row 0 = bottom (panel row l = H - 1 - GL row).
layout(binding = EIA_IMAGE_EIA, rgba8) uniform writeonly image2D eia;

layout(location = EIA_LOC_PANEL_SIZE) uniform uvec2 panelSize;     // W, H in pixels
layout(location = EIA_LOC_VIEW_SIZE) uniform uvec2 viewSize;       // view width, height in pixels
layout(location = EIA_LOC_VIEW_COUNT) uniform uint viewCount;      // N
// lfd::FixedSubpixelMapping: 2^-64 lens periods as uvec2(low word, high word).
layout(location = EIA_LOC_PER_SUBPIXEL) uniform uvec2 perSubpixel;
layout(location = EIA_LOC_PER_ROW) uniform uvec2 perRow;
layout(location = EIA_LOC_PHASE_OFFSET) uniform uvec2 phaseOffset;
layout(location = EIA_LOC_INVERT_PHASE) uniform bool invertPhase;
layout(location = EIA_LOC_SUBPIXELS_BGR) uniform bool subpixelsBgr;
// Mode view: sRGB byte -> linear value, the CPU reference's table (IEC 61966-2-1). Why a
// table: llvmpipe decodes every channel of an sRGB texel in arithmetic, and a subpixel uses
// one; looking its byte up made the view mode's EIA pass 1.3x faster.
layout(location = EIA_LOC_LINEAR_FROM_BYTE) uniform float linearFromByte[256];
// Invocation order: (stride s, runs n = ceil(W / s)), C++: lfd::samePhasePixelStride.
layout(location = EIA_LOC_LENS_ORDER) uniform uvec2 lensOrder;

#include "subpixel_phase.glsl"

#include "subpixel_view_texel.glsl"

// The view texel under subpixel (k, l) (subpixel_view_texel.glsl).
ivec2 viewTexelUnder(uint k, uint l)
{
    return subpixelViewTexel(k, l, panelSize, viewSize);
}

// Nearest view: the subpixel takes its channel from view floor(phase * N).
float nearestView(uint k, uint l, uint channel, uint64_t phase)
{
    const uint view = fixedPhaseView(phase, viewCount);
    return texelFetch(views, ivec3(viewTexelUnder(k, l), int(view)), 0)[channel];
}

#if EIA_MODE != EIA_MODE_NONE
// Filtered modes: linear value -> 8-bit sRGB level (the level of IEC 61966-2-1's encode,
// rounded to nearest; off only within 1e-4 levels of a rounding edge), by table, not pow. Entry i covers sqrt(linear) * B in
// [i, i + 1) (B = EIA_ENCODE_BUCKETS), where the level rises by at most one (a bucket spans
// at most 0.71 levels): the entry is level + f / 2, with f in [0, 1) the point in the
// bucket where the level rises (f = 1: it does not). Why: llvmpipe evaluates pow as
// exp2(log2) polynomials in every lane; a square root and a table read made the
// view-spatial EIA pass 8% faster (car, 48 views of 480x360). A storage buffer, not a
// uniform array: a GPU serves a uniform array read at differing indices across a warp one
// address at a time. C++ builds the table (eia_builder.cpp, srgbEncodeTable) and its CPU
// reference reads it the same way (encodeSrgbLevel).
layout(std430, binding = EIA_SSBO_ENCODE_TABLE) readonly buffer EncodeTable { float encodeTable[EIA_ENCODE_BUCKETS]; };

// Linear -> sRGB-encoded value, quantised to the 8-bit level the image stores.
float encodeSrgb(float linear)
{
    const float x = sqrt(clamp(linear, 0.0, 1.0)) * float(EIA_ENCODE_BUCKETS);
    const uint i = min(uint(x), uint(EIA_ENCODE_BUCKETS) - 1u);
    const float entry = encodeTable[i];
    const float level = floor(entry);
    const float rise = x - float(i) >= 2.0 * (entry - level) ? 1.0 : 0.0;
    return min(level + rise, 255.0) * (1.0 / 255.0);
}
#endif

// An 8-bit view value (UNORM, as stored) in linear light.
float linearValue(float stored)
{
    return linearFromByte[uint(round(stored * 255.0))];
}

// View v clamped to the cone (the cone's ends repeat their views).
uint clampedView(int v)
{
    return uint(clamp(v, 0, int(viewCount) - 1));
}

#if EIA_MODE != EIA_MODE_NONE
float filtered(uint k, uint l, uint channel, uint64_t phase)
{
#if EIA_MODE == EIA_MODE_VIEW
    // The view centres around c = phase * N: views floor(c - 1/2) and the next, weighted
    // linearly. c = view + fraction, so c - 1/2 has the fraction's top bit flipped, and its
    // floor is view - 1 where that bit was 0.
    const uint view = fixedPhaseView(phase, viewCount);
    const uint64_t fraction = fixedPhaseViewFraction(phase, viewCount);
    const int below = int(view) - (fraction < 0x8000000000000000UL ? 1 : 0);
    const float a = fixedPhaseToFloat(fraction ^ 0x8000000000000000UL);
    const ivec2 texel = viewTexelUnder(k, l);
    const float v0 = linearValue(texelFetch(views, ivec3(texel, int(clampedView(below))), 0)[channel]);
    const float v1 = linearValue(texelFetch(views, ivec3(texel, int(clampedView(below + 1))), 0)[channel]);
    return encodeSrgb(mix(v0, v1, a));
#else
    // The subpixel's screen position ((2k + 1) / 6W, (2l + 1) / 2H) in texture coordinates
    // of its channel's plane (planes side by side: u = (channel + x) / 3), x clamped to
    // the edge texels' centres so that the bilinear read never reaches the next plane (as
    // a clamped edge). Products with reciprocals, not quotients: divisions were a tenth of
    // this pass on llvmpipe.
    const float inPlane = clamp(float(2u * k + 1u) * (1.0 / float(6u * panelSize.x)), 0.5 / float(viewSize.x),
                                1.0 - 0.5 / float(viewSize.x));
    const vec2 uv = vec2((float(channel) + inPlane) * (1.0 / 3.0), 1.0 - float(2u * l + 1u) * (1.0 / float(2u * panelSize.y)));
#if EIA_MODE == EIA_MODE_SPATIAL
    const float layer = float(fixedPhaseView(phase, viewCount)); // the view under c = phase * N
    return encodeSrgb(textureLod(prefiltered, vec3(uv, layer), 0.0).r);
#else
    // z = c / N = the phase: linear between the two view centres around c.
    return encodeSrgb(textureLod(prefiltered, vec3(uv, fixedPhaseToFloat(phase)), 0.0).r);
#endif
#endif
}
#endif

// The panel column of invocation x: consecutive invocations are s pixels apart, s being the
// stride over which the phase comes back nearest to itself (one lens on the 8K panels and
// the prototype), so the lanes of a workgroup show the same or adjacent views and read
// neighbouring texels of the same view layers (row by row instead of 6 views apart per
// pixel); s = 1 is the plain order. Invocation x = p n + j is pixel j s + p (p < s).
uint lensOrderedColumn(uint invocation)
{
    const uint position = floorDivide(invocation, lensOrder.y);
    return (invocation - position * lensOrder.y) * lensOrder.x + position;
}

float subpixelValue(uint k, uint l, uint channel, uint64_t phase)
{
#if EIA_MODE == EIA_MODE_NONE
    return nearestView(k, l, channel, phase);
#else
    return filtered(k, l, channel, phase);
#endif
}

void main()
{
    if (gl_GlobalInvocationID.x >= lensOrder.x * lensOrder.y)
        return;
    const uvec2 pixel = uvec2(lensOrderedColumn(gl_GlobalInvocationID.x), gl_GlobalInvocationID.y); // x, GL row
    if (any(greaterThanEqual(pixel, panelSize)))
        return;
    const uint l = panelSize.y - 1u - pixel.y; // panel row, 0 = top

    // The pixel's three subpixels: P(k + 1) = P(k) + perSubpixel exactly (mod 2^64), so one
    // evaluation of the phase and two adds.
    const uint64_t step = fixedPhaseUniform(perSubpixel);
    uint64_t raw = fixedRawSubpixelPhase(3u * pixel.x, l, step, fixedPhaseUniform(perRow), fixedPhaseUniform(phaseOffset));
    vec4 rgba = vec4(0.0, 0.0, 0.0, 1.0);
    for (uint i = 0u; i < 3u; ++i) {
        const uint channel = subpixelsBgr ? 2u - i : i;
        rgba[channel] = subpixelValue(3u * pixel.x + i, l, channel, fixedSubpixelPhase(raw, invertPhase));
        raw += step;
    }
    imageStore(eia, ivec2(pixel), rgba);
}
