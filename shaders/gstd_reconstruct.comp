#version 450 core
// gstd reconstruction (Gavane & Watson 2024, section 5, "GStd"): one output view pixel per
// invocation. The sub-view (layer u_layer) was rendered at `factor` times the view resolution into an
// GL_SRGB8_ALPHA8 texture, so every bilinear fetch decodes to linear light before it is
// filtered. The pixel's value is the Gaussian reconstruction filter integrated with the
// seeded sample offsets (drawn from the Gaussian itself, so the estimate is their plain
// mean). Sub-views are averaged in linear light: the first stores its estimate in the
// accumulator, the last adds its own, divides by the sub-view count, encodes sRGB and
// writes the view layer (the values every renderer stores).
#include "gstd_bindings.glsl"
layout(local_size_x = GSTD_LOCAL_SIZE, local_size_y = GSTD_LOCAL_SIZE) in;

layout(binding = GSTD_UNIT_HIGH_RES) uniform sampler2DArray u_highRes;        // linear filter, clamp
layout(binding = GSTD_IMAGE_ACCUM, rgba32f) uniform image2D u_accum;         // view size, linear
layout(binding = GSTD_IMAGE_VIEW, rgba8) uniform writeonly image2D u_view;   // one ViewTargets layer

layout(location = GSTD_LOC_SIZE) uniform uvec2 u_size;
layout(location = GSTD_LOC_SAMPLE_COUNT) uniform uint u_sampleCount;
layout(location = GSTD_LOC_SUB_VIEW) uniform uint u_subView;
layout(location = GSTD_LOC_SUB_VIEW_COUNT) uniform uint u_subViewCount;
layout(location = GSTD_LOC_OFFSETS) uniform vec2 u_offsets[GSTD_MAX_SAMPLES];
layout(location = GSTD_LOC_LAYER) uniform uint u_layer;

#include "srgb.glsl"

void main()
{
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, u_size)))
        return;

    // Monte Carlo estimate of the Gaussian-weighted integral around the pixel centre.
    vec2 centre = vec2(pixel) + 0.5;
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < u_sampleCount; ++s)
        sum += texture(u_highRes, vec3((centre + u_offsets[s]) / vec2(u_size), float(u_layer))).rgb;
    vec3 estimate = sum / float(u_sampleCount);

    ivec2 p = ivec2(pixel);
    if (u_subView > 0u)
        estimate += imageLoad(u_accum, p).rgb;
    if (u_subView + 1u < u_subViewCount)
        imageStore(u_accum, p, vec4(estimate, 1.0));
    else
        imageStore(u_view, p, vec4(linearToSrgb(estimate / float(u_subViewCount)), 1.0));
}
