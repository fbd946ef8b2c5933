#version 450 core
// The window's readout and key help: each rectangle's own colour, alpha-blended by the
// drawer (the box is semi-opaque, the glyphs opaque).
layout(location = 0) in vec4 v_color;

layout(location = 0) out vec4 o_color;

void main()
{
    o_color = v_color;
}
