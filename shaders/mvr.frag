#version 450 core
// Fragment stage of mvr and mvr-layered: glTF metallic-roughness material, shaded for the
// eye of this fragment's view, written sRGB-encoded.
#include "scene_bindings.glsl"
#include "pbr_shading.glsl"

layout(location = 0) in vec3 v_position;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec4 v_tangent;
layout(location = 3) in vec2 v_uv;
layout(location = 4) flat in int v_view;

layout(location = LFD_LOC_MATERIAL) uniform uint u_material;
layout(location = LFD_LOC_STREAMS) uniform uint u_streams;

layout(binding = LFD_UNIT_BASE_COLOR) uniform sampler2D t_baseColor;
layout(binding = LFD_UNIT_METALLIC_ROUGHNESS) uniform sampler2D t_metallicRoughness;
layout(binding = LFD_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = LFD_UNIT_OCCLUSION) uniform sampler2D t_occlusion;
layout(binding = LFD_UNIT_EMISSIVE) uniform sampler2D t_emissive;

layout(location = 0) out vec4 o_color;

void main()
{
    MaterialGpu m = materials[u_material];
    bool hasUv = (u_streams & LFD_STREAM_UV) != 0u;
    // note: flags and streams are uniform per draw, so texture() stays in uniform control
    // flow and hardware mip selection (derivatives) is well defined.
    bool useTextures = hasUv;

    // Base colour and alpha (texture is GL_SRGB8_ALPHA8: the fetch returns linear values).
    vec4 baseColor = m.baseColorFactor;
    if (useTextures && (m.flags & LFD_MATERIAL_BASE_COLOR_TEXTURE) != 0u)
        baseColor *= texture(t_baseColor, v_uv);
    // note: BLEND is drawn as opaque (no sorting of transparent surfaces).
    if (m.alphaMode == LFD_ALPHA_MASK && baseColor.a < m.emissiveCutoff.w)
        discard;

    // Geometric normal: interpolated vertex normal, or the face normal from derivatives
    // when the mesh has none (that one always faces the camera).
    vec3 n;
    if ((u_streams & LFD_STREAM_NORMAL) != 0u) {
        n = normalize(v_normal);
        if (!gl_FrontFacing)
            n = -n; // double-sided back faces (single-sided ones are culled)
    } else {
        n = normalize(cross(dFdx(v_position), dFdy(v_position)));
    }

    // Normal map (tangent space, glTF convention: B = cross(N, T) * w).
    if (useTextures && (m.flags & LFD_MATERIAL_NORMAL_TEXTURE) != 0u &&
        (u_streams & LFD_STREAM_TANGENT) != 0u) {
        vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
        if (dot(t, t) > 1e-12) {
            t = normalize(t);
            vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 tn = texture(t_normal, v_uv).xyz * 2.0 - 1.0;
            tn.xy *= m.params.z;
            n = normalize(mat3(t, b, n) * tn);
        }
    }

    SurfacePbr s;
    s.baseColor = baseColor.rgb;
    s.metallic = m.params.x;
    s.roughness = m.params.y;
    if (useTextures && (m.flags & LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE) != 0u) {
        vec4 mr = texture(t_metallicRoughness, v_uv);
        s.roughness *= mr.g;
        s.metallic *= mr.b;
    }
    s.roughness = clamp(s.roughness, 0.0, 1.0);
    s.metallic = clamp(s.metallic, 0.0, 1.0);
    s.occlusion = 1.0;
    if (useTextures && (m.flags & LFD_MATERIAL_OCCLUSION_TEXTURE) != 0u)
        s.occlusion = 1.0 + m.params.w * (texture(t_occlusion, v_uv).r - 1.0);
    s.emissive = m.emissiveCutoff.rgb;
    if (useTextures && (m.flags & LFD_MATERIAL_EMISSIVE_TEXTURE) != 0u)
        s.emissive *= texture(t_emissive, v_uv).rgb;
    s.normal = n;

    vec3 color = shadePbr(s, v_position, views[v_view].eyeScene.xyz);
    o_color = vec4(linearToSrgb(color), 1.0);
}
