// The N rendered views: one GL_TEXTURE_2D_ARRAY (RGBA8, layer i = view i, sRGB-encoded
// values, row 0 = bottom as usual in GL) plus a matching depth array for raster renderers.
// Every renderer writes here; the EIA builder, quilt and view PNGs read from here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lfd::player {

class ViewTargets {
public:
    ViewTargets(uint32_t viewCount, uint32_t width, uint32_t height);
    ~ViewTargets();
    ViewTargets(const ViewTargets&) = delete;
    ViewTargets& operator=(const ViewTargets&) = delete;

    uint32_t viewCount() const { return viewCount_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    unsigned colorArray() const { return color_; } // GL texture name, GL_RGBA8
    unsigned depthArray() const { return depth_; } // GL texture name, GL_DEPTH_COMPONENT32F
    // Framebuffer with all layers attached (layered rendering) and per-layer framebuffers.
    unsigned layeredFramebuffer() const { return layeredFbo_; }
    unsigned layerFramebuffer(uint32_t view) const { return layerFbos_[view]; }
    size_t bytes() const; // GPU memory of colour + depth

    void clear(const float rgba[4]);
    // Reads view `view` as RGBA8, rows top to bottom (image order).
    std::vector<uint8_t> readView(uint32_t view) const;

private:
    uint32_t viewCount_, width_, height_;
    unsigned color_ = 0, depth_ = 0, layeredFbo_ = 0;
    std::vector<unsigned> layerFbos_;
};

} // namespace lfd::player
