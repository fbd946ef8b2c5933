// Vertex stage shared by mvr (one pass per view) and mvr-layered (one instance per view):
// both call lfdEmitVertex with the view index, so both produce the same clip positions.
#include "scene_bindings.glsl"

layout(location = LFD_ATTRIB_POSITION) in vec3 a_position;
layout(location = LFD_ATTRIB_NORMAL) in vec3 a_normal;
layout(location = LFD_ATTRIB_TANGENT) in vec4 a_tangent;
layout(location = LFD_ATTRIB_UV) in vec2 a_uv;

layout(location = LFD_LOC_NODE) uniform uint u_node;

layout(location = 0) out vec3 v_position; // scene space
layout(location = 1) out vec3 v_normal;   // scene space
layout(location = 2) out vec4 v_tangent;  // xyz scene space, w handedness
layout(location = 3) out vec2 v_uv;
layout(location = 4) flat out int v_view;

// note: mvr and mvr-layered are different programs; `invariant` makes the compiler
// evaluate gl_Position identically in both, so their rasterisation matches pixel for pixel.
invariant gl_Position;

void lfdEmitVertex(int view)
{
    NodeGpu node = nodes[u_node];
    vec4 positionScene = node.sceneFromObject * vec4(a_position, 1.0);
    v_position = positionScene.xyz;
    v_normal = mat3(node.normalFromObject) * a_normal;
    v_tangent = vec4(mat3(node.sceneFromObject) * a_tangent.xyz, a_tangent.w);
    v_uv = a_uv;
    v_view = view;
    gl_Position = views[view].clipFromScene * positionScene;
}
