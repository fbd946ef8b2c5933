// Draws an OverlayLayout (text_overlay_layout.h) into the window's default framebuffer:
// one small program (shaders/text_overlay.vert / .frag), the rectangles as two triangles
// each, alpha-blended over what is there. Called after the output's blit and after
// --screenshot has read the back buffer, so no saved image ever contains it.
#pragma once

#include "gl_handles.h"
#include "text_overlay_layout.h"

#include <cstddef>

namespace lfd::player {

class TextOverlayDrawer {
public:
    TextOverlayDrawer(); // needs a current GL context; throws GlError if the shaders fail
    // Leaves the GL state it touches (blend, depth, cull, scissor, sRGB, program, vertex
    // array, draw framebuffer, viewport) as the frame pipeline expects it.
    void draw(const OverlayLayout& layout, int windowWidth, int windowHeight);

private:
    gl::Program program_;
    gl::VertexArray vao_;
    gl::Buffer vbo_;
    size_t capacity_ = 0; // vertices vbo_ holds
};

} // namespace lfd::player
