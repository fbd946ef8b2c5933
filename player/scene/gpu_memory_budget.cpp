#include "gpu_memory_budget.h"

#include "scene_bindings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace lfd::player {

namespace {

// Not in every epoxy version's headers: the enums of GL_NVX_gpu_memory_info and GL_ATI_meminfo.
constexpr GLenum kNvxCurrentAvailableVidmem = 0x9049; // KiB
constexpr GLenum kAtiTextureFreeMemory = 0x87FC;      // 4 values, [0] = total free KiB

uint64_t bufferBytes(uint64_t bytes) { return std::max<uint64_t>(bytes, 16); } // as gl::createBuffer keeps

std::string mib(uint64_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", double(bytes) / (1024.0 * 1024.0));
    return text;
}

} // namespace

GpuLimits queryGpuLimits()
{
    GpuLimits limits;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    limits.maxTextureSize = uint32_t(std::max(maxSize, 1));
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kib = 0;
        glGetIntegerv(kNvxCurrentAvailableVidmem, &kib);
        if (kib > 0)
            limits.availableBytes = uint64_t(kib) * 1024;
    } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint kib[4] = {};
        glGetIntegerv(kAtiTextureFreeMemory, kib);
        if (kib[0] > 0)
            limits.availableBytes = uint64_t(kib[0]) * 1024;
    }
    return limits;
}

uint64_t geometryGpuBytes(const Scene& scene)
{
    const VertexStreams& v = scene.vertices;
    uint64_t total = 0;
    for (const uint64_t stream : {uint64_t(v.positions.size()) * 12, uint64_t(v.normals.size()) * 12,
                                  uint64_t(v.tangents.size()) * 16, uint64_t(v.uvs.size()) * 8})
        if (stream != 0)
            total += bufferBytes(stream);
    total += bufferBytes(uint64_t(scene.indices.size()) * 4);
    total += bufferBytes((uint64_t(scene.materials.size()) + 1) * sizeof(bindings::MaterialGpu));
    total += bufferBytes(uint64_t(scene.triangleStats.size()) * sizeof(TriangleStats));
    total += bufferBytes(std::max<uint64_t>(scene.nodes.size(), 1) * sizeof(bindings::NodeGpu));
    return total;
}

uint64_t textureLevelBytes(const Texture& texture, uint32_t firstLevel)
{
    uint64_t total = 0;
    for (size_t l = firstLevel; l < texture.mips.size(); ++l)
        total += texture.mips[l].size;
    return total;
}

GpuMemoryPlan planGpuMemory(const Scene& scene, const std::string& packName, std::optional<uint64_t> budgetBytes,
                            uint32_t maxTextureSize)
{
    GpuMemoryPlan plan;
    const size_t count = scene.textures.size();
    plan.droppedLevels.assign(count, 0);
    std::vector<uint32_t> sizeDrops(count, 0);

    // Step 1: levels the driver cannot allocate at all.
    for (size_t t = 0; t < count; ++t) {
        const Texture& tex = scene.textures[t];
        uint32_t& drop = plan.droppedLevels[t];
        while (drop + 1 < tex.mips.size() &&
               (tex.mips[drop].width > maxTextureSize || tex.mips[drop].height > maxTextureSize))
            ++drop;
        sizeDrops[t] = drop;
        if (drop != 0)
            plan.warnings.push_back("texture " + std::to_string(t) + " (" + tex.name + "): " +
                                    std::to_string(tex.width) + "x" + std::to_string(tex.height) +
                                    " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxTextureSize) + ", dropping " +
                                    std::to_string(drop) + " top mip level(s), uploading " +
                                    std::to_string(tex.mips[drop].width) + "x" +
                                    std::to_string(tex.mips[drop].height));
    }

    // Step 2: geometry fits whole or not at all.
    plan.geometryBytes = geometryGpuBytes(scene);
    auto textureTotal = [&] {
        uint64_t total = 0;
        for (size_t t = 0; t < count; ++t)
            total += textureLevelBytes(scene.textures[t], plan.droppedLevels[t]);
        return total;
    };
    plan.textureBytes = textureTotal();
    if (!budgetBytes)
        return plan;
    if (plan.geometryBytes > *budgetBytes)
        throw std::runtime_error(packName + ": geometry needs " + mib(plan.geometryBytes) +
                                 " MiB of GPU memory, the budget is " + mib(*budgetBytes) +
                                 " MiB (--gpu-memory-budget)");

    // Step 3: textures lose their largest remaining top level until they fit; dropping
    // the largest level first loses the least detail per byte saved.
    const uint64_t room = *budgetBytes - plan.geometryBytes;
    while (plan.textureBytes > room) {
        size_t largest = count;
        for (size_t t = 0; t < count; ++t) {
            const Texture& tex = scene.textures[t];
            if (plan.droppedLevels[t] + 1 >= tex.mips.size())
                continue;
            if (largest == count ||
                tex.mips[plan.droppedLevels[t]].size > scene.textures[largest].mips[plan.droppedLevels[largest]].size)
                largest = t;
        }
        if (largest == count)
            throw std::runtime_error(packName + ": geometry (" + mib(plan.geometryBytes) +
                                     " MiB) and the textures at their smallest level (" + mib(plan.textureBytes) +
                                     " MiB) exceed the GPU memory budget of " + mib(*budgetBytes) +
                                     " MiB (--gpu-memory-budget)");
        plan.textureBytes -= scene.textures[largest].mips[plan.droppedLevels[largest]].size;
        ++plan.droppedLevels[largest];
    }
    for (size_t t = 0; t < count; ++t) {
        const uint32_t drop = plan.droppedLevels[t] - sizeDrops[t];
        if (drop == 0)
            continue;
        const Texture& tex = scene.textures[t];
        plan.warnings.push_back("texture " + std::to_string(t) + " (" + tex.name + "): dropping " +
                                std::to_string(drop) + " top mip level(s) to fit the GPU memory budget of " +
                                mib(*budgetBytes) + " MiB, uploading " +
                                std::to_string(tex.mips[plan.droppedLevels[t]].width) + "x" +
                                std::to_string(tex.mips[plan.droppedLevels[t]].height));
    }
    return plan;
}

} // namespace lfd::player
