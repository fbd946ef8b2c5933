// Preflight of one frame's GPU resources against the driver's limits, before the first frame
// allocates anything: the view targets (2D array, colour + depth), the supersampled targets, the
// lfdpr per-pixel view buffers (SSBOs read through buffer textures), the spatial reconstructions'
// prefiltered planes (--aa spatial: 2D array; view-spatial: 3D texture, 3 view widths wide) and the
// panel-sized EIA, and their sum against the GPU memory the driver reports (GL_NVX_gpu_memory_info
// / GL_ATI_meminfo). Pure computation (checkFrameLimits) with the GL query apart
// (queryFrameLimits), so tests use fake limits. 8K panels (7680x4320, 49-72 views) are what first
// reach these limits; docs/player/quilts.md "8K panels".
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace lfd::player {

struct FrameLimits {
    uint64_t maxTextureSize = 0;          // GL_MAX_TEXTURE_SIZE
    uint64_t maxArrayTextureLayers = 0;   // GL_MAX_ARRAY_TEXTURE_LAYERS
    uint64_t max3dTextureSize = 0;        // GL_MAX_3D_TEXTURE_SIZE
    uint64_t maxTextureBufferTexels = 0;  // GL_MAX_TEXTURE_BUFFER_SIZE
    uint64_t maxShaderStorageBlockBytes = 0; // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
    std::optional<uint64_t> availableBytes;  // GPU memory free; unset: not reported
};

enum class PrefilterPlanes : uint32_t { None, Layered, Volume }; // --aa none|view, spatial, view-spatial

struct FrameShape {
    uint32_t views = 0, viewWidth = 0, viewHeight = 0; // the profile's (after --views / --view-size)
    uint32_t panelWidth = 0, panelHeight = 0;
    uint32_t supersampleViews = 1;  // --ss 2v: 2
    uint32_t supersampleSize = 1;   // --ss 2s: 2 (both axes)
    bool viewBuffers = false;       // lfdpr renderers: per-pixel depth/index buffers
    bool depthTargets = true;       // raster renderers (mvr, mvr-layered): a D32F array beside the colours
    uint32_t viewBufferBytesPerPixel = 8; // their SSBO words per pixel (8: 64-bit atomics)
    PrefilterPlanes prefilter = PrefilterPlanes::None;
};

// What the frame allocates, in the units of the limits.
struct FrameNeeds {
    uint64_t renderViews = 0, renderWidth = 0, renderHeight = 0; // the targets the renderer draws into
    uint64_t viewBufferTexels = 0;   // lfdpr: one texel per rendered view pixel
    uint64_t viewBufferBytes = 0;    // lfdpr: its largest SSBO
    uint64_t prefilterWidth = 0;     // 3 view widths
    uint64_t totalBytes = 0;         // all of the above plus view targets and the EIA
};

FrameNeeds frameNeeds(const FrameShape& shape);

// nullopt when the frame fits; otherwise one line naming the first limit exceeded, the
// value needed, the limit and a setting that would fit (a --view-size or --views), e.g.
// "frame needs 72 views of 8192x8192 = 4.8 GiB of views in GL_MAX_TEXTURE_BUFFER_SIZE ...".
std::optional<std::string> checkFrameLimits(const FrameShape& shape, const FrameLimits& limits);

// The current context's limits (needs a GL context).
FrameLimits queryFrameLimits();

} // namespace lfd::player
