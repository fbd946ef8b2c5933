#version 450 core
// The direct subpixel splat's last pass (renderer lfdpr-direct, docs/player/direct-splat.md):
// the three channel planes lfdpr_direct_shade.comp wrote (cleared to the background first)
// into the RGBA8 panel image, one invocation per panel pixel. Each plane holds the 8-bit
// level the views path would have stored, so reading it back as byte / 255 and storing it
// again keeps the byte, as the EIA pass's copy from the views does.
#include "lfdpr_bindings.glsl"

layout(local_size_x = LFDPR_DIRECT_LOCAL_SIZE, local_size_y = LFDPR_DIRECT_LOCAL_SIZE) in;

layout(binding = LFDPR_UNIT_SUBPIXELS) uniform sampler2DArray t_subpixels; // R8, layer = channel
layout(binding = LFDPR_IMAGE_PANEL, rgba8) uniform writeonly image2D u_panel;
layout(location = LFDPR_LOC_PANEL_SIZE) uniform uvec2 u_panelSize;

void main()
{
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy); // x, GL row
    if (any(greaterThanEqual(uvec2(pixel), u_panelSize)))
        return;
    vec4 rgba = vec4(0.0, 0.0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c)
        rgba[c] = texelFetch(t_subpixels, ivec3(pixel, c), 0).r;
    imageStore(u_panel, pixel, rgba);
}
