// glTF 2.0 metallic-roughness shading (glTF spec, appendix B): Lambert diffuse plus GGX
// specular with Smith height-correlated visibility and Schlick Fresnel, lit by one fixed
// directional light and a constant ambient term. View-dependent: `eye` is the camera of
// the view being shaded. Output is encoded to sRGB in the shader, so the RGBA8 views hold
// display values (readback bytes are what the panel shows).

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

vec3 shadePbr(SurfacePbr s, vec3 position, vec3 eye)
{
    // Vectors: n normal, v towards the eye, l towards the light, h half vector.
    vec3 n = s.normal;
    vec3 v = normalize(eye - position);
    vec3 l = normalize(u_frame.lightDirScene.xyz);
    vec3 h = normalize(v + l);
    float NdotL = max(dot(n, l), 0.0);
    float NdotV = max(dot(n, v), 1e-4);
    float NdotH = max(dot(n, h), 0.0);
    float VdotH = max(dot(v, h), 0.0);

    // glTF BRDF inputs: alpha = roughness^2, F0 = mix(0.04, baseColor, metallic).
    float alpha = max(s.roughness * s.roughness, 1e-3);
    vec3 f0 = mix(vec3(0.04), s.baseColor, s.metallic);
    vec3 diffuseColor = s.baseColor * (1.0 - s.metallic);

    // Specular: D (GGX/Trowbridge-Reitz), V (Smith height-correlated), F (Schlick).
    float a2 = alpha * alpha;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    float D = a2 / (LFD_PI * d * d);
    float visV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float visL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    float Vis = (visV + visL) > 0.0 ? 0.5 / (visV + visL) : 0.0;
    vec3 F = f0 + (vec3(1.0) - f0) * pow(1.0 - VdotH, 5.0);

    vec3 diffuse = (vec3(1.0) - F) * diffuseColor / LFD_PI;
    vec3 specular = F * (D * Vis);
    vec3 direct = (diffuse + specular) * u_frame.lightColor.rgb * NdotL;

    // Ambient: constant light on the diffuse and F0-weighted specular lobes, occluded.
    vec3 ambient = u_frame.ambientColor.rgb * (diffuseColor + f0 * (1.0 - s.roughness * 0.5)) *
                   s.occlusion;
    return direct + ambient + s.emissive;
}
