#version 450 core
// mvr: one raster pass per view; the view index is a uniform set before each pass.
#include "mvr_vertex.glsl"

layout(location = LFD_LOC_VIEW) uniform int u_view;

void main()
{
    lfdEmitVertex(u_view);
}
