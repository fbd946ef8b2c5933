#include "lfdpr_paper_view_generation.h"

#include "lfdpr_constants.h"
#include "lfdpr_counters.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace lfd::player {

LfdprPaperViewGeneration::LfdprPaperViewGeneration(bool int64) : int64_(int64)
{
    const std::vector<std::string> defines =
        int64 ? std::vector<std::string>{"LFDPR_INT64 1"} : std::vector<std::string>{};
    dispatchProgram_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_paper_dispatch.comp"}}));
    splatProgram_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_paper_splat.comp"}}, defines));
    resolveProgram_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_paper_resolve.comp"}}, defines));
}

void LfdprPaperViewGeneration::resize(uint32_t viewCount, uint32_t width, uint32_t height)
{
    if (viewCount == views_ && width == width_ && height == height_ && depth_)
        return;
    views_ = viewCount;
    width_ = width;
    height_ = height;
    const size_t pixels = std::max<size_t>(size_t(viewCount) * width * height, 1);
    depth_ = gl::createBuffer(pixels * (int64_ ? sizeof(uint64_t) : sizeof(uint32_t)));
    color_ = int64_ ? gl::Buffer() : gl::createBuffer(pixels * sizeof(uint32_t));
}

size_t LfdprPaperViewGeneration::viewBufferBytes() const { return size_t(views_) * width_ * height_ * 8; }

void LfdprPaperViewGeneration::splat(unsigned counters) const
{
    // Step 1: dispatch arguments from the point count (GPU side, no CPU read-back).
    glUseProgram(dispatchProgram_);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);

    // Step 2: clear: all ones = empty (depth 0xFFFFFFFF is beyond every depth in [0, 1]).
    const GLuint ones = 0xFFFFFFFFu;
    glClearNamedBufferData(depth_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    if (color_)
        glClearNamedBufferData(color_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    const LfdprConstants& k = LfdprConstants::get();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewDepth, depth_);
    if (color_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewWinner, color_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    // Step 3: splat, one pass (64-bit) or depth then colour (32-bit), with the arguments
    // lfdpr_paper_dispatch.comp wrote into the counter block.
    const GLintptr dispatchOffset = offsetof(LfdprPaperCountersGpu, dispatchX);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counters);
    glUseProgram(splatProgram_);
    const int passes = int64_ ? 1 : 2;
    for (int pass = 0; pass < passes; ++pass) {
        if (!int64_)
            glProgramUniform1ui(splatProgram_, k.locPass, GLuint(pass));
        glDispatchComputeIndirect(dispatchOffset);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glUseProgram(0);
}

void LfdprPaperViewGeneration::resolve(ViewTargets& targets) const
{
    glUseProgram(resolveProgram_);
    glBindImageTexture(LfdprConstants::get().imageViews, targets.colorArray(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA8);
    gl::dispatchCovering(resolveProgram_, width_, height_, views_); // one invocation per view pixel
    // The EIA pass samples the array, read-back copies it.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace lfd::player
