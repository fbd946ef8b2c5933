#version 450 core
// gstd's panel model, last step: the accumulated linear subpixel values (their sub-view
// weights sum to 1, gstd_panel_accumulate.comp) encoded as sRGB into the EIA, the values
// every EIA stores.
#include "gstd_bindings.glsl"
layout(local_size_x = GSTD_PANEL_LOCAL_SIZE, local_size_y = GSTD_PANEL_LOCAL_SIZE) in;

layout(binding = GSTD_PANEL_IMAGE_ACCUM, rgba32f) uniform readonly image2D u_accum;
layout(binding = GSTD_PANEL_IMAGE_EIA, rgba8) uniform writeonly image2D u_eia;
layout(location = GSTD_PANEL_LOC_PANEL_SIZE) uniform uvec2 u_panelSize;

#include "srgb.glsl"

void main()
{
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), u_panelSize)))
        return;
    imageStore(u_eia, pixel, vec4(linearToSrgb(imageLoad(u_accum, pixel).rgb), 1.0));
}
