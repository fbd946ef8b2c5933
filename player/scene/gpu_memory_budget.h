// How much of a pack goes to the GPU: geometry must fit whole, textures may lose their
// finest (top) mip levels - to fit GL_MAX_TEXTURE_SIZE (a larger level cannot be
// allocated: GL_INVALID_VALUE) and to fit a GPU memory budget (lfd-play
// --gpu-memory-budget). The plan is computed on the CPU before anything is allocated, so
// a pack that cannot fit fails with one line instead of a GL_OUT_OF_MEMORY mid-upload.
#pragma once

#include "lfd/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lfd::player {

struct GpuLimits {
    uint32_t maxTextureSize = 0;              // GL_MAX_TEXTURE_SIZE
    std::optional<uint64_t> availableBytes;   // GL_NVX_gpu_memory_info / GL_ATI_meminfo; unset: unknown
};
// Needs a current GL context.
GpuLimits queryGpuLimits();

struct GpuMemoryPlan {
    std::vector<uint32_t> droppedLevels; // per texture: top mip levels not uploaded
    uint64_t geometryBytes = 0;          // buffers (as GpuScene counts them)
    uint64_t textureBytes = 0;           // texture storage after the drops
    std::vector<std::string> warnings;   // one line each, naming the texture
};

// Bytes of the scene's buffers on the GPU: vertex streams, indices, triangle statistics,
// materials (plus the default one) and node transforms, each at least 16 bytes.
uint64_t geometryGpuBytes(const Scene& scene);
// Bytes of levels [first, end) of a texture's chain.
uint64_t textureLevelBytes(const Texture& texture, uint32_t firstLevel);

// Throws std::runtime_error "<pack>: geometry needs X MiB of GPU memory, the budget is Y
// MiB" when the buffers alone exceed `budgetBytes`, or when the textures do not fit even
// at their 1x1 level. Textures lose top levels largest first until the rest fits.
GpuMemoryPlan planGpuMemory(const Scene& scene, const std::string& packName, std::optional<uint64_t> budgetBytes,
                            uint32_t maxTextureSize);

} // namespace lfd::player
