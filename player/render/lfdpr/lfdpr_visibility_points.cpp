#include "lfdpr_visibility_points.h"

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

using lfdpr_bindings::LfdprVisibilityWorkgroupGpu;

bool alphaTested(const GpuScene& scene, int32_t material)
{
    return material != kNone && scene.cpu().materials[size_t(material)].alphaMode == AlphaMode::Mask;
}

// (x, y) workgroups covering `n`, x at most 65535 (the guaranteed limit).
void dispatchCovering(uint32_t n)
{
    const uint32_t x = std::min<uint32_t>(n, 65535u);
    glDispatchCompute(x, (n + x - 1) / x, 1);
}

} // namespace

LfdprVisibilityPointGeneration::LfdprVisibilityPointGeneration(bool pixelCentreCulling, bool trimMargin,
                                                               uint32_t cellScale, bool gpuWork)
{
    for (int alpha = 0; alpha < 2; ++alpha)
        for (int large = 0; large < 2; ++large) {
            std::vector<std::string> defines;
            if (pixelCentreCulling)
                defines.emplace_back("LFDPR_PIXEL_CENTRE_CULLING 1");
            if (trimMargin)
                defines.emplace_back("LFDPR_TRIM_MARGIN 1");
            if (alpha)
                defines.emplace_back("LFDPR_ALPHA_TEST 1");
            if (large)
                defines.emplace_back("LFDPR_LARGE_PASS 1");
            if (!alpha && cellScale > 1) // alpha-masked cells carry the mask: the paper's spacing
                defines.push_back("LFDPR_CELL_SCALE " + std::to_string(cellScale));
            if (gpuWork)
                defines.emplace_back("LFDPR_WORK_GPU 1");
            programs_[alpha][large] = gl::Program(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_visibility_points.comp"}}, defines));
        }
}

void LfdprVisibilityPointGeneration::prepare(const GpuScene& scene, const std::vector<uint32_t>& drawFirstTriangle)
{
    if (scene.serial() == sceneSerial_)
        return;
    sceneSerial_ = scene.serial();
    drawCount_ = scene.draws().size();
    const LfdprConstants& k = LfdprConstants::get();

    // Step 1: the workgroup table, draws without an alpha test first (one class), then each
    // alpha-tested draw (a class each); a class's large triangles queue in a segment of
    // its triangle count. Each entry's firstRecord is the drawn index of its first triangle
    // (draws in scene order, whatever the class order), the slot of its triangles' records.
    std::vector<LfdprVisibilityWorkgroupGpu> table;
    classes_.clear();
    uint32_t queued = 0;
    auto addDraw = [&](uint32_t d) {
        const uint32_t triangles = scene.draws()[d].indexCount / 3;
        for (uint32_t first = 0; first < triangles; first += k.groupSize)
            table.push_back({d, first, std::min(k.groupSize, triangles - first), drawFirstTriangle[d] + first});
        return triangles;
    };
    DispatchClass opaque{kNone, 0, 0, 0};
    for (uint32_t d = 0; d < drawCount_; ++d)
        if (!alphaTested(scene, scene.draws()[d].material))
            queued += addDraw(d);
    opaque.workgroups = uint32_t(table.size());
    classes_.push_back(opaque);
    for (uint32_t d = 0; d < drawCount_; ++d)
        if (alphaTested(scene, scene.draws()[d].material)) {
            DispatchClass c{scene.draws()[d].material, uint32_t(table.size()), 0, queued};
            queued += addDraw(d);
            c.workgroups = uint32_t(table.size()) - c.firstWorkgroup;
            classes_.push_back(c);
        }

    // Step 2: the buffers.
    workgroups_ = gl::createBuffer(table.size() * sizeof(LfdprVisibilityWorkgroupGpu), 0, table.empty() ? nullptr : table.data());
    large_ = gl::createBuffer(size_t(std::max<uint32_t>(queued, 1)) * k.largeEntryBytes);
    largeDispatch_ = gl::createBuffer(classes_.size() * k.largeDispatchBytes);
    bytes_ = table.size() * sizeof(LfdprVisibilityWorkgroupGpu) + size_t(queued) * k.largeEntryBytes +
             classes_.size() * k.largeDispatchBytes;
}

void LfdprVisibilityPointGeneration::clearQueues() const
{
    const GLuint noGroups[4] = {0, 1, 1, 0}; // x, y, z, queued (lfdpr_visibility_points.comp keeps x, y)
    glClearNamedBufferData(largeDispatch_, GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, noGroups);
}

size_t LfdprVisibilityPointGeneration::bufferBytes() const { return bytes_; }

size_t LfdprVisibilityPointGeneration::clearedBytes() const
{
    return classes_.size() * LfdprConstants::get().largeDispatchBytes;
}

void LfdprVisibilityPointGeneration::run(const GpuScene& scene) const
{
    const LfdprConstants& k = LfdprConstants::get();
    const uint32_t streams = scene.cpu().vertices.mask();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboWorkgroups, workgroups_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboLarge, large_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboLargeDispatch, largeDispatch_);
    auto use = [&](unsigned program, const DispatchClass& c, uint32_t index) {
        glUseProgram(program);
        glProgramUniform1ui(program, bindings::kLocStreams, streams);
        glProgramUniform1ui(program, k.locFirstWorkgroup, c.firstWorkgroup);
        glProgramUniform1ui(program, k.locWorkgroups, c.workgroups);
        glProgramUniform1ui(program, k.locLargeClass, index);
        glProgramUniform1ui(program, k.locLargeBase, c.largeBase);
        scene.bindMaterialTextures(c.material); // the alpha test's base colour
    };

    // Step 1: one invocation per triangle, one dispatch per class.
    for (uint32_t i = 0; i < classes_.size(); ++i) {
        const DispatchClass& c = classes_[i];
        if (c.workgroups == 0)
            continue;
        use(programs_[c.material != kNone][0], c, i);
        dispatchCovering(c.workgroups);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    // Step 2: each class's queued large triangles, one workgroup each (indirect: the
    // counts stay on the GPU).
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, largeDispatch_);
    for (uint32_t i = 0; i < classes_.size(); ++i) {
        const DispatchClass& c = classes_[i];
        if (c.workgroups == 0)
            continue;
        use(programs_[c.material != kNone][1], c, i);
        glDispatchComputeIndirect(GLintptr(i) * GLintptr(k.largeDispatchBytes));
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    // For the splat: the points (storage), its indirect dispatch (command); for the
    // counters' read-back copy (buffer update).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace lfd::player
