// IEC 61966-2-1 sRGB transfer functions, per channel: the one definition every shader
// includes (shading, the supersampling resolve, gstd, the paper splat, the EIA).

// Linear -> encoded; the input is clamped to 0..1 first.
vec3 linearToSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    vec3 low = c * 12.92;
    vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(c, vec3(0.0031308)));
}

// Encoded -> linear.
vec3 srgbToLinear(vec3 c)
{
    return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}
