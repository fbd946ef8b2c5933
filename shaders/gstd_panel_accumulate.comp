#version 450 core
// gstd's panel model, one batch of consecutive sub-views' contribution (renderer_gstd.h, gstd_panel.h,
// docs/player/gstd.md): one invocation per panel pixel, its three subpixels. A
// subpixel shows, at each point of its area, the light leaving its lens in the direction
// of that point's lenticular phase; its ideal value is the scene's radiance integrated
// over that footprint:
//   angular: the phase over the subpixel's area, phi + perSubpixel * x + perRow * y with x, y
//            uniform in [-1/2, 1/2]: a trapezoid (two boxes, widths a = |perSubpixel| and
//            b = |perRow|, convolved). The sub-views tile the cone's phases [0, 1) in
//            intervals of width h, each rendered at its centre t; a sub-view's weight is
//            the trapezoid's mass inside [t - h/2, t + h/2) (circular: the lens period),
//            so the weights of all sub-views sum to exactly 1 for every subpixel.
//   spatial: a box of one view pixel centred on the lens the subpixel lies under (the
//            light of a direction leaves through the whole lens) and on its row:
//            integrated with bilinear taps at the sub-view's texel spacing.
// Values are linear (the sub-views are stored sRGB, so fetches decode); the accumulator
// holds each subpixel's running sum in its own colour channel. The phases and lens centres
// come from gstd_panel_phases.comp. A batch is the layers of u_subViews, consecutive
// sub-views whose phases start at u_firstPhase, h apart: each subpixel visits only the
// layers within its reach (about (a + b) / h + 1 of them).
#include "gstd_bindings.glsl"
layout(local_size_x = GSTD_PANEL_LOCAL_SIZE, local_size_y = GSTD_PANEL_LOCAL_SIZE) in;

layout(binding = GSTD_PANEL_UNIT_SUB_VIEWS) uniform sampler2DArray u_subViews;
layout(binding = GSTD_PANEL_IMAGE_ACCUM, rgba32f) uniform image2D u_accum;
layout(binding = GSTD_PANEL_IMAGE_PHASE, rgba32f) uniform readonly image2D u_phase;
layout(binding = GSTD_PANEL_IMAGE_LENS, rgba32f) uniform readonly image2D u_lens;

layout(location = GSTD_PANEL_LOC_PANEL_SIZE) uniform uvec2 u_panelSize;
layout(location = GSTD_PANEL_LOC_SUBPIXELS_BGR) uniform bool u_subpixelsBgr;
layout(location = GSTD_PANEL_LOC_FIRST_PHASE) uniform float u_firstPhase;
layout(location = GSTD_PANEL_LOC_SUB_VIEW_WIDTH) uniform float u_subViewWidth;
layout(location = GSTD_PANEL_LOC_LAYER_COUNT) uniform uint u_layerCount;
layout(location = GSTD_PANEL_LOC_SPREAD) uniform vec2 u_spread;
layout(location = GSTD_PANEL_LOC_FOOTPRINT) uniform vec2 u_footprint;
layout(location = GSTD_PANEL_LOC_TAPS) uniform uvec2 u_taps;

float squaredRamp(float x)
{
    return x > 0.0 ? x * x : 0.0;
}

// P(U <= x) for U the phase offset of a point uniform on the subpixel (the trapezoid's
// distribution function; lfd::player::gstdSpreadCdf is the same formula on the CPU).
float spreadCdf(float x)
{
    const float a = u_spread.x, b = u_spread.y;
    const float s = x + 0.5 * (a + b);
    if (s <= 0.0)
        return 0.0;
    if (s >= a + b)
        return 1.0; // exactly: the four squares cancel only to rounding
    return clamp((squaredRamp(s) - squaredRamp(s - a) - squaredRamp(s - b) + squaredRamp(s - a - b)) / (2.0 * a * b),
                 0.0, 1.0);
}

// x wrapped to [-1/2, 1/2): phases are circular (the lens period).
float wrapped(float x)
{
    return x - floor(x + 0.5);
}

void main()
{
    const uvec2 pixel = gl_GlobalInvocationID.xy; // x, GL row
    if (any(greaterThanEqual(pixel, u_panelSize)))
        return;
    const vec4 phase = imageLoad(u_phase, ivec2(pixel));
    // Each subpixel's position in layer units, relative to the batch's middle (circular),
    // and the layers within its reach: |t_j - phase| < h/2 + (a + b)/2.
    const float halfSpan = 0.5 * float(u_layerCount - 1u);
    const float middle = u_firstPhase + halfSpan * u_subViewWidth;
    const float reach = 0.5 + 0.5 * (u_spread.x + u_spread.y) / u_subViewWidth;
    vec3 position;
    for (uint i = 0u; i < 3u; ++i)
        position[i] = halfSpan + wrapped(phase[i] - middle) / u_subViewWidth;
    // A batch of the whole cone wraps around: its last layer neighbours its first.
    const bool wholeCone = float(u_layerCount) * u_subViewWidth > 0.999;
    if (!wholeCone && (all(lessThanEqual(position + reach, vec3(0.0))) ||
                       all(greaterThanEqual(position - reach, vec3(float(u_layerCount - 1u))))))
        return;

    // The row's centre in texture coordinates (GL: v = 0 at the bottom of the screen).
    const uint l = u_panelSize.y - 1u - pixel.y;
    const float v = 1.0 - (float(l) + 0.5) / float(u_panelSize.y);
    const vec4 lens = imageLoad(u_lens, ivec2(pixel));
    vec4 added = vec4(0.0);
    bool touched = false;
    for (uint i = 0u; i < 3u; ++i) {
        const int layers = int(u_layerCount);
        const int first = wholeCone ? int(ceil(position[i] - reach)) : max(int(ceil(position[i] - reach)), 0);
        const int last = wholeCone ? int(floor(position[i] + reach)) : min(int(floor(position[i] + reach)), layers - 1);
        const uint channel = u_subpixelsBgr ? 2u - i : i;
        for (int j = first; j <= last; ++j) {
            const float d = (float(j) - position[i]) * u_subViewWidth; // t_j - phase
            // GLSL leaves % of a negative operand undefined; j > -layers - 1 since the reach
            // stays within half the period (gstdPanelFootprint checks).
            const int layer = (j + 2 * layers) % layers;
            const float weight = spreadCdf(d + 0.5 * u_subViewWidth) - spreadCdf(d - 0.5 * u_subViewWidth);
            if (weight <= 0.0)
                continue;
            float value = 0.0;
            for (uint ty = 0u; ty < u_taps.y; ++ty)
                for (uint tx = 0u; tx < u_taps.x; ++tx) {
                    const vec2 offset = (vec2(tx, ty) + 0.5) / vec2(u_taps) - 0.5;
                    value += texture(u_subViews, vec3(vec2(lens[i], v) + offset * u_footprint, float(layer)))[channel];
                }
            added[channel] += weight * value / float(u_taps.x * u_taps.y);
            touched = true;
        }
    }
    if (touched)
        imageStore(u_accum, ivec2(pixel), imageLoad(u_accum, ivec2(pixel)) + added);
}
