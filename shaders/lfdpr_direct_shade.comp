#version 450 core
// The direct subpixel splat's shading (renderer lfdpr-direct, docs/player/direct-splat.md):
// one invocation per panel pixel shades each of its three subpixels whose word
// (lfdpr_direct_fanout.glsl) a point of shading group u_group won, for the one channel that
// subpixel shows. A subpixel's view is floor(phase * N) by the exact fixed-point phase
// (subpixel_phase.glsl) and its view pixel the texel under it (subpixel_view_texel.glsl),
// both as the EIA pass's nearest mode computes them; it is shaded there exactly as the
// views path shades that view pixel (lfdpr_visibility_shade_pixel.glsl), so its channel is
// the byte the two-stage EIA would copy. Each subpixel costs a full material evaluation:
// the price of having no view images (3 W H shadings against the views' visible pixels).
// LFDPR_DIRECT_EXACT (renderer lfdpr-direct-exact, an exact-ray hybrid): visibility as
// above (the winner of the subpixel's nearest view and texel), but the winner's triangle
// shaded along the subpixel's own ray - from the camera of its continuous phase (view
// coordinate phase * N, between two views' cameras) through the centre of the lens it lies
// under (the position gstd's panel model integrates around) - instead of the nearest
// view's camera through the texel centre.
// Output: one R8 plane per channel (layer = channel), since the three subpixels of a pixel
// may belong to different groups' dispatches; lfdpr_direct_pack.comp writes the RGBA8 panel.
#extension GL_ARB_gpu_shader_int64 : require // the phase (subpixel_phase.glsl), on every path
#include "scene_bindings.glsl"
#define LFDPR_VISIBILITY_PIPELINE
#include "lfdpr_bindings.glsl"
#include "lfdpr_work_shape.glsl"
#define LFD_PRECISE precise
#include "lfdpr_math.glsl"
#include "lfdpr_visibility_shade_pixel.glsl"
#include "lfdpr_work_counters.glsl"
#include "subpixel_phase.glsl"
#include "subpixel_view_texel.glsl"

layout(local_size_x = LFDPR_DIRECT_LOCAL_SIZE, local_size_y = LFDPR_DIRECT_LOCAL_SIZE) in;

// The subpixels' winners (lfdpr_direct_fanout.glsl): RG32UI 64-bit words (record, key), or
// on the 32-bit path R32UI records (all ones: no point covers the subpixel).
layout(binding = LFDPR_UNIT_PANEL_WORDS) uniform usamplerBuffer t_panelWords;
layout(binding = LFDPR_IMAGE_SUBPIXELS, r8) uniform writeonly image2DArray u_subpixels;
layout(location = LFDPR_LOC_SHADE_MATERIAL) uniform uint u_shadeMaterial;
layout(location = LFDPR_LOC_SHADE_GROUP) uniform uint u_group;
layout(location = LFDPR_LOC_PANEL_SIZE) uniform uvec2 u_panelSize;
// lfd::FixedSubpixelMapping: 2^-64 lens periods as uvec2(low word, high word).
layout(location = LFDPR_LOC_PER_SUBPIXEL) uniform uvec2 u_perSubpixel;
layout(location = LFDPR_LOC_PER_ROW) uniform uvec2 u_perRow;
layout(location = LFDPR_LOC_PHASE_OFFSET) uniform uvec2 u_phaseOffset;
layout(location = LFDPR_LOC_INVERT_PHASE) uniform bool u_invertPhase;
layout(location = LFDPR_LOC_SUBPIXELS_BGR) uniform bool u_subpixelsBgr;
#ifdef LFDPR_DIRECT_EXACT
// Subpixel columns per lens along a row, 1 / perSubpixel (signed), as gstd's panel model.
layout(location = LFDPR_LOC_LENS_SUBPIXELS) uniform float u_lensSubpixels;

// The camera at continuous view coordinate v (view i's camera at v = i): its camera-line
// offset and eye, linear between the two nearest views' (all on one line; linear in the
// offset where the views are tan-spaced, a second-order difference within a view
// interval), extrapolated past the cone's ends by the end interval.
void continuousCamera(float v, out float e, out vec3 eye)
{
    const uint n = u_lfd.counts.x;
    const uint i = n < 2u ? 0u : uint(clamp(floor(v), 0.0, float(n - 2u)));
    const uint j = min(i + 1u, n - 1u);
    const float f = n < 2u ? 0.0 : v - float(i);
    e = mix(lfdViewOffset(i), lfdViewOffset(j), f);
    eye = mix(views[i].eyeScene.xyz, views[j].eyeScene.xyz, f);
}

// Subpixel (k, l)'s exact ray (raw: its phase before inversion, phase: after): the winner's
// triangle seen from the camera of phase * N at the lens centre's window position.
vec4 shadeExactRay(LfdprVisibilityRecordGpu record, LfdprVisibilityDrawGpu draw, uint k, uint l, uint64_t raw,
                   uint64_t phase)
{
    float e;
    vec3 eye;
    continuousCamera(fixedPhaseToFloat(phase) * float(u_lfd.counts.x) - 0.5, e, eye);
    // The raw phase runs 0 -> 1 across a lens, so its centre is (1/2 - raw) lenses away.
    const float lensColumn = float(k) + 0.5 + (0.5 - fixedPhaseToFloat(raw)) * u_lensSubpixels;
    const vec2 window = vec2(lensColumn / float(3u * u_panelSize.x),
                             (float(u_panelSize.y - l) - 0.5) / float(u_panelSize.y)) * u_lfd.viewSize.xy;
    ViewTriangle t = viewTriangleAt(record, draw, e);
    LfdViewTriangle vt = lfdViewTriangle(t.s0, t.s1, t.s2, t.invW);
    return shadePixelFrom(t, eye, vt, lfdEdgeValues(vt, window));
}
#endif

// Subpixel k on panel row l, whose phase before inversion is `raw`: shaded into its
// channel's plane at GL pixel `pixel` when its winner is the group's (background subpixels
// keep the clear).
void shadeSubpixel(uint k, uint l, uint channel, uint64_t raw, ivec2 pixel)
{
#ifdef LFDPR_INT64
    const uvec2 word = texelFetch(t_panelWords, int(l * 3u * u_panelSize.x + k)).xy;
    const uint winner = word.y == 0xFFFFFFFFu ? 0xFFFFFFFFu : word.x;
#else
    const uint winner = texelFetch(t_panelWords, int(l * 3u * u_panelSize.x + k)).x;
#endif
    if (winner == 0xFFFFFFFFu)
        return; // no point covers it
    const LfdprVisibilityRecordGpu record = lfdRecord(winner);
    const LfdprVisibilityDrawGpu draw = lfdDraw(record.draw);
    if (draw.group != u_group || (u_group != 0u && draw.material != u_shadeMaterial))
        return;
    const uint64_t phase = fixedSubpixelPhase(raw, u_invertPhase);
    LFDPR_COUNT(shadings, 1u);
#ifdef LFDPR_DIRECT_EXACT
    const vec4 color = shadeExactRay(record, draw, k, l, raw, phase);
#else
    // The view pixel it shows, shaded as lfdpr_visibility_shade.comp shades it.
    const uint view = fixedPhaseView(phase, u_lfd.counts.x);
    const ivec2 texel = subpixelViewTexel(k, l, u_panelSize, uvec2(u_lfd.viewSize.xy));
    ViewTriangle t = viewTriangle(record, draw, view);
    LfdViewTriangle vt = lfdViewTriangle(t.s0, t.s1, t.s2, t.invW);
    const vec4 color = shadePixel(t, view, vt, lfdEdgeValues(vt, vec2(texel) + 0.5));
#endif
    imageStore(u_subpixels, ivec3(pixel, int(channel)), vec4(color[channel]));
}

void main()
{
    const uvec2 pixel = gl_GlobalInvocationID.xy; // x, GL row
    if (all(lessThan(pixel, u_panelSize))) {
        const uint l = u_panelSize.y - 1u - pixel.y; // panel row, 0 = top
        // P(k + 1) = P(k) + perSubpixel exactly (mod 2^64), as in the EIA pass.
        const uint64_t step = fixedPhaseUniform(u_perSubpixel);
        uint64_t raw = fixedRawSubpixelPhase(3u * pixel.x, l, step, fixedPhaseUniform(u_perRow),
                                             fixedPhaseUniform(u_phaseOffset));
        for (uint i = 0u; i < 3u; ++i) {
            const uint channel = u_subpixelsBgr ? 2u - i : i;
            shadeSubpixel(3u * pixel.x + i, l, channel, raw, ivec2(pixel));
            raw += step;
        }
    }
    lfdWorkFlush(); // uniform control flow: every invocation of the workgroup gets here
}
