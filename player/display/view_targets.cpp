#include "view_targets.h"

#include "gl_context.h"
#include "row_order.h"

#include <epoxy/gl.h>

#include <string>

namespace lfd::player {

ViewTargets::ViewTargets(uint32_t viewCount, uint32_t width, uint32_t height)
    : viewCount_(viewCount), width_(width), height_(height)
{
    GLint maxLayers = 0, maxSize = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (viewCount == 0 || width == 0 || height == 0 || viewCount > uint32_t(maxLayers) ||
        width > uint32_t(maxSize) || height > uint32_t(maxSize))
        throw gl::GlError("view targets: " + std::to_string(viewCount) + " views of " +
                          std::to_string(width) + "x" + std::to_string(height) +
                          " exceed the driver's limits (" + std::to_string(maxLayers) +
                          " layers, " + std::to_string(maxSize) + " pixels)");

    // Colour: RGBA8 holding sRGB-encoded values written by the shaders (not GL_SRGB8, so
    // no conversion happens on write or read and readback bytes are display values).
    color_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(color_, 1, GL_RGBA8, GLsizei(width), GLsizei(height), GLsizei(viewCount));
    glTextureParameteri(color_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(color_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(color_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(color_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GLuint view = 0;
    glGenTextures(1, &view); // a texture view needs a name no target has been bound to
    glTextureView(view, GL_TEXTURE_2D_ARRAY, color_, GL_SRGB8_ALPHA8, 0, 1, 0, GLuint(viewCount));
    srgbView_ = gl::Texture(view);
    glTextureParameteri(srgbView_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(srgbView_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void ViewTargets::createDepthAndFramebuffers()
{
    depth_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depth_, 1, GL_DEPTH_COMPONENT32F, GLsizei(width_), GLsizei(height_),
                       GLsizei(viewCount_));
    const float one = 1.0f; // a new depth array starts cleared, like one cleared by clear()
    glClearTexImage(depth_, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);

    // One layered framebuffer (all layers; gl_Layer selects) and one per view.
    auto check = [](GLuint fbo, const char* what) {
        const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw gl::GlError(std::string("view targets: ") + what + " framebuffer incomplete (0x" +
                              std::to_string(status) + ")");
    };
    layeredFbo_ = gl::createFramebuffer();
    glNamedFramebufferTexture(layeredFbo_, GL_COLOR_ATTACHMENT0, color_, 0);
    glNamedFramebufferTexture(layeredFbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
    check(layeredFbo_, "layered");
    layerFbos_.reserve(viewCount_);
    for (uint32_t i = 0; i < viewCount_; ++i) {
        layerFbos_.push_back(gl::createFramebuffer());
        glNamedFramebufferTextureLayer(layerFbos_[i], GL_COLOR_ATTACHMENT0, color_, 0, GLint(i));
        glNamedFramebufferTextureLayer(layerFbos_[i], GL_DEPTH_ATTACHMENT, depth_, 0, GLint(i));
        check(layerFbos_[i], "per-view");
    }
}

unsigned ViewTargets::depthArray()
{
    if (!hasDepth())
        createDepthAndFramebuffers();
    return depth_.get();
}

unsigned ViewTargets::layeredFramebuffer()
{
    if (!hasDepth())
        createDepthAndFramebuffers();
    return layeredFbo_.get();
}

unsigned ViewTargets::layerFramebuffer(uint32_t view)
{
    if (!hasDepth())
        createDepthAndFramebuffers();
    return layerFbos_[view].get();
}

size_t ViewTargets::colourBytes() const { return size_t(viewCount_) * width_ * height_ * 4; } // RGBA8

size_t ViewTargets::depthBytes() const { return size_t(viewCount_) * width_ * height_ * 4; } // DEPTH32F

size_t ViewTargets::bytes() const { return colourBytes() + (hasDepth() ? depthBytes() : 0); }

void ViewTargets::clear(const float rgba[4])
{
    // glClearTexImage clears every layer at once, independent of framebuffer state.
    const float one = 1.0f;
    glClearTexImage(color_, 0, GL_RGBA, GL_FLOAT, rgba);
    if (hasDepth())
        glClearTexImage(depth_, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
}

std::vector<uint8_t> ViewTargets::readView(uint32_t view) const
{
    if (view >= viewCount_)
        throw gl::GlError("view targets: view " + std::to_string(view) + " out of range (" +
                          std::to_string(viewCount_) + " views)");
    const size_t row = size_t(width_) * 4;
    std::vector<uint8_t> glOrder(row * height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureSubImage(color_, 0, 0, 0, GLint(view), GLsizei(width_), GLsizei(height_), 1,
                         GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(glOrder.size()), glOrder.data());
    return gl::flipRows(glOrder, row); // GL order to image order
}

} // namespace lfd::player
