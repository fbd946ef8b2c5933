#version 450 core
// LFDPR point generation, vertex stage (paper section 3, figure LFDPRpipeline): transform
// to scene space and flag visibility against the union of the LFD view frusta (one bit per
// plane of the union's convex hull; the geometry shader culls a triangle whose three
// vertices are all outside the same plane, i.e. a triangle outside every view).
#include "scene_bindings.glsl"
#include "lfdpr_bindings.glsl"
#include "lfdpr_math.glsl"
#include "lfdpr_triangle_setup.glsl"

layout(location = LFD_ATTRIB_POSITION) in vec3 a_position;
layout(location = LFD_ATTRIB_NORMAL) in vec3 a_normal;
layout(location = LFD_ATTRIB_TANGENT) in vec4 a_tangent;
layout(location = LFD_ATTRIB_UV) in vec2 a_uv;

layout(location = LFD_LOC_NODE) uniform uint u_node;

layout(location = 0) out vec3 v_position; // scene space
layout(location = 1) out vec3 v_normal;   // scene space
layout(location = 2) out vec4 v_tangent;  // xyz scene space, w handedness
layout(location = 3) out vec2 v_uv;
layout(location = 4) flat out uint v_outside; // bit k: outside hull plane k

void main()
{
    NodeGpu node = nodes[u_node];
    vec4 positionScene = node.sceneFromObject * vec4(a_position, 1.0);
    v_position = positionScene.xyz;
    v_normal = mat3(node.normalFromObject) * a_normal;
    v_tangent = vec4(mat3(node.sceneFromObject) * a_tangent.xyz, a_tangent.w);
    v_uv = a_uv;
    v_outside = lfdOutsideHullBits(v_position);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // the geometry shader places the triangle
}
