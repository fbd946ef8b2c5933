// The N rendered views: one GL_TEXTURE_2D_ARRAY (RGBA8, layer i = view i, sRGB-encoded
// values, row 0 = bottom as usual in GL) plus a matching depth array for raster renderers.
// Every renderer writes here; the EIA builder, quilt and view PNGs read from here.
// The depth array and the framebuffers exist only once a raster renderer asks for them
// (mvr, mvr-layered): lfdpr resolves visibility in its own view words, and at 8K a depth
// array nobody reads is 4 B per view pixel (127 MiB at 72 views of 960x480).
#pragma once

#include "gl_handles.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lfd::player {

class ViewTargets {
public:
    ViewTargets(uint32_t viewCount, uint32_t width, uint32_t height);

    uint32_t viewCount() const { return viewCount_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    unsigned colorArray() const { return color_.get(); } // GL texture name, GL_RGBA8
    // The same texels through a GL_SRGB8_ALPHA8 texture view: fetches return linear values
    // (the EIA's reconstruction filters average in linear light).
    unsigned linearColorArray() const { return srgbView_.get(); }
    // GL texture name, GL_DEPTH_COMPONENT32F; allocated on the first call.
    unsigned depthArray();
    // Framebuffer with all layers attached (layered rendering) and per-layer framebuffers,
    // colour + depth; created (with the depth array) on the first call.
    unsigned layeredFramebuffer();
    unsigned layerFramebuffer(uint32_t view);
    bool hasDepth() const { return depth_.get() != 0; }
    size_t colourBytes() const; // GPU memory of the colour array
    size_t depthBytes() const;  // GPU memory of the depth array, allocated or not
    size_t bytes() const;       // GPU memory held now: colour, and depth once allocated

    // Clears colour, and depth where it exists.
    void clear(const float rgba[4]);
    // Reads view `view` as RGBA8, rows top to bottom (image order).
    std::vector<uint8_t> readView(uint32_t view) const;

private:
    void createDepthAndFramebuffers();

    uint32_t viewCount_, width_, height_;
    gl::Texture color_, depth_, srgbView_;
    gl::Framebuffer layeredFbo_;
    std::vector<gl::Framebuffer> layerFbos_;
};

} // namespace lfd::player
