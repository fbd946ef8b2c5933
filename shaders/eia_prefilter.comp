#version 450
// Spatial reconstruction, step 1 of 2 (paper section 4; README "Reconstruction and
// supersampling"): every view in linear light, filtered by the separable 3-tap kernel
// [a, 1 - 2a, a] in x and y, edge texels repeated, into a 3D texture (z = view). Step 2
// (eia_construct.comp) reads it with one filtered fetch per subpixel: bilinear at the
// subpixel's screen position, so the spatial filter is tent * kernel (the kernel's
// variance 2a is the paper's Gaussian's sigma^2, 0.375^2 view pixels^2: the spread of the
// Gaussian integral of the bilinear image), and in view-spatial also linear between the
// two nearest views.
#include "eia_bindings.glsl"

layout(local_size_x = EIA_PREFILTER_LOCAL_SIZE, local_size_y = EIA_PREFILTER_LOCAL_SIZE) in;

// The views through an sRGB texture view: texelFetch returns linear values.
layout(binding = EIA_PREFILTER_UNIT_VIEWS) uniform sampler2DArray views;
layout(binding = EIA_PREFILTER_IMAGE_OUT, rgba16f) uniform writeonly image3D prefiltered;
layout(location = EIA_PREFILTER_LOC_SIZE) uniform uvec3 size; // width, height, views
layout(location = EIA_PREFILTER_LOC_TAP) uniform float tap;

// One invocation filters a 2x2 block of texels from the 4x4 texels around it (4 fetches
// per texel instead of 9).
void main()
{
    const ivec2 base = 2 * ivec2(gl_GlobalInvocationID.xy); // the block's lower-left texel
    const int view = int(gl_GlobalInvocationID.z);
    if (base.x >= int(size.x) || base.y >= int(size.y) || view >= int(size.z))
        return;
    const float w0 = tap, w1 = 1.0 - 2.0 * tap;
    // Rows base.y - 1 .. base.y + 2, each filtered in x for the block's two columns.
    vec4 rows[4][2];
    for (int j = 0; j < 4; ++j) {
        vec4 t[4];
        for (int i = 0; i < 4; ++i)
            t[i] = texelFetch(views, ivec3(clamp(base + ivec2(i - 1, j - 1), ivec2(0), ivec2(size.xy) - 1), view), 0);
        rows[j][0] = w0 * t[0] + w1 * t[1] + w0 * t[2];
        rows[j][1] = w0 * t[1] + w1 * t[2] + w0 * t[3];
    }
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            const ivec2 p = base + ivec2(x, y);
            if (p.x < int(size.x) && p.y < int(size.y))
                imageStore(prefiltered, ivec3(p, view), w0 * rows[y][x] + w1 * rows[y + 1][x] + w0 * rows[y + 2][x]);
        }
}
