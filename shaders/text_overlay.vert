#version 450 core
// The window's readout and key help (player/app/text_overlay_drawer.h): rectangles given
// in window pixels, x right and y down from the top-left corner, each with its colour.
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec4 a_color; // RGBA8, normalized

layout(location = 0) uniform vec2 u_windowSize;

layout(location = 0) out vec4 v_color;

void main()
{
    v_color = a_color;
    // Pixel edges land on pixel edges, so every rectangle covers whole pixels.
    gl_Position = vec4(2.0 * a_position.x / u_windowSize.x - 1.0, 1.0 - 2.0 * a_position.y / u_windowSize.y, 0.0, 1.0);
}
