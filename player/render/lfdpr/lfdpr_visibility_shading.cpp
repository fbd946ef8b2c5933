#include "lfdpr_visibility_shading.h"

#include "gpu_scene.h"
#include "lfdpr_constants.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

namespace lfd::player {

LfdprVisibilityShading::LfdprVisibilityShading(bool int64) : int64_(int64)
{
    const std::vector<std::string> defines =
        int64 ? std::vector<std::string>{"LFDPR_INT64 1"} : std::vector<std::string>{};
    splatProgram_ = gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_visibility.comp"}}, defines);
    try {
        shadeProgram_ = gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_shade.comp"}}, defines);
    } catch (...) {
        glDeleteProgram(splatProgram_);
        throw;
    }
}

LfdprVisibilityShading::~LfdprVisibilityShading()
{
    const GLuint buffers[] = {depth_, index_, materialIds_};
    glDeleteBuffers(3, buffers);
    glDeleteProgram(splatProgram_);
    glDeleteProgram(shadeProgram_);
}

void LfdprVisibilityShading::resize(uint32_t viewCount, uint32_t width, uint32_t height)
{
    if (viewCount == views_ && width == width_ && height == height_ && depth_)
        return;
    const GLuint old[] = {depth_, index_, materialIds_};
    glDeleteBuffers(3, old);
    views_ = viewCount;
    width_ = width;
    height_ = height;
    const size_t pixels = std::max<size_t>(size_t(viewCount) * width * height, 1);
    auto make = [](size_t bytes) {
        GLuint buffer = 0;
        glCreateBuffers(1, &buffer);
        glNamedBufferStorage(buffer, GLsizeiptr(bytes), nullptr, 0);
        return buffer;
    };
    depth_ = make(pixels * (int64_ ? 8 : 4));
    index_ = int64_ ? 0 : make(pixels * 4);
    materialIds_ = make(pixels * 4);
}

size_t LfdprVisibilityShading::viewBufferBytes() const { return size_t(views_) * width_ * height_ * 12; }

void LfdprVisibilityShading::splat(uint32_t points) const
{
    const LfdprConstants& k = LfdprConstants::get();
    // Step 1: clear: all ones = empty (a depth key beyond every depth).
    const GLuint ones = 0xFFFFFFFFu;
    glClearNamedBufferData(depth_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    if (index_)
        glClearNamedBufferData(index_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewDepth, depth_);
    if (index_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewColor, index_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (points == 0)
        return;

    // Step 2: splat (the 32-bit path's index pass runs only to repair, in shade()).
    splatPass(points, 0);
}

void LfdprVisibilityShading::splatPass(uint32_t points, uint32_t pass) const
{
    const LfdprConstants& k = LfdprConstants::get();
    const uint32_t groups = (points + k.groupSize - 1) / k.groupSize;
    const uint32_t x = std::min<uint32_t>(groups, 65535u);
    glUseProgram(splatProgram_);
    if (!int64_)
        glProgramUniform1ui(splatProgram_, k.locPass, pass);
    glDispatchCompute(x, (groups + x - 1) / x, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
}

uint32_t LfdprVisibilityShading::shade(const GpuScene& scene, ViewTargets& targets,
                                       const std::vector<int32_t>& texturedMaterials, uint32_t points,
                                       unsigned counters) const
{
    const LfdprConstants& k = LfdprConstants::get();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewDepth, depth_);
    if (index_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewColor, index_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboMaterialIds, materialIds_);
    glBindImageTexture(k.imageViews, targets.colorArray(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glProgramUniform1ui(shadeProgram_, bindings::kLocStreams, scene.cpu().vertices.mask());

    // Pass 0 (or 2 after a repair) classifies and shades untextured materials and the
    // first textured one; pass 1 then shades each further textured material.
    auto shadePasses = [&](GLuint firstPass) {
        glUseProgram(shadeProgram_);
        const size_t passes = std::max<size_t>(texturedMaterials.size(), 1);
        for (size_t i = 0; i < passes; ++i) {
            const int32_t material = texturedMaterials.empty() ? kNone : texturedMaterials[i];
            const GLuint gpuMaterial = texturedMaterials.empty() ? 0xFFFFFFFFu : scene.gpuMaterialIndex(material);
            glProgramUniform1ui(shadeProgram_, k.locPass, i == 0 ? firstPass : 1u);
            glProgramUniform1ui(shadeProgram_, k.locShadeMaterial, gpuMaterial);
            scene.bindMaterialTextures(material);
            glDispatchCompute((width_ + 7) / 8, views_, (height_ + 7) / 8); // (x tile, view, row tile)
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        glUseProgram(0);
    };
    shadePasses(0);

    // The 32-bit path's rare repair: the index pass, then the flagged pixels' shading.
    uint32_t repairs = 0;
    if (!int64_) {
        glGetNamedBufferSubData(counters, 5 * sizeof(uint32_t), sizeof(repairs), &repairs);
        if (repairs > 0) {
            splatPass(points, 1);
            shadePasses(2);
        }
    }
    // The EIA pass samples the array, read-back copies it.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    return repairs;
}

} // namespace lfd::player
