#version 450 core
// Fragment stage of mvr and mvr-layered: glTF metallic-roughness material
// (material_shading.glsl), shaded for the eye of this fragment's view, written
// sRGB-encoded. texture() takes its derivatives from the slot's transformed uv itself.
#include "scene_bindings.glsl"
#include "pbr_shading.glsl"
#define LFD_SAMPLE(t, uv, uvFromTexcoord) texture(t, uv)
layout(location = LFD_LOC_UV_TRANSFORMS) uniform vec4 u_uvTransforms[2 * LFD_SLOT_COUNT];
#define LFD_UV_TRANSFORMS u_uvTransforms
#include "material_shading.glsl"

layout(location = 0) in vec3 v_position;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec4 v_tangent;
layout(location = 3) in vec2 v_uv;
layout(location = 4) flat in int v_view;

layout(location = LFD_LOC_MATERIAL) uniform uint u_material;
layout(location = LFD_LOC_STREAMS) uniform uint u_streams;

layout(location = 0) out vec4 o_color;

void main()
{
    LfdSurfacePoint p;
    p.position = v_position;
    p.vertexNormal = (u_streams & LFD_STREAM_NORMAL) != 0u;
    // Without a normal stream: the face normal from derivatives (it always faces the eye).
    p.normal = p.vertexNormal ? v_normal : cross(dFdx(v_position), dFdy(v_position));
    p.frontFacing = gl_FrontFacing;
    p.tangent = v_tangent;
    p.uv = v_uv;
    vec3 color;
    if (!lfdShadeMaterial(materials[u_material], u_streams, p, views[v_view].eyeScene.xyz, color))
        discard;
    o_color = vec4(color, 1.0);
}
