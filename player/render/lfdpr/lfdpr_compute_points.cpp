#include "lfdpr_compute_points.h"

#include "gpu_scene.h"
#include "lfdpr_constants.h"
#include "scene_bindings.h"
#include "shader_library.h"

#include "lfd/scene.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

namespace lfd::player {

namespace {

bool alphaTested(const GpuScene& scene, int32_t material)
{
    return material != kNone && scene.cpu().materials[size_t(material)].alphaMode == AlphaMode::Mask;
}

} // namespace

LfdprComputePointGeneration::LfdprComputePointGeneration(bool pixelCentreCulling, uint32_t cellScale)
{
    for (int alpha = 0; alpha < 2; ++alpha)
        for (int large = 0; large < 2; ++large) {
            std::vector<std::string> defines;
            if (pixelCentreCulling)
                defines.emplace_back("LFDPR_PIXEL_CENTRE_CULLING 1");
            if (alpha)
                defines.emplace_back("LFDPR_ALPHA_TEST 1");
            if (large)
                defines.emplace_back("LFDPR_LARGE_PASS 1");
            if (!alpha && cellScale > 1) // alpha-masked cells carry the mask: the paper's spacing
                defines.push_back("LFDPR_CELL_SCALE " + std::to_string(cellScale));
            programs_[alpha][large] = gl::Program(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_points.comp"}}, defines));
        }
}

void LfdprComputePointGeneration::run(const GpuScene& scene, const std::vector<uint32_t>& largeBase,
                                      unsigned largeDispatch) const
{
    const LfdprConstants& k = LfdprConstants::get();
    const uint32_t streams = scene.cpu().vertices.mask();
    auto setDrawUniforms = [&](unsigned program, const DrawItem& draw, uint32_t index) {
        glProgramUniform1ui(program, bindings::kLocNode, draw.node);
        glProgramUniform1ui(program, bindings::kLocMaterial, scene.gpuMaterialIndex(draw.material));
        glProgramUniform1ui(program, bindings::kLocStreams, streams);
        glProgramUniform1ui(program, k.locDraw, index);
        glProgramUniform1ui(program, k.locTriangles, draw.indexCount / 3);
        glProgramUniform1ui(program, k.locLargeBase, largeBase[index]);
    };

    // Step 1: one invocation per triangle, draw by draw (each with its material's
    // textures, for the alpha test of masked materials). Groups beyond the guaranteed
    // 65535 in x spill into y.
    const std::vector<DrawItem>& draws = scene.draws();
    for (uint32_t d = 0; d < draws.size(); ++d) {
        const uint32_t triangles = draws[d].indexCount / 3;
        if (triangles == 0)
            continue;
        const unsigned program = programs_[alphaTested(scene, draws[d].material)][0];
        glUseProgram(program);
        setDrawUniforms(program, draws[d], d);
        scene.bindMaterialTextures(draws[d].material);
        const uint32_t groups = (triangles + k.groupSize - 1) / k.groupSize;
        const uint32_t x = std::min<uint32_t>(groups, 65535u);
        glDispatchCompute(x, (groups + x - 1) / x, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    // Step 2: the large triangles each draw queued, one workgroup each (indirect: the
    // counts stay on the GPU).
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, largeDispatch);
    for (uint32_t d = 0; d < draws.size(); ++d) {
        if (draws[d].indexCount < 3)
            continue;
        const unsigned program = programs_[alphaTested(scene, draws[d].material)][1];
        glUseProgram(program);
        setDrawUniforms(program, draws[d], d);
        scene.bindMaterialTextures(draws[d].material);
        glDispatchComputeIndirect(GLintptr(d) * GLintptr(k.largeDispatchBytes));
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace lfd::player
