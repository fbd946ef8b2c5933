// glTF 2.0 metallic-roughness shading (glTF spec, appendix B): Lambert diffuse plus GGX
// specular with Smith height-correlated visibility and Schlick Fresnel, lit by the frame's
// punctual lights (KHR_lights_punctual, or the default directional light) and by the
// environment (image-based lighting, split sum) or, without one, a constant ambient term.
// View-dependent: `eye` is the camera of the view being shaded. lfdDisplayEncode turns the
// radiance into what the views store: exposure, the Khronos PBR Neutral tone mapper and
// the sRGB encode, so the RGBA8 views hold display values (readback bytes are what the
// panel shows). docs/lighting.md describes the model; player/lighting/ holds its CPU side
// (prefiltering, the BRDF table, the Monte Carlo reference the tests compare with).

const float LFD_PI = 3.14159265358979;

struct SurfacePbr {
    vec3 baseColor;  // linear
    float metallic;
    float roughness; // perceptual roughness
    float occlusion; // ambient occlusion, 1 = none
    vec3 normal;     // unit, scene space, facing the viewer's side of the surface
    vec3 emissive;   // linear
};

#include "srgb.glsl" // linearToSrgb

layout(binding = LFD_UNIT_ENVIRONMENT) uniform samplerCube t_environment;
layout(binding = LFD_UNIT_IRRADIANCE) uniform samplerCube t_irradiance;
layout(binding = LFD_UNIT_BRDF_TABLE) uniform sampler2D t_brdfTable;
layout(binding = LFD_UNIT_LOBE_TAPS) uniform sampler2D t_lobeTaps;

// The BRDF's inputs that do not depend on the light: alpha = roughness^2,
// F0 = mix(0.04, baseColor, metallic), the diffuse colour.
struct LfdBrdf {
    vec3 f0;
    vec3 diffuseColor;
    float a2; // alpha^2
};

LfdBrdf lfdBrdf(SurfacePbr s)
{
    LfdBrdf b;
    float alpha = max(s.roughness * s.roughness, 1e-3);
    b.a2 = alpha * alpha;
    b.f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    b.diffuseColor = s.baseColor * (1.0 - s.metallic);
    return b;
}

// f(l, v) for one light direction l (unit, towards the light), and n.l.
vec3 lfdBrdfValue(LfdBrdf b, vec3 n, vec3 v, vec3 l, float NdotV, out float NdotL)
{
    vec3 h = normalize(v + l);
    NdotL = max(dot(n, l), 0.0);
    float NdotH = max(dot(n, h), 0.0);
    float VdotH = max(dot(v, h), 0.0);

    // Specular: D (GGX/Trowbridge-Reitz), V (Smith height-correlated), F (Schlick).
    float d = NdotH * NdotH * (b.a2 - 1.0) + 1.0;
    float D = b.a2 / (LFD_PI * d * d);
    float visV = NdotL * sqrt(NdotV * NdotV * (1.0 - b.a2) + b.a2);
    float visL = NdotV * sqrt(NdotL * NdotL * (1.0 - b.a2) + b.a2);
    float Vis = (visV + visL) > 0.0 ? 0.5 / (visV + visL) : 0.0;
    vec3 F = b.f0 + (vec3(1.0) - b.f0) * pow(1.0 - VdotH, 5.0);

    vec3 diffuse = (vec3(1.0) - F) * b.diffuseColor / LFD_PI;
    vec3 specular = F * (D * Vis);
    return diffuse + specular;
}

// Light i at `position`: the unit direction towards it and the radiance it brings
// (KHR_lights_punctual: directional lights in lux, point and spot lights in candela with
// inverse-square falloff, windowed to zero at `range`; spot cones smoothed between the
// inner and outer angles as the extension's reference implementation does).
vec3 lfdLightIncidence(uint i, vec3 position, out vec3 l)
{
    vec4 dirType = u_frame.lightDirection[i];
    vec3 radiance = u_frame.lightRadiance[i].rgb;
    if (uint(dirType.w) == LFD_LIGHT_DIRECTIONAL) {
        l = normalize(-dirType.xyz);
        return radiance;
    }
    vec4 posRange = u_frame.lightPosition[i];
    vec3 toLight = posRange.xyz - position;
    float distance2 = max(dot(toLight, toLight), 1e-8);
    l = toLight * inversesqrt(distance2);
    float attenuation = 1.0 / distance2;
    if (posRange.w > 0.0) {
        float r = distance2 / (posRange.w * posRange.w); // (d / range)^2
        attenuation *= clamp(1.0 - r * r, 0.0, 1.0);
    }
    if (uint(dirType.w) == LFD_LIGHT_SPOT) {
        vec2 cone = u_frame.lightCone[i].xy;
        float t = clamp(dot(dirType.xyz, -l) * cone.x + cone.y, 0.0, 1.0);
        attenuation *= t * t;
    }
    return radiance * attenuation;
}

vec3 lfdEnvironmentDirection(vec3 sceneDirection)
{
    return mat3(u_frame.environmentFromScene[0].xyz, u_frame.environmentFromScene[1].xyz,
                u_frame.environmentFromScene[2].xyz) * sceneDirection;
}

// The cube's lod for a lobe of GGX alpha (lighting/prefilter.h levelOfAlpha): level 0 the
// mirror, level l >= 1 alpha 2^(l + 1 - L) up to alpha 1 at level L - 1, and beyond it the
// wide level L (alpha in (1, 2]); GL clamps the lod to the cube's last level.
float lfdLodOfAlpha(float alpha, float alpha1)
{
    return alpha < alpha1 ? (alpha - 1e-3) / (alpha1 - 1e-3) : 1.0 + log2(alpha / alpha1);
}

// Image-based lighting by the split sum (Karis 2013), as player/lighting/split_sum.h
// evaluates it on the CPU (the tests' mirror). The specular radiance is the mean of two
// lookups of the prefiltered cube whose directions (mix(n, R, k)) and widths (alpha 2^d) the
// lobe tap table gives per (n.v, roughness) (lighting/lobe_taps.h): a narrow core near R and
// a wide halo towards n, fitted to the glTF lobe, which at n != v is a streak one isotropic
// lookup cannot follow; times F0 A + B. The diffuse radiance is the irradiance (E / pi)
// times the diffuse colour weighted by (1 - F0)(1 - C), the mean of (1 - F) over a Lambert
// lobe. A, B, C come from the BRDF table at the same (n.v, roughness) coordinate.
// docs/lighting.md gives the measured accuracy and cost.
vec3 lfdEnvironmentLight(SurfacePbr s, LfdBrdf b, vec3 n, vec3 v, float NdotV)
{
    const float size = float(LFD_BRDF_TABLE_SIZE);
    vec2 tableUv = (vec2(NdotV, s.roughness) * (size - 1.0) + 0.5) / size;
    vec3 abc = textureLod(t_brdfTable, tableUv, 0.0).rgb;
    vec4 taps = textureLod(t_lobeTaps, tableUv, 0.0); // (k0, d0, k1, d1)
    float alpha = max(s.roughness * s.roughness, 1e-3);
    float alpha1 = exp2(2.0 - u_frame.environmentMaxLevel); // level 1's alpha: 2^(2 - L)
    vec3 r = reflect(-v, n);
    vec3 core = mix(n, r, taps.x), halo = mix(n, r, taps.z); // a cube lookup needs no unit vector
    vec3 prefiltered =
        0.5 * (textureLod(t_environment, lfdEnvironmentDirection(core), lfdLodOfAlpha(alpha * exp2(taps.y), alpha1)).rgb +
               textureLod(t_environment, lfdEnvironmentDirection(halo), lfdLodOfAlpha(alpha * exp2(taps.w), alpha1)).rgb);
    vec3 specular = prefiltered * (b.f0 * abc.x + abc.y);
    vec3 irradiance = textureLod(t_irradiance, lfdEnvironmentDirection(n), 0.0).rgb;
    vec3 diffuse = b.diffuseColor * (vec3(1.0) - b.f0) * (1.0 - abc.z) * irradiance;
    return (diffuse + specular) * s.occlusion;
}

// Radiance leaving the surface towards `eye` (linear, before exposure).
vec3 shadePbr(SurfacePbr s, vec3 position, vec3 eye)
{
    // Vectors: n normal, v towards the eye, l towards a light.
    vec3 n = s.normal;
    vec3 v = normalize(eye - position);
    float NdotV = max(dot(n, v), 1e-4);
    LfdBrdf b = lfdBrdf(s);

    vec3 direct = vec3(0.0);
    for (uint i = 0u; i < u_frame.lightCount; ++i) {
        vec3 l;
        float NdotL;
        vec3 radiance = lfdLightIncidence(i, position, l);
        direct += lfdBrdfValue(b, n, v, l, NdotV, NdotL) * radiance * NdotL;
    }

    vec3 ambient;
    if ((u_frame.lightingFlags & LFD_LIGHTING_ENVIRONMENT) != 0u)
        ambient = lfdEnvironmentLight(s, b, n, v, NdotV);
    else // constant light on the diffuse and F0-weighted specular lobes, occluded
        ambient = u_frame.ambientColor.rgb * (b.diffuseColor + b.f0 * (1.0 - s.roughness * 0.5)) * s.occlusion;
    return direct + ambient + s.emissive;
}

// Khronos PBR Neutral tone mapping (Khronos 3D Commerce, "PBR Neutral", reference
// implementation): colours under the compression start pass unchanged but for a small
// toe, highlights are compressed towards white without hue shifts.
vec3 lfdPbrNeutralToneMap(vec3 color)
{
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression)
        return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

// Scene radiance -> the sRGB-encoded value a view stores: exposure, tone mapping, encode.
vec3 lfdDisplayEncode(vec3 radiance)
{
    radiance *= u_frame.exposure;
    if ((u_frame.lightingFlags & LFD_LIGHTING_TONE_MAP) != 0u)
        radiance = lfdPbrNeutralToneMap(radiance);
    return linearToSrgb(radiance);
}
