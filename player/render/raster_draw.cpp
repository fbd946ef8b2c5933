#include "raster_draw.h"

#include "frame_stages.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

namespace lfd::player {

RasterDraw::RasterDraw(const char* vertexShader)
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, vertexShader}, {GL_FRAGMENT_SHADER, "mvr.frag"}}))
{
}

void RasterDraw::beginFrame(const GpuScene& scene, const FrameSetup& frame)
{
    uniforms_.upload(frame);
    glUseProgram(program_);
    glBindVertexArray(scene.vertexArray());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboMaterials, scene.materialBuffer());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboNodes, scene.nodeTransformBuffer());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboTriangleStats, scene.triangleStatsBuffer());
    glProgramUniform1ui(program_, bindings::kLocStreams, scene.cpu().vertices.mask());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB); // the shader writes sRGB-encoded values itself
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glCullFace(GL_BACK);
    glViewport(0, 0, GLsizei(frame.profile.viewWidth), GLsizei(frame.profile.viewHeight));
}

void RasterDraw::drawScene(const GpuScene& scene, unsigned instances) const
{
    const Scene& cpu = scene.cpu();
    for (const DrawItem& draw : scene.draws()) {
        const Material* material =
            draw.material == kNone ? nullptr : &cpu.materials[size_t(draw.material)];
        glProgramUniform1ui(program_, bindings::kLocNode, draw.node);
        glProgramUniform1ui(program_, bindings::kLocMaterial, scene.gpuMaterialIndex(draw.material));
        glProgramUniform4fv(program_, bindings::kLocUvTransforms, 2 * kTextureSlotCount,
                            &scene.uvTransforms(draw.material)[0].x);
        scene.bindMaterialTextures(draw.material);

        // Culling: glTF single-sided materials cull back faces, double-sided ones draw both
        // (the shader flips the normal). A mirroring node transform flips the winding.
        if (material && material->doubleSided)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        const glm::mat4& m = scene.sceneFromNode()[draw.node];
        glFrontFace(glm::determinant(glm::mat3(m)) < 0.0f ? GL_CW : GL_CCW);

        glDrawElementsInstanced(GL_TRIANGLES, GLsizei(draw.indexCount), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(size_t(draw.firstIndex) * sizeof(uint32_t)),
                                GLsizei(instances));
    }
}

void RasterDraw::endFrame() const
{
    glBindVertexArray(0);
    glUseProgram(0);
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RasterDraw::countWork(const GpuScene& scene, const ViewTargets& targets)
{
    workBytesCleared_ = uint64_t(targets.viewCount()) * targets.width() * targets.height() * (4 + 4);
    uint64_t triangles = 0;
    for (const DrawItem& d : scene.draws())
        triangles += d.indexCount / 3;
    workTriangleViews_ = triangles * targets.viewCount();
}

std::vector<std::pair<std::string, double>> RasterDraw::workStats() const
{
    return {{"work_triangle_views", double(workTriangleViews_)}, {"work_bytes_cleared", double(workBytesCleared_)}};
}

void RasterRenderer::render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets, GpuTimer& timer)
{
    timer.begin(stage::kViewGeneration);
    targets.clear(kBackground);
    draw_.countWork(scene, targets);
    draw_.beginFrame(scene, frame);
    drawViews(scene, targets);
    draw_.endFrame();
    timer.end();
}

} // namespace lfd::player
