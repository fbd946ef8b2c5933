#version 450 core
#extension GL_ARB_gpu_shader_int64 : require
// gstd's panel model, once per panel: every subpixel's phase (after inversion) and the
// centre of the lens it lies under (texture u), for gstd_panel_accumulate.comp. The phase
// is the exact 64-bit fixed-point one of subpixel_phase.glsl, the EIA pass's; stored as
// float, whose 6e-8 resolution in [0, 1) is ample once the large argument has been reduced.
#include "gstd_bindings.glsl"
layout(local_size_x = GSTD_PANEL_LOCAL_SIZE, local_size_y = GSTD_PANEL_LOCAL_SIZE) in;

layout(binding = GSTD_PANEL_IMAGE_PHASE, rgba32f) uniform writeonly image2D u_phase;
layout(binding = GSTD_PANEL_IMAGE_LENS, rgba32f) uniform writeonly image2D u_lens;

layout(location = GSTD_PANEL_LOC_PANEL_SIZE) uniform uvec2 u_panelSize;
// lfd::FixedSubpixelMapping: 2^-64 lens periods as uvec2(low word, high word).
layout(location = GSTD_PANEL_LOC_PER_SUBPIXEL) uniform uvec2 u_perSubpixel;
layout(location = GSTD_PANEL_LOC_PER_ROW) uniform uvec2 u_perRow;
layout(location = GSTD_PANEL_LOC_PHASE_OFFSET) uniform uvec2 u_phaseOffset;
layout(location = GSTD_PANEL_LOC_INVERT_PHASE) uniform bool u_invertPhase;
layout(location = GSTD_PANEL_LOC_LENS_SUBPIXELS) uniform float u_lensSubpixels;

#include "subpixel_phase.glsl"

void main()
{
    const uvec2 pixel = gl_GlobalInvocationID.xy; // x, GL row
    if (any(greaterThanEqual(pixel, u_panelSize)))
        return;
    const uint l = u_panelSize.y - 1u - pixel.y; // panel row, 0 = top
    vec4 phase = vec4(0.0), lens = vec4(0.0);
    for (uint i = 0u; i < 3u; ++i) {
        const uint k = 3u * pixel.x + i;
        const uint64_t raw = fixedRawSubpixelPhase(k, l, fixedPhaseUniform(u_perSubpixel),
                                                   fixedPhaseUniform(u_perRow), fixedPhaseUniform(u_phaseOffset));
        phase[i] = fixedPhaseToFloat(fixedSubpixelPhase(raw, u_invertPhase));
        // The lens centre along the row: the raw phase runs 0 -> 1 across the lens, so the
        // centre is (1/2 - raw) / perSubpixel subpixel columns away (in float: within
        // 2^-9 subpixel columns, the stored u's own resolution at the right edge).
        lens[i] = (float(k) + 0.5 + (0.5 - fixedPhaseToFloat(raw)) * u_lensSubpixels) / float(3u * u_panelSize.x);
    }
    imageStore(u_phase, ivec2(pixel), phase);
    imageStore(u_lens, ivec2(pixel), lens);
}
