#include "text_overlay_drawer.h"

#include "shader_library.h"

#include <epoxy/gl.h>

#include <vector>

namespace lfd::player {

namespace {

// The vertex layout text_overlay.vert reads: window pixels and an RGBA8 colour.
struct OverlayVertex {
    float x, y;
    uint8_t rgba[4];
};
static_assert(sizeof(OverlayVertex) == 12);

constexpr GLint kLocWindowSize = 0; // text_overlay.vert's u_windowSize

// Restores a capability's enabled state when the scope ends.
class Capability {
public:
    Capability(GLenum cap, bool on) : cap_(cap), was_(glIsEnabled(cap) == GL_TRUE) { set(on); }
    ~Capability() { set(was_); }
    Capability(const Capability&) = delete;
    Capability& operator=(const Capability&) = delete;

private:
    void set(bool on) { on ? glEnable(cap_) : glDisable(cap_); }
    GLenum cap_;
    bool was_;
};

} // namespace

TextOverlayDrawer::TextOverlayDrawer()
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, "text_overlay.vert"}, {GL_FRAGMENT_SHADER, "text_overlay.frag"}})),
      vao_(gl::createVertexArray())
{
    glVertexArrayAttribFormat(vao_, 0, 2, GL_FLOAT, GL_FALSE, offsetof(OverlayVertex, x));
    glVertexArrayAttribFormat(vao_, 1, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(OverlayVertex, rgba));
    for (GLuint attribute : {0u, 1u}) {
        glVertexArrayAttribBinding(vao_, attribute, 0);
        glEnableVertexArrayAttrib(vao_, attribute);
    }
}

void TextOverlayDrawer::draw(const OverlayLayout& layout, int windowWidth, int windowHeight)
{
    if (layout.rects.empty() || windowWidth <= 0 || windowHeight <= 0)
        return;
    std::vector<OverlayVertex> vertices;
    vertices.reserve(layout.rects.size() * 6);
    for (const OverlayRect& r : layout.rects) {
        auto corner = [&](float x, float y) {
            vertices.push_back({x, y, {r.rgba[0], r.rgba[1], r.rgba[2], r.rgba[3]}});
        };
        corner(r.x0, r.y0);
        corner(r.x1, r.y0);
        corner(r.x1, r.y1);
        corner(r.x0, r.y0);
        corner(r.x1, r.y1);
        corner(r.x0, r.y1);
    }
    if (vertices.size() > capacity_) {
        // Grown to a power of two, so a readout whose digits change does not reallocate.
        capacity_ = 1024;
        while (capacity_ < vertices.size())
            capacity_ *= 2;
        vbo_ = gl::createBuffer(capacity_ * sizeof(OverlayVertex), GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, sizeof(OverlayVertex));
    }
    glNamedBufferSubData(vbo_, 0, GLsizeiptr(vertices.size() * sizeof(OverlayVertex)), vertices.data());

    // The colours are written as given: no sRGB encode (the panel's window has no sRGB
    // framebuffer; a desktop one might), no depth or face culling, blended over the output.
    const Capability blend(GL_BLEND, true), srgb(GL_FRAMEBUFFER_SRGB, false), depth(GL_DEPTH_TEST, false),
        cull(GL_CULL_FACE, false), scissor(GL_SCISSOR_TEST, false);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, windowWidth, windowHeight);
    glUseProgram(program_);
    glProgramUniform2f(program_, kLocWindowSize, float(windowWidth), float(windowHeight));
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace lfd::player
