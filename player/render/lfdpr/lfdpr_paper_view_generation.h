// LFDPR view generation (paper sections 3.2, 3.3; shaders/lfdpr_paper_splat.comp) and the
// resolve into ViewTargets (shaders/lfdpr_paper_resolve.comp): the per-view depth/colour buffers
// for either atomics path, the indirect dispatch built from the point counter
// (shaders/lfdpr_paper_dispatch.comp), the splat pass(es) and the resolve.
#pragma once

#include "gl_handles.h"

#include <cstddef>
#include <cstdint>

namespace lfd::player {

class ViewTargets;

class LfdprPaperViewGeneration {
public:
    // int64: use the 64-bit atomicMin path (needs GL_NV_shader_atomic_int64 and
    // GL_ARB_gpu_shader_int64; its shaders are only compiled then).
    explicit LfdprPaperViewGeneration(bool int64);

    bool int64() const { return int64_; }
    // (Re)allocates the view buffers for N views of W x H (no-op when unchanged).
    void resize(uint32_t viewCount, uint32_t width, uint32_t height);
    size_t viewBufferBytes() const; // 8 bytes per view pixel on either path

    // Clears the view buffers and splats every point into every view. The caller has
    // bound the LFDPR buffers, the scene's materials and the frame uniforms; `counters`
    // is the counter buffer (its dispatch words are written here and read indirectly).
    void splat(unsigned counters) const;
    // Writes the resolved colours into targets' colour array.
    void resolve(ViewTargets& targets) const;

private:
    bool int64_;
    gl::Program dispatchProgram_, splatProgram_, resolveProgram_;
    gl::Buffer depth_, color_; // 64-bit path: depth_ holds the words, color_ stays empty
    uint32_t views_ = 0, width_ = 0, height_ = 0;
};

} // namespace lfd::player
