#version 450 core
// mvr-layered: one instanced draw covers all views; instance i renders view i into layer
// i of the view texture array by writing gl_Layer from the vertex shader
// (GL_ARB_shader_viewport_layer_array; AMD/NV variants accepted), after Unterguggenberger
// et al. 2020. No geometry shader, so it is not limited by GS invocation counts.
#extension GL_ARB_shader_viewport_layer_array : enable
#extension GL_AMD_vertex_shader_layer : enable
#extension GL_NV_viewport_array2 : enable
#include "mvr_vertex.glsl"

void main()
{
    lfdEmitVertex(gl_InstanceID);
    gl_Layer = gl_InstanceID;
}
