#version 450
// Spatial reconstruction, step 1 of 2 (paper section 4; docs/player/reconstruction.md): every view
// in linear light, filtered by the separable 3-tap kernel [a, 1 - 2a, a] in x and y, edge texels
// repeated, into one R16F plane per channel, the planes side by side (x = channel * width + x), of
// a 3D texture (z = view; view-spatial) or an array (layer = view; spatial, EIA_PREFILTER_LAYERED
// defined). Step 2 (eia_construct.comp) reads it with one filtered fetch per subpixel from its
// channel's plane: bilinear at the subpixel's screen position, so the spatial filter is tent *
// kernel (the kernel's variance 2a is the paper's Gaussian's sigma^2, 0.375^2 view pixels^2: the
// spread of the Gaussian integral of the bilinear image), and in view-spatial also linear between
// the two nearest views.
#include "eia_bindings.glsl"

layout(local_size_x = EIA_PREFILTER_LOCAL_SIZE, local_size_y = EIA_PREFILTER_LOCAL_SIZE) in;

// The views as stored (sRGB-encoded RGBA8), decoded by linearTexel.
layout(binding = EIA_PREFILTER_UNIT_VIEWS) uniform sampler2DArray views;
#ifdef EIA_PREFILTER_LAYERED
layout(binding = EIA_PREFILTER_IMAGE_OUT, r16f) uniform writeonly image2DArray prefiltered;
#else
layout(binding = EIA_PREFILTER_IMAGE_OUT, r16f) uniform writeonly image3D prefiltered;
#endif
layout(location = EIA_PREFILTER_LOC_SIZE) uniform uvec3 size; // width, height, views
layout(location = EIA_PREFILTER_LOC_TAP) uniform float tap;
// Texel p of the views in linear light: IEC 61966-2-1's decode, x / 12.92 up to 0.04045 and
// the polynomial of eia_bindings.glsl above (eia_builder.cpp's prefilterCpu evaluates it
// the same way). Why not the CPU's byte table: llvmpipe reads a table entry lane by lane,
// and three per texel were a third of this pass (car, 48 views of 480x360).
vec3 linearTexel(ivec3 p)
{
    const vec3 x = texelFetch(views, p, 0).rgb;
    vec3 high = vec3(EIA_DECODE_C6);
    high = high * x + EIA_DECODE_C5;
    high = high * x + EIA_DECODE_C4;
    high = high * x + EIA_DECODE_C3;
    high = high * x + EIA_DECODE_C2;
    high = high * x + EIA_DECODE_C1;
    high = high * x + EIA_DECODE_C0;
    return mix(high, x * (1.0 / 12.92), lessThanEqual(x, vec3(0.04045)));
}

// One invocation filters a BxB block of texels from the (B + 2)^2 texels around it
// (B = EIA_PREFILTER_BLOCK: (B + 2)^2 / B^2 fetches per texel instead of 9). Measured on
// llvmpipe (48 views of 480x360), the spatial EIA pass took 363 ms with B = 4, 474 with
// B = 2 and 438 with B = 8 (registers spill); a shared-memory tile with a barrier, 487.
const int kBlock = EIA_PREFILTER_BLOCK;
void main()
{
    const ivec2 base = kBlock * ivec2(gl_GlobalInvocationID.xy); // the block's lower-left texel
    const int view = int(gl_GlobalInvocationID.z);
    if (base.x >= int(size.x) || base.y >= int(size.y) || view >= int(size.z))
        return;
    const float w0 = tap, w1 = 1.0 - 2.0 * tap;
    // Rows base.y - 1 .. base.y + B, each filtered in x for the block's B columns.
    vec3 rows[kBlock + 2][kBlock];
    for (int j = 0; j < kBlock + 2; ++j) {
        vec3 t[kBlock + 2];
        for (int i = 0; i < kBlock + 2; ++i)
            t[i] = linearTexel(ivec3(clamp(base + ivec2(i - 1, j - 1), ivec2(0), ivec2(size.xy) - 1), view));
        for (int i = 0; i < kBlock; ++i)
            rows[j][i] = w0 * t[i] + w1 * t[i + 1] + w0 * t[i + 2];
    }
    for (int y = 0; y < kBlock; ++y)
        for (int x = 0; x < kBlock; ++x) {
            const ivec2 p = base + ivec2(x, y);
            if (p.x < int(size.x) && p.y < int(size.y)) {
                const vec3 value = w0 * rows[y][x] + w1 * rows[y + 1][x] + w0 * rows[y + 2][x];
                for (int channel = 0; channel < 3; ++channel)
                    imageStore(prefiltered, ivec3(p.x + channel * int(size.x), p.y, view), vec4(value[channel]));
            }
        }
}
