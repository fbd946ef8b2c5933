#version 450 core
// gstd reconstruction (Gavane & Watson 2024, section 5, "GStd"): one output view pixel per
// invocation. The sub-view was rendered at `factor` times the view resolution into an
// GL_SRGB8_ALPHA8 texture, so every bilinear fetch decodes to linear light before it is
// filtered. The pixel's value is the Gaussian reconstruction filter integrated with the
// seeded sample offsets (drawn from the Gaussian itself, so the estimate is their plain
// mean). Sub-views are averaged in linear light: the first stores its estimate in the
// accumulator, the last adds its own, divides by the sub-view count, encodes sRGB and
// writes the view layer (the values every renderer stores).
// The C++ side dispatches with gl::dispatchCovering, which reads this local size back.
layout(local_size_x = 8, local_size_y = 8) in;

#define GSTD_MAX_SAMPLES 64

layout(binding = 5) uniform sampler2D u_highRes;                  // linear filter, clamp
layout(binding = 0, rgba32f) uniform image2D u_accum;             // view size, linear
layout(binding = 1, rgba8) uniform writeonly image2D u_view;      // one ViewTargets layer

layout(location = 0) uniform uvec2 u_size;        // view size in pixels
layout(location = 1) uniform uint u_sampleCount;
layout(location = 2) uniform uint u_subView;      // 0 .. u_subViewCount - 1
layout(location = 3) uniform uint u_subViewCount;
layout(location = 4) uniform vec2 u_offsets[GSTD_MAX_SAMPLES]; // view pixels

vec3 lfdEncodeSrgb(vec3 linear)
{
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main()
{
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, u_size)))
        return;

    // Monte Carlo estimate of the Gaussian-weighted integral around the pixel centre.
    vec2 centre = vec2(pixel) + 0.5;
    vec3 sum = vec3(0.0);
    for (uint s = 0u; s < u_sampleCount; ++s)
        sum += texture(u_highRes, (centre + u_offsets[s]) / vec2(u_size)).rgb;
    vec3 estimate = sum / float(u_sampleCount);

    ivec2 p = ivec2(pixel);
    if (u_subView > 0u)
        estimate += imageLoad(u_accum, p).rgb;
    if (u_subView + 1u < u_subViewCount)
        imageStore(u_accum, p, vec4(estimate, 1.0));
    else
        imageStore(u_view, p, vec4(lfdEncodeSrgb(estimate / float(u_subViewCount)), 1.0));
}
