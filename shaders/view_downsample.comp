#version 450
// Supersampling resolve (paper section 4; frame_pipeline.h, `--ss`): the supersampled
// views are averaged down to the display's views in linear light, an unweighted mean as the
// paper's MVR does ("a pixel-by-pixel unweighted average of the supersampled image").
//   2x spatial (VIEW_DOWNSAMPLE_SPATIAL): view v pixel (x, y) = mean of the 2x2 source
//     pixels (2x + i, 2y + j) of source view v;
//   2x angular (VIEW_DOWNSAMPLE_ANGULAR): view v pixel (x, y) = mean of source views 2v and
//     2v + 1 (the two cameras at random positions inside view v's interval) at (x, y).
// One invocation per output pixel and view (z = view).
#include "view_downsample_bindings.glsl"

layout(local_size_x = VIEW_DOWNSAMPLE_LOCAL_SIZE, local_size_y = VIEW_DOWNSAMPLE_LOCAL_SIZE, local_size_z = 1) in;

// Supersampled views, RGBA8 sRGB-encoded values (layer = view, GL row 0 = bottom).
layout(binding = VIEW_DOWNSAMPLE_UNIT_SOURCE) uniform sampler2DArray source;
// The display's views, same encoding.
layout(binding = VIEW_DOWNSAMPLE_IMAGE_TARGET, rgba8) uniform writeonly image2DArray target;

layout(location = VIEW_DOWNSAMPLE_LOC_TARGET_SIZE) uniform uvec3 targetSize; // width, height, views
layout(location = VIEW_DOWNSAMPLE_LOC_MODE) uniform uint mode;               // VIEW_DOWNSAMPLE_*

#include "srgb.glsl"

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
                sum += 0.25 * srgbToLinear(texelFetch(source, ivec3(2 * p + ivec2(i, j), v), 0).rgb);
    } else {
        sum = 0.5 * (srgbToLinear(texelFetch(source, ivec3(p, 2 * v), 0).rgb) +
                     srgbToLinear(texelFetch(source, ivec3(p, 2 * v + 1), 0).rgb));
    }
    imageStore(target, ivec3(p, v), vec4(linearToSrgb(sum), 1.0));
}
