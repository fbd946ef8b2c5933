#include "frame_limits.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lfd::player {

namespace {

std::string gib(uint64_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", double(bytes) / double(uint64_t(1) << 30));
    return text;
}

std::string size(uint64_t w, uint64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

// The profile's view size scaled by `linear` (< 1), each side at least 1, as a flag.
std::string viewSizeFlag(const FrameShape& s, double linear)
{
    const auto side = [&](uint32_t v) { return std::max<uint64_t>(1, uint64_t(std::floor(double(v) * linear))); };
    return "--view-size " + size(side(s.viewWidth), side(s.viewHeight));
}

// A setting for a limit on a per-pixel quantity (texels, bytes): the view size scaled by
// sqrt(limit / need), or the view count scaled by limit / need where that leaves a view.
std::string areaFix(const FrameShape& s, uint64_t need, uint64_t limit)
{
    const double ratio = double(limit) / double(need);
    std::string fix = viewSizeFlag(s, std::sqrt(ratio) * 0.999);
    const uint64_t views = uint64_t(std::floor(double(s.views) * ratio));
    if (views >= 1)
        fix += " or --views " + std::to_string(views);
    return fix;
}

std::string line(const char* limitName, const std::string& what, uint64_t need, uint64_t limit, const std::string& fix)
{
    return std::string(limitName) + ": " + what + " needs " + std::to_string(need) + ", the driver allows " +
           std::to_string(limit) + "; " + fix + " would fit";
}

} // namespace

FrameNeeds frameNeeds(const FrameShape& s)
{
    FrameNeeds n;
    const uint64_t viewPixels = uint64_t(s.views) * s.viewWidth * s.viewHeight;
    n.renderViews = uint64_t(s.views) * s.supersampleViews;
    n.renderWidth = uint64_t(s.viewWidth) * s.supersampleSize;
    n.renderHeight = uint64_t(s.viewHeight) * s.supersampleSize;
    const uint64_t renderPixels = n.renderViews * n.renderWidth * n.renderHeight;
    const uint64_t targetBytes = s.depthTargets ? 8 : 4; // RGBA8 colour (+ 32-bit float depth)
    n.totalBytes = targetBytes * viewPixels;
    if (renderPixels != viewPixels)
        n.totalBytes += targetBytes * renderPixels; // the supersampled targets as well
    if (s.viewBuffers) {
        n.viewBufferTexels = renderPixels;
        n.viewBufferBytes = renderPixels * s.viewBufferBytesPerPixel;
        n.totalBytes += 8 * renderPixels; // 64-bit depth, or 32-bit depth + 32-bit index
    }
    if (s.prefilter != PrefilterPlanes::None) {
        n.prefilterWidth = 3 * uint64_t(s.viewWidth);
        n.totalBytes += 2 * n.prefilterWidth * s.viewHeight * s.views; // R16F
    }
    n.totalBytes += 4 * uint64_t(s.panelWidth) * s.panelHeight; // the EIA, RGBA8
    return n;
}

std::optional<std::string> checkFrameLimits(const FrameShape& s, const FrameLimits& l)
{
    const FrameNeeds n = frameNeeds(s);
    const std::string views = std::to_string(n.renderViews) + " views of " + size(n.renderWidth, n.renderHeight);
    const auto sideFix = [&](uint64_t side, uint64_t limit) { return viewSizeFlag(s, double(limit) / double(side)); };

    // View targets: one 2D array texture, a layer per view.
    if (n.renderViews > l.maxArrayTextureLayers)
        return line("GL_MAX_ARRAY_TEXTURE_LAYERS", "the view targets (" + views + ")", n.renderViews,
                    l.maxArrayTextureLayers, "--views " + std::to_string(l.maxArrayTextureLayers / s.supersampleViews));
    const uint64_t side = std::max(n.renderWidth, n.renderHeight);
    if (side > l.maxTextureSize)
        return line("GL_MAX_TEXTURE_SIZE", "the view targets (" + views + ")", side, l.maxTextureSize,
                    sideFix(side, l.maxTextureSize));
    if (std::max(s.panelWidth, s.panelHeight) > l.maxTextureSize)
        return line("GL_MAX_TEXTURE_SIZE", "the EIA (panel " + size(s.panelWidth, s.panelHeight) + ")",
                    std::max(s.panelWidth, s.panelHeight), l.maxTextureSize, "a display profile with a smaller panel");
    if (s.viewBuffers) {
        if (n.viewBufferTexels > l.maxTextureBufferTexels)
            return line("GL_MAX_TEXTURE_BUFFER_SIZE", "the lfdpr view buffers (" + views + ", texels)",
                        n.viewBufferTexels, l.maxTextureBufferTexels,
                        areaFix(s, n.viewBufferTexels, l.maxTextureBufferTexels));
        if (n.viewBufferBytes > l.maxShaderStorageBlockBytes)
            return line("GL_MAX_SHADER_STORAGE_BLOCK_SIZE", "the lfdpr view buffers (" + views + ", bytes)",
                        n.viewBufferBytes, l.maxShaderStorageBlockBytes,
                        areaFix(s, n.viewBufferBytes, l.maxShaderStorageBlockBytes));
    }
    if (s.prefilter != PrefilterPlanes::None) {
        const bool volume = s.prefilter == PrefilterPlanes::Volume;
        const char* name = volume ? "GL_MAX_3D_TEXTURE_SIZE" : "GL_MAX_TEXTURE_SIZE";
        const uint64_t maxSide = volume ? l.max3dTextureSize : l.maxTextureSize;
        const std::string what = std::string("the prefiltered planes of --aa ") + (volume ? "view-spatial" : "spatial") +
                                 " (3 view widths: " + size(n.prefilterWidth, s.viewHeight) + " x " +
                                 std::to_string(s.views) + ")";
        const uint64_t planeSide = std::max<uint64_t>(n.prefilterWidth, s.viewHeight);
        if (planeSide > maxSide)
            return line(name, what, planeSide, maxSide,
                        viewSizeFlag(s, double(maxSide) / double(planeSide)) + " or --aa none");
        const uint64_t maxDepth = volume ? l.max3dTextureSize : l.maxArrayTextureLayers;
        if (s.views > maxDepth)
            return line(volume ? "GL_MAX_3D_TEXTURE_SIZE" : "GL_MAX_ARRAY_TEXTURE_LAYERS", what, s.views, maxDepth,
                        "--views " + std::to_string(maxDepth) + " or --aa none");
    }
    if (l.availableBytes && n.totalBytes > *l.availableBytes) {
        const uint64_t eia = 4 * uint64_t(s.panelWidth) * s.panelHeight;
        const std::string fix = *l.availableBytes > eia
                                    ? areaFix(s, n.totalBytes - eia, *l.availableBytes - eia)
                                    : std::string("a display profile with a smaller panel");
        return "GPU memory (GL_NVX_gpu_memory_info / GL_ATI_meminfo): the frame (" + views + ") needs " +
               gib(n.totalBytes) + ", the driver reports " + gib(*l.availableBytes) + " free; " + fix + " would fit";
    }
    return std::nullopt;
}

FrameLimits queryFrameLimits()
{
    FrameLimits l;
    GLint v = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &v);
    l.maxTextureSize = uint64_t(std::max(v, 0));
    v = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &v);
    l.maxArrayTextureLayers = uint64_t(std::max(v, 0));
    v = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &v);
    l.max3dTextureSize = uint64_t(std::max(v, 0));
    v = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &v);
    l.maxTextureBufferTexels = uint64_t(std::max(v, 0));
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    l.maxShaderStorageBlockBytes = uint64_t(std::max<GLint64>(bytes, 0));
    // Free memory: the same extensions as the scene's budget (scene/gpu_memory_budget.cpp).
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kib = 0;
        glGetIntegerv(0x9049, &kib); // GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, KiB
        if (kib > 0)
            l.availableBytes = uint64_t(kib) * 1024;
    } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint kib[4] = {};
        glGetIntegerv(0x87FC, kib); // TEXTURE_FREE_MEMORY_ATI, [0] = total free KiB
        if (kib[0] > 0)
            l.availableBytes = uint64_t(kib[0]) * 1024;
    }
    return l;
}

} // namespace lfd::player
