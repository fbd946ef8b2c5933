#version 450 core
// LFDPR point generation, fragment stage (paper sections 3.1, 3.3): each sampling pixel
// that overlaps the triangle is one point. Its position is the pixel centre mapped back
// onto the triangle plane (inverse of S_ortho * T_align); its attributes come from the
// barycentrics clamped onto the triangle; its texture values are fetched twice, at
// LOD_min and LOD_max (eqs. minLOD, maxLOD; multiview mipmapping), and the point is
// appended to the point buffer. No colour attachment: nothing is written but the buffer.
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"
#include "lfdpr_math.glsl"
#include "pbr_shading.glsl" // linearToSrgb
#include "texture_transform.glsl"

layout(location = 0) flat in uint g_record;
layout(location = 1) flat in vec2 g_tileOrigin;

layout(location = LFD_LOC_MATERIAL) uniform uint u_material;
layout(location = LFD_LOC_STREAMS) uniform uint u_streams;

layout(binding = LFD_UNIT_BASE_COLOR) uniform sampler2D t_baseColor;
layout(binding = LFD_UNIT_METALLIC_ROUGHNESS) uniform sampler2D t_metallicRoughness;
layout(binding = LFD_UNIT_NORMAL) uniform sampler2D t_normal;
layout(binding = LFD_UNIT_OCCLUSION) uniform sampler2D t_occlusion;
layout(binding = LFD_UNIT_EMISSIVE) uniform sampler2D t_emissive;

layout(std430, binding = LFDPR_SSBO_TRIANGLES) coherent readonly buffer TriangleRecords {
    LfdprPaperTriangleGpu records[];
};
layout(std430, binding = LFDPR_SSBO_SAMPLING) coherent readonly buffer TriangleSampling {
    LfdprPaperSamplingGpu sampling[];
};
layout(std430, binding = LFDPR_SSBO_POINTS) writeonly buffer Points {
    LfdprPaperPointGpu points[];
};

// Texture values at the two LODs of one texture (eqs. minLOD, maxLOD with its X_t * Y_t).
struct TexPair {
    vec4 lo; // at LOD_min
    vec4 hi; // at LOD_max
};

// Texture `slot` of material m at TEXCOORD_0 `uv`: the slot's KHR_texture_transform maps
// uv into the texture's own space and scales its areas by |det| (uvOffset.z), so the view
// pixel's footprint there, size_vpuv, scales with it.
TexPair fetchPair(sampler2D t, MaterialGpu m, uint slot, vec2 uv, vec2 vpuv, bool mipmapping)
{
    uv = mat2(m.uvLinear[slot].xy, m.uvLinear[slot].zw) * uv + m.uvOffset[slot].xy;
    vpuv *= m.uvOffset[slot].z;
    ivec2 size = textureSize(t, 0);
    float texels = float(size.x) * float(size.y);
    TexPair pair;
    pair.lo = textureLod(t, uv, mipmapping ? lfdLod(vpuv.x, texels) : 0.0);
    pair.hi = mipmapping ? textureLod(t, uv, lfdLod(vpuv.y, texels)) : pair.lo;
    return pair;
}

// Tangent-space normal map value -> scene-space normal (glTF: B = cross(N, T) * w), as
// mvr.frag does per pixel.
vec3 perturb(vec3 n, vec3 t, float handedness, vec4 texel, MaterialGpu m)
{
    vec3 tn = texel.xyz * 2.0 - 1.0;
    tn.xy *= m.params.z;
    vec3 b = cross(n, t) * handedness;
    if ((m.flags & LFD_MATERIAL_UV_TRANSFORM) != 0u) // the frame turns with the texture's axes
        lfdTransformTangentFrame(mat2(m.uvLinear[LFD_SLOT_NORMAL].xy, m.uvLinear[LFD_SLOT_NORMAL].zw), n, t, b);
    return normalize(mat3(t, b, n) * tn);
}

// The point's shading normal: the face normal, or the vertex normals interpolated at the
// (clamped) barycentrics w.
vec3 pointNormal(LfdprPaperSamplingGpu s, vec3 w, uint flags, vec3 faceNormal)
{
    if ((flags & LFDPR_TRIANGLE_FACE_NORMAL) != 0u)
        return faceNormal;
    vec3 n = w.x * lfdOctDecode(unpackSnorm2x16(s.normals.x)) + w.y * lfdOctDecode(unpackSnorm2x16(s.normals.y)) +
             w.z * lfdOctDecode(unpackSnorm2x16(s.normals.z));
    return dot(n, n) > 0.0 ? normalize(n) : faceNormal;
}

// The normal map's perturbed normals at LOD_min and LOD_max (n itself where the tangent
// is degenerate).
void normalMapPair(LfdprPaperSamplingGpu s, MaterialGpu m, vec3 w, vec3 n, vec2 uv, vec2 vpuv, bool mipmapping,
                   inout vec3 normalLo, inout vec3 normalHi)
{
    vec3 tangent = w.x * lfdOctDecode(unpackSnorm2x16(s.tangents.x)) +
                   w.y * lfdOctDecode(unpackSnorm2x16(s.tangents.y)) +
                   w.z * lfdOctDecode(unpackSnorm2x16(s.tangents.z));
    // Handedness of the nearest vertex (it is constant across a well-formed triangle).
    uint nearest = w.x >= w.y && w.x >= w.z ? 0u : (w.y >= w.z ? 1u : 2u);
    float handedness = (s.tangents.w & (1u << nearest)) != 0u ? -1.0 : 1.0;
    vec3 t = tangent - n * dot(n, tangent);
    if (dot(t, t) > 1e-12) {
        t = normalize(t);
        TexPair nt = fetchPair(t_normal, m, LFD_SLOT_NORMAL, uv, vpuv, mipmapping);
        normalLo = perturb(n, t, handedness, nt.lo, m);
        normalHi = perturb(n, t, handedness, nt.hi, m);
    }
}

void main()
{
    // Step 1: conservative coverage in the sampling viewport.
    LfdprPaperSamplingGpu s = sampling[g_record];
    vec2 q0 = s.q01.xy, q1 = s.q01.zw, q2 = s.q2uv0.xy;
    vec2 q = gl_FragCoord.xy + g_tileOrigin;
    if (!lfdPixelOverlapsTriangle(q, q0, q1, q2))
        return;

    // Step 2: the point: pixel centre on the triangle plane; attributes from the clamped
    // barycentrics (conservative pixels may lie just outside the triangle).
    LfdprPaperTriangleGpu r = records[g_record];
    LfdFrame frame;
    frame.u = r.axisU.xyz;
    frame.v = r.axisV.xyz;
    frame.n = cross(frame.u, frame.v);
    vec2 spacing = vec2(r.axisU.w, r.axisV.w);
    vec3 position = lfdSceneFromSampling(q, s.origin.xyz, frame, spacing);
    vec3 w = lfdClampedBarycentric(q0, q1, q2, q);
    vec2 uv = w.x * s.q2uv0.zw + w.y * s.uv12.xy + w.z * s.uv12.zw;
    uint flags = floatBitsToUint(r.p2.w);
    vec3 n = pointNormal(s, w, flags, frame.n);

    // Step 3: texture values at LOD_min and LOD_max for each of the material's textures
    // (multiview mipmapping); LOD 0 for both when it is switched off.
    MaterialGpu m = materials[u_material];
    bool useTextures = (u_streams & LFD_STREAM_UV) != 0u;
    bool mipmapping = (u_lfd.counts.z & LFDPR_OPTION_MV_MIPMAPPING) != 0u;
    vec2 vpuv = r.mip.xy;
    TexPair base = TexPair(vec4(1.0), vec4(1.0));
    TexPair mr = TexPair(vec4(1.0), vec4(1.0));
    TexPair occlusion = TexPair(vec4(1.0), vec4(1.0));
    TexPair emissive = TexPair(vec4(1.0), vec4(1.0));
    vec3 normalLo = n, normalHi = n;
    if (useTextures && (m.flags & LFD_MATERIAL_BASE_COLOR_TEXTURE) != 0u)
        base = fetchPair(t_baseColor, m, LFD_SLOT_BASE_COLOR, uv, vpuv, mipmapping);
    if (useTextures && (m.flags & LFD_MATERIAL_METALLIC_ROUGHNESS_TEXTURE) != 0u)
        mr = fetchPair(t_metallicRoughness, m, LFD_SLOT_METALLIC_ROUGHNESS, uv, vpuv, mipmapping);
    if (useTextures && (m.flags & LFD_MATERIAL_OCCLUSION_TEXTURE) != 0u)
        occlusion = fetchPair(t_occlusion, m, LFD_SLOT_OCCLUSION, uv, vpuv, mipmapping);
    if (useTextures && (m.flags & LFD_MATERIAL_EMISSIVE_TEXTURE) != 0u)
        emissive = fetchPair(t_emissive, m, LFD_SLOT_EMISSIVE, uv, vpuv, mipmapping);
    if (useTextures && (m.flags & LFD_MATERIAL_NORMAL_TEXTURE) != 0u &&
        (u_streams & LFD_STREAM_TANGENT) != 0u && (flags & LFDPR_TRIANGLE_FACE_NORMAL) == 0u)
        normalMapPair(s, m, w, n, uv, vpuv, mipmapping, normalLo, normalHi);

    // Step 4: append (never past the capacity: the count still grows, so the renderer sees
    // the overflow and enlarges the buffer for the next frame).
    uint index = atomicAdd(counters.pointCount, 1u);
    if (index >= u_lfd.counts.y)
        return;
    LfdprPaperPointGpu p;
    p.position = position;
    p.triangle = g_record;
    p.normalMin = packSnorm2x16(lfdOctEncode(normalLo));
    p.normalMax = packSnorm2x16(lfdOctEncode(normalHi));
    p.baseColorMin = packUnorm4x8(vec4(linearToSrgb(base.lo.rgb), base.lo.a));
    p.baseColorMax = packUnorm4x8(vec4(linearToSrgb(base.hi.rgb), base.hi.a));
    p.ormMin = packUnorm4x8(vec4(occlusion.lo.r, mr.lo.g, mr.lo.b, 0.0));
    p.ormMax = packUnorm4x8(vec4(occlusion.hi.r, mr.hi.g, mr.hi.b, 0.0));
    p.emissiveMin = packUnorm4x8(vec4(linearToSrgb(emissive.lo.rgb), 0.0));
    p.emissiveMax = packUnorm4x8(vec4(linearToSrgb(emissive.hi.rgb), 0.0));
    points[index] = p;
}
