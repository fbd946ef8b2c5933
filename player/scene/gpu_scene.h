// A pack uploaded to the GPU: one vertex buffer per stream, one index buffer, textures
// (GL_TEXTURE_2D with the pack's mip chain; sRGB textures as GL_SRGB8_ALPHA8), materials
// and per-triangle statistics as SSBOs, and per-frame node transforms. Draws are listed
// per (node, primitive) so renderers can issue them (or multi-draw) in one place.
#pragma once

#include "gl_handles.h"
#include "gpu_memory_budget.h"
#include "scene_poser.h"

#include "lfd/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace lfd::player {

struct DrawItem {
    uint32_t node = 0;
    uint32_t primitive = 0;
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int32_t material = -1;
};

// The LFD_MATERIAL_*_TEXTURE bits of a material: the textures it samples, and
// LFD_MATERIAL_UV_TRANSFORM when a textured slot has a KHR_texture_transform.
uint32_t materialTextureFlags(const Material& material);

struct GpuSceneOptions {
    // Top mip levels to leave out and the budget figures; null: planned in the constructor
    // for GL_MAX_TEXTURE_SIZE only (no budget), warnings to stderr.
    const GpuMemoryPlan* plan = nullptr;
    // Streaming (TextureStreamer): allocate the buffers and texture storage only; the
    // streamer fills them from a MappedPack. Textures then sample nothing until their
    // first level is resident (GL_TEXTURE_BASE_LEVEL starts at the coarsest level).
    bool streamed = false;
    // --aniso: the scene textures' GL_TEXTURE_MAX_ANISOTROPY (1 = trilinear, as before),
    // clamped to the driver's limit; every renderer that samples them gets it (the raster
    // methods' texture(), lfdpr's textureGrad).
    float maxAnisotropy = 1.0f;
};

// Which pack levels a GL texture holds: GL level l is pack level firstPackLevel + l.
struct GpuTextureLayout {
    uint32_t firstPackLevel = 0;
    uint32_t levels = 0;
};

class GpuScene {
public:
    // Needs a current GL context. Without options.streamed the scene's textures must carry
    // their texels (readPack).
    explicit GpuScene(Scene scene, const GpuSceneOptions& options = {});
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    // Evaluates glTF node animations at `time` and uploads sceneFromObject per node.
    void update(double time);
    // Whether the scene has skinned or morphed meshes (the frame then has a pose stage).
    bool deforms() const { return poser_ != nullptr; }
    // Poses them at the last update's time into the vertex streams and the triangle
    // statistics (scene_poser.h); nothing for a static scene.
    void pose();

    const Scene& cpu() const { return scene_; } // metadata (textures' texels released after upload)
    const std::vector<DrawItem>& draws() const { return draws_; }
    const std::vector<glm::mat4>& sceneFromNode() const { return sceneFromNode_; }
    unsigned vertexArray() const { return vao_.get(); }
    unsigned indexBuffer() const { return ibo_.get(); }
    // The vertex buffer of stream `location` (LFD_ATTRIB_*), 0 when the pack has none.
    unsigned streamBuffer(unsigned location) const { return location < 4 ? streamVbos_[location].get() : 0u; }
    unsigned texture(int32_t index) const; // 0 for kNone
    // Binds the material's five textures to their units (LFD_UNIT_*; absent ones as 0, the
    // shaders branch on the material flags). material = kNone: the default material.
    void bindMaterialTextures(int32_t material) const;
    // The material's texture transforms as MaterialGpu holds them, slot s at 2s (linear
    // part) and 2s + 1 (offset, |det|): mvr.frag's per-draw uniform (LFD_LOC_UV_TRANSFORMS).
    const std::array<glm::vec4, 2 * kTextureSlotCount>& uvTransforms(int32_t material) const
    {
        return uvTransforms_[gpuMaterialIndex(material)];
    }
    // Index of `material` in the materials SSBO (kNone: the default material, stored last).
    uint32_t gpuMaterialIndex(int32_t material) const;
    unsigned materialBuffer() const { return materialSsbo_.get(); }
    unsigned triangleStatsBuffer() const { return statsSsbo_.get(); }
    unsigned nodeTransformBuffer() const { return nodeSsbo_.get(); }
    size_t gpuBytes() const { return gpuBytes_; }
    float maxAnisotropy() const { return anisotropy_; } // as applied (1 without driver support)
    // Unique per GpuScene made in this process (1, 2, ...), so renderers that keep tables
    // per scene rebuild them for a new one even where it reuses a freed one's address.
    uint64_t serial() const { return serial_; }
    const GpuTextureLayout& textureLayout(size_t index) const { return layouts_[index]; }

private:
    Scene scene_;
    std::vector<DrawItem> draws_;
    std::vector<std::array<glm::vec4, 2 * kTextureSlotCount>> uvTransforms_; // by GPU material index
    std::vector<glm::mat4> sceneFromNode_;
    float anisotropy_ = 1.0f;
    std::vector<gl::Texture> textures_;
    std::vector<GpuTextureLayout> layouts_;
    std::array<gl::Buffer, 4> streamVbos_; // by LFD_ATTRIB_* location; empty when absent
    gl::VertexArray vao_;
    gl::Buffer ibo_, materialSsbo_, statsSsbo_, nodeSsbo_;
    size_t gpuBytes_ = 0;
    uint64_t serial_;
    std::unique_ptr<ScenePoser> poser_; // only for scenes with deformers
    double time_ = 0.0;
};

} // namespace lfd::player
