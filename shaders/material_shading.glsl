// The glTF metallic-roughness material at one surface point, shaded for one view's eye:
// one function shared by mvr.frag (per fragment) and lfdpr_visibility_shade.comp (per visible view
// pixel of the visibility pipeline), so both evaluate the same material the same way.
// The includer defines LFD_SAMPLE(sampler, uv, uvFromTexcoord): texture() with the
// rasteriser's implicit derivatives in a fragment shader (which see the transformed uv),
// textureGrad() with analytic gradients in compute, taken through the slot's
// KHR_texture_transform (its linear part, uvFromTexcoord) to the texture's own uv space.
// Needs scene_bindings.glsl and pbr_shading.glsl first.
#include "texture_transform.glsl"

// The textures a program can sample (LFD_MATERIAL_*_TEXTURE bits): a program compiled for
// a known set (lfdpr_visibility_shade.comp, per shading group) contains no code for the others.
// note: Mesa's llvmpipe runs every `if` under a lane mask - a texture fetch no lane takes
// still costs its full price - so leaving the code out is the only way to skip it there.
#ifndef LFD_TEXTURE_MASK
#define LFD_TEXTURE_MASK 0xFFFFFFFFu
#endif

layout(binding = LFD_UNIT_BASE_COLOR) uniform sampler2D t_baseColor;
layout(binding = LFD_UNIT_METALLIC_ROUGHNESS) uniform sampler2D t_metallicRoughness;
layout(binding = LFD_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = LFD_UNIT_OCCLUSION) uniform sampler2D t_occlusion;
layout(binding = LFD_UNIT_EMISSIVE) uniform sampler2D t_emissive;

struct LfdSurfacePoint {
    vec3 position;     // scene space
    vec3 normal;       // interpolated vertex normal (any length); or, without a normal
                       // stream, the geometric normal facing the eye
    bool vertexNormal; // the normal comes from the normal stream
    bool frontFacing;  // as the rasteriser decides it (double-sided back faces flip)
    vec4 tangent;      // xyz scene space, w handedness
    vec2 uv;
};

// Slot `slot`'s texture coordinates (KHR_texture_transform: uv' = linear * uv + offset)
// and the linear part, which carries uv gradients into the slot's space. A fragment
// shader defines LFD_UV_TRANSFORMS to take them from its per-draw uniform
// (LFD_LOC_UV_TRANSFORMS) instead of the material buffer: llvmpipe reads storage buffers as
// zeros in a fragment shader's helper invocations, so a uv computed from one would corrupt
// texture()'s implicit derivatives along every triangle edge.
#ifdef LFD_UV_TRANSFORMS
#define LFD_SLOT_LINEAR(m, slot) LFD_UV_TRANSFORMS[2u * (slot)]
#define LFD_SLOT_OFFSET(m, slot) LFD_UV_TRANSFORMS[2u * (slot) + 1u]
#else
#define LFD_SLOT_LINEAR(m, slot) m.uvLinear[slot]
#define LFD_SLOT_OFFSET(m, slot) m.uvOffset[slot]
#endif

mat2 lfdSlotLinear(MaterialGpu m, uint slot)
{
    vec4 l = LFD_SLOT_LINEAR(m, slot);
    return mat2(l.xy, l.zw);
}

vec2 lfdSlotUv(MaterialGpu m, uint slot, vec2 uv)
{
    return lfdSlotLinear(m, slot) * uv + LFD_SLOT_OFFSET(m, slot).xy;
}

#define LFD_SAMPLE_SLOT(t, slot) LFD_SAMPLE(t, lfdSlotUv(m, slot, p.uv), lfdSlotLinear(m, slot))

// False when an alpha-masked material discards the point.
bool lfdShadeMaterial(MaterialGpu m, uint streams, LfdSurfacePoint p, vec3 eye, out vec3 color)
{
    color = vec3(0.0);
    // note: flags and streams are uniform per draw in mvr, so texture() stays in uniform
    // control flow and hardware mip selection (derivatives) is well defined.
    bool useTextures = (streams & LFD_STREAM_UV) != 0u;

    // Base colour and alpha (texture is GL_SRGB8_ALPHA8: the fetch returns linear values).
    vec4 baseColor = m.baseColorFactor;
    if (useTextures && (m.flags & LFD_MATERIAL_BASE_COLOR_TEXTURE & LFD_TEXTURE_MASK) != 0u)
        baseColor *= LFD_SAMPLE_SLOT(t_baseColor, LFD_SLOT_BASE_COLOR);
    // note: BLEND is drawn as opaque (no sorting of transparent surfaces).
    if (m.alphaMode == LFD_ALPHA_MASK && baseColor.a < m.emissiveCutoff.w)
        return false;
    // KHR_materials_unlit: the base colour as it is, shown as stored (no exposure or tone map).
    if ((m.flags & LFD_MATERIAL_UNLIT) != 0u) {
        color = linearToSrgb(baseColor.rgb);
        return true;
    }

    // Geometric normal: interpolated vertex normal (flipped on double-sided back faces),
    // or the face normal that always faces the eye.
    vec3 n = normalize(p.normal);
    if (p.vertexNormal && !p.frontFacing)
        n = -n;

    // Normal map (tangent space, glTF convention: B = cross(N, T) * w).
    if (useTextures && (m.flags & LFD_MATERIAL_NORMAL_TEXTURE & LFD_TEXTURE_MASK) != 0u &&
        (streams & LFD_STREAM_TANGENT) != 0u) {
        vec3 t = p.tangent.xyz - n * dot(n, p.tangent.xyz);
        if (dot(t, t) > 1e-12) {
            t = normalize(t);
            vec3 b = cross(n, t) * (p.tangent.w < 0.0 ? -1.0 : 1.0);
            // The slot's KHR_texture_transform turns the frame with the texture's axes.
            if ((m.flags & LFD_MATERIAL_UV_TRANSFORM) != 0u)
                lfdTransformTangentFrame(lfdSlotLinear(m, LFD_SLOT_NORMAL), n, t, b);
            vec3 tn = LFD_SAMPLE_SLOT(t_normal, LFD_SLOT_NORMAL).xyz * 2.0 - 1.0;
            // A two-channel (BC5) normal map stores x and y of the unit normal.
            if ((m.flags & LFD_MATERIAL_NORMAL_TWO_CHANNEL) != 0u)
                tn.z = sqrt(max(1.0 - dot(tn.xy, tn.xy), 0.0));
            tn.xy *= m.params.z;
            n = normalize(mat3(t, b, n) * tn);
        }
    }

    SurfacePbr s;
    s.baseColor = baseColor.rgb;
    s.metallic = m.params.x;
    s.roughness = m.params.y;
    if (useTextures && (m.flags & LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE & LFD_TEXTURE_MASK) != 0u) {
        vec4 mr = LFD_SAMPLE_SLOT(t_metallicRoughness, LFD_SLOT_METALLIC_ROUGHNESS);
        s.roughness *= mr.g;
        s.metallic *= mr.b;
    }
    s.roughness = clamp(s.roughness, 0.0, 1.0);
    s.metallic = clamp(s.metallic, 0.0, 1.0);
    s.occlusion = 1.0;
    if (useTextures && (m.flags & LFD_MATERIAL_OCCLUSION_TEXTURE & LFD_TEXTURE_MASK) != 0u)
        s.occlusion = 1.0 + m.params.w * (LFD_SAMPLE_SLOT(t_occlusion, LFD_SLOT_OCCLUSION).r - 1.0);
    s.emissive = m.emissiveCutoff.rgb;
    if (useTextures && (m.flags & LFD_MATERIAL_EMISSIVE_TEXTURE & LFD_TEXTURE_MASK) != 0u)
        s.emissive *= LFD_SAMPLE_SLOT(t_emissive, LFD_SLOT_EMISSIVE).rgb;
    s.normal = n;

    color = lfdDisplayEncode(shadePbr(s, p.position, eye));
    return true;
}
