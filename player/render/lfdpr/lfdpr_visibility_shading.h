// LFDPR visibility splatting and per-pixel shading (the visibility pipeline;
// shaders/lfdpr_visibility.comp, shaders/lfdpr_shade.comp): the per-view depth and point
// index buffers for either atomics path, the splat pass(es), and the shading passes that
// write the visible pixels (or the background) into the ViewTargets colour array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lfd::player {

class GpuScene;
class ViewTargets;

class LfdprVisibilityShading {
public:
    // int64: one 64-bit atomicMin pass (GL_NV_shader_atomic_int64; its shaders are only
    // compiled then); otherwise a depth pass and a point-index pass over 32-bit words.
    explicit LfdprVisibilityShading(bool int64);
    ~LfdprVisibilityShading();
    LfdprVisibilityShading(const LfdprVisibilityShading&) = delete;
    LfdprVisibilityShading& operator=(const LfdprVisibilityShading&) = delete;

    bool int64() const { return int64_; }
    void resize(uint32_t viewCount, uint32_t width, uint32_t height);
    // 8 bytes per view pixel (depth + point index) plus 4 (the material id).
    size_t viewBufferBytes() const;

    // Clears the view buffers and splats `points` points into every view (one pass on
    // either path). The caller has bound the scene, the LFDPR buffers and the constants.
    void splat(uint32_t points) const;
    // Shades every visible pixel into targets: one pass per textured material the scene
    // draws with (`texturedMaterials`, scene material indices; the first pass also writes
    // the background and shades untextured materials). On the 32-bit path, pixels whose
    // point index lost a race to a nearer point (counted in the counter buffer `counters`)
    // are repaired - the index pass over all `points`, then their shading - and their
    // number is returned (0 on the 64-bit path).
    uint32_t shade(const GpuScene& scene, ViewTargets& targets, const std::vector<int32_t>& texturedMaterials,
                   uint32_t points, unsigned counters) const;

private:
    void splatPass(uint32_t points, uint32_t pass) const;

    bool int64_;
    unsigned splatProgram_ = 0, shadeProgram_ = 0;
    unsigned depth_ = 0, index_ = 0, materialIds_ = 0; // 64-bit path: depth_ holds the words
    uint32_t views_ = 0, width_ = 0, height_ = 0;
};

} // namespace lfd::player
