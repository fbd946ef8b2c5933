#version 450
// Supersampling resolve (paper section 4; frame_pipeline.h, `--ss`): the supersampled
// views are averaged down to the display's views in linear light, an unweighted mean as the
// paper's MVR does ("a pixel-by-pixel unweighted average of the supersampled image").
//   2x spatial (VIEW_DOWNSAMPLE_SPATIAL): view v pixel (x, y) = mean of the 2x2 source
//     pixels (2x + i, 2y + j) of source view v;
//   2x angular (VIEW_DOWNSAMPLE_ANGULAR): view v pixel (x, y) = mean of source views 2v and
//     2v + 1 (the two cameras at random positions inside view v's interval) at (x, y).
// One invocation per output pixel and view (z = view).
#define VIEW_DOWNSAMPLE_SPATIAL 1
#define VIEW_DOWNSAMPLE_ANGULAR 2

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// Supersampled views, RGBA8 sRGB-encoded values (layer = view, GL row 0 = bottom).
layout(binding = 0) uniform sampler2DArray source;
// The display's views, same encoding.
layout(binding = 0, rgba8) uniform writeonly image2DArray target;

uniform uvec3 targetSize; // width, height, views
uniform uint mode;        // VIEW_DOWNSAMPLE_*

vec3 linearFromSrgb(vec3 c)
{
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

vec3 srgbFromLinear(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main()
{
    const uvec3 id = gl_GlobalInvocationID;
    if (any(greaterThanEqual(id, targetSize)))
        return;
    const ivec2 p = ivec2(id.xy);
    const int v = int(id.z);
    vec3 sum = vec3(0.0);
    if (mode == VIEW_DOWNSAMPLE_SPATIAL) {
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                sum += 0.25 * linearFromSrgb(texelFetch(source, ivec3(2 * p + ivec2(i, j), v), 0).rgb);
    } else {
        sum = 0.5 * (linearFromSrgb(texelFetch(source, ivec3(p, 2 * v), 0).rgb) +
                     linearFromSrgb(texelFetch(source, ivec3(p, 2 * v + 1), 0).rgb));
    }
    imageStore(target, ivec3(p, v), vec4(srgbFromLinear(sum), 1.0));
}
