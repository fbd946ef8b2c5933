#include "lfdpr_visibility_shading.h"

#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "lfdpr_constants.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include "lfd/scene.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>

namespace lfd::player {

namespace {

using lfdpr_bindings::LfdprVisibilityRepairGpu;
using lfdpr_bindings::LfdprVisibilityCountersGpu;
using lfdpr_bindings::LfdprVisibilityShadeCountersGpu;

std::vector<std::string> atomicsDefines(bool int64)
{
    return int64 ? std::vector<std::string>{"LFDPR_INT64 1"} : std::vector<std::string>{};
}

constexpr uint32_t kStreamsAll = kStreamPosition | kStreamNormal | kStreamTangent | kStreamUv;

// LFDPR_SHADE_WORK_BUFFER: LfdprVisibilityShadeCountersGpu, then the dispatches, then groupTiles.
constexpr GLintptr kDispatchOffset = sizeof(LfdprVisibilityShadeCountersGpu);
// Points the tie queue holds (lfdpr_visibility_splat.comp queueTies), per tile chunk and in
// all: 8 bytes each, 32-512 KiB. Ties are rare but for coincident surfaces; points past it
// (a mesh drawn twice in place) have their chunks repaired instead.
constexpr uint32_t kTiePointsPerChunk = 8, kTieCapacityMin = 4096, kTieCapacityMax = 1u << 16;

} // namespace

std::vector<uint32_t> lfdprMaterialGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials)
{
    const uint32_t shared = LfdprConstants::get().maxShadeGroups - 1; // dispatch slots for textured materials
    std::vector<uint32_t> groups(scene.cpu().materials.size() + 1, 0u); // + the default material, stored last
    for (size_t i = 0; i < texturedMaterials.size(); ++i)
        groups[scene.gpuMaterialIndex(texturedMaterials[i])] = 1u + uint32_t(i % shared);
    return groups;
}

std::vector<LfdprShadeGroup> lfdprShadeGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials)
{
    std::vector<LfdprShadeGroup> groups{{kNone, scene.gpuMaterialIndex(kNone), 0u}};
    const std::vector<Material>& materials = scene.cpu().materials;
    for (const int32_t m : texturedMaterials)
        groups.push_back({m, scene.gpuMaterialIndex(m), materialTextureFlags(materials[size_t(m)])});
    return groups;
}

std::vector<std::string> lfdprShadeDefines(std::vector<std::string> base, uint32_t textureMask, uint32_t streams,
                                           bool taps)
{
    char text[48];
    std::snprintf(text, sizeof(text), "LFD_TEXTURE_MASK 0x%Xu", textureMask);
    base.emplace_back(text);
    std::snprintf(text, sizeof(text), "LFD_STREAMS 0x%Xu", streams);
    base.emplace_back(text);
    if (taps)
        base.emplace_back("LFDPR_ANISO_TAPS 1");
    return base;
}

LfdprVisibilityShading::LfdprVisibilityShading(bool int64, bool gpuWork, bool hardwareAniso, uint32_t testIndexRaces,
                                               bool countWork, bool direct)
    : int64_(int64), direct_(direct), hardwareAniso_(hardwareAniso), defines_(atomicsDefines(int64)),
      trilinear_(gl::createSampler())
{
    // As GpuScene's textures without anisotropy: trilinear, glTF's default REPEAT.
    glSamplerParameteri(trilinear_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glSamplerParameteri(trilinear_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(trilinear_, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(trilinear_, GL_TEXTURE_WRAP_T, GL_REPEAT);
    if (gpuWork)
        defines_.emplace_back("LFDPR_WORK_GPU 1");
    if (countWork) // the splat's and the shading's work counters (lfdpr_work_counters.glsl)
        defines_.emplace_back("LFDPR_COUNT_WORK 1");
    auto build = [&](const char* shader, std::vector<std::string> extra) {
        std::vector<std::string> defines = defines_;
        defines.insert(defines.end(), extra.begin(), extra.end());
        return gl::Program(gl::buildProgram({{GL_COMPUTE_SHADER, shader}}, defines));
    };
    // A shader error thrown below leaves nothing behind: the programs built so far are
    // owned by their handles.
    std::vector<std::string> splatDefines;
    // The test hook lives here, not in the shader: every n-th point also stores its record
    // unconditionally, as a lost race would, so tests drive the repair through both paths.
    if (!int64 && testIndexRaces > 0)
        splatDefines.push_back("LFDPR_AFTER_INDEX_WRITE(index, pixel, record) if ((index) % " +
                               std::to_string(testIndexRaces) + "u == 0u) viewIndex[pixel] = (record)");
    if (direct)
        splatDefines.push_back("LFDPR_DIRECT 1");
    splatProgram_ = build("lfdpr_visibility_splat.comp", splatDefines);
    if (!int64 && direct) // the direct splat's record pass runs every frame (lfdpr_direct_fanout.glsl)
        indexProgram_ = build("lfdpr_visibility_splat.comp", {"LFDPR_INDEX_PASS 1", "LFDPR_DIRECT 1"});
    else if (!int64)
        indexProgram_ = build("lfdpr_visibility_splat.comp", {"LFDPR_INDEX_PASS 1"});
    if (!int64 && !direct && gpuWork) // lfdpr_visibility_splat.comp noteTie: the GPU work shape's
        tieProgram_ = build("lfdpr_visibility_splat.comp", {"LFDPR_INDEX_PASS 1", "LFDPR_TIE_PASS 1"});
    if (gpuWork) // lfdpr_visibility_clear.comp says why a GPU clears in a shader
        clearProgram_ = build("lfdpr_visibility_clear.comp", {});
    listProgram_ = build("lfdpr_visibility_shade_list.comp", {});
    if (!int64)
        listRepairProgram_ = build("lfdpr_visibility_shade_list.comp", {"LFDPR_REPAIR_LIST 1"});
    if (!int64) {
        repairDispatchProgram_ = build("lfdpr_visibility_repair_dispatch.comp", {});
        repair_ = gl::createBuffer(LfdprConstants::get().repairBytes);
    }
    // The untextured group's program is always needed; built now (for a scene with every
    // stream) so a shader error surfaces at construction, not in the middle of a frame.
    shadeProgram(0u, kStreamsAll, false);
}

LfdprVisibilityShading::~LfdprVisibilityShading() = default;

unsigned LfdprVisibilityShading::shadeProgram(uint32_t textureMask, uint32_t streams, bool taps)
{
    const uint64_t key = uint64_t(textureMask) << 33 | uint64_t(streams) << 1 | (taps ? 1u : 0u);
    if (const auto it = shadePrograms_.find(key); it != shadePrograms_.end())
        return it->second.get();
    gl::Program program(gl::buildProgram({{GL_COMPUTE_SHADER, "lfdpr_visibility_shade.comp"}},
                                         lfdprShadeDefines(defines_, textureMask, streams, taps)));
    const unsigned name = program.get();
    shadePrograms_[key] = std::move(program);
    return name;
}

void LfdprVisibilityShading::resize(uint32_t viewCount, uint32_t width, uint32_t height)
{
    if (viewCount == views_ && width == width_ && height == height_ && depth_)
        return;
    views_ = viewCount;
    width_ = width;
    height_ = height;
    const LfdprConstants& k = LfdprConstants::get();
    tilesX_ = divideUp(width, k.shadeTile);
    tilesY_ = divideUp(height, k.shadeTile);
    chunks_ = divideUp(viewCount, k.viewChunk);
    entryCount_ = tilesX_ * tilesY_ * chunks_; // lfdShadeEntryCount
    const size_t pixels = std::max<size_t>(size_t(viewCount) * width * height, 1);
    depth_ = gl::createBuffer(pixels * (int64_ ? 8 : 4));
    index_ = int64_ ? gl::Buffer() : gl::createBuffer(pixels * 4);
    // The shading pass reads the words through buffer textures
    // (lfdpr_pixel_access.glsl).
    auto texels = [](const gl::Buffer& buffer, GLenum format) {
        gl::Texture texture = gl::createTexture(GL_TEXTURE_BUFFER);
        if (buffer)
            glTextureBuffer(texture, format, buffer);
        return texture;
    };
    depthTexels_ = texels(depth_, int64_ ? GL_RG32UI : GL_R32UI);
    indexTexels_ = texels(index_, GL_R32UI);
    shadeWorkBytes_ = 0; // the tile lists depend on the tile count: sized again
    chunkMaskBytes_ = 0;
}

size_t LfdprVisibilityShading::viewBufferBytes() const { return size_t(views_) * width_ * height_ * 8; }

size_t LfdprVisibilityShading::shadeWorkBytes() const {
    return shadeWorkBytes_ + chunkMaskBytes_;
}

size_t LfdprVisibilityShading::repairCountOffset() { return offsetof(LfdprVisibilityRepairGpu, indexPass) + 12; }

size_t LfdprVisibilityShading::tiePointsOffset() { return offsetof(LfdprVisibilityShadeCountersGpu, tieDispatch) + 12; }

void LfdprVisibilityShading::beginFrame(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials,
                                        ViewTargets& targets)
{
    // The shading groups (the splat marks where each group's points land), then every
    // clear of the frame: the marks, the view words (all ones = empty: a depth key beyond
    // every depth), the shading's dispatches and the views' background. No barrier: the
    // caller puts one after its own clears.
    updateGroups(scene, texturedMaterials);
    const GLuint zero = 0, ones = 0xFFFFFFFFu;
    glClearNamedBufferData(chunkMasks_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    clearShadeDispatches(true);
    if (clearProgram_) {
        clearViews(targets);
        return;
    }
    glClearNamedBufferData(depth_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    if (index_)
        glClearNamedBufferData(index_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
    glClearTexImage(targets.colorArray(), 0, GL_RGBA, GL_FLOAT, kBackground);
}

// The GPU work shape's clear of the view words and colours: one dispatch
// (lfdpr_visibility_clear.comp), an invocation per view pixel.
void LfdprVisibilityShading::clearViews(ViewTargets& targets) const
{
    const LfdprConstants& k = LfdprConstants::get();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewDepth, depth_);
    if (index_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewWinner, index_);
    glBindImageTexture(k.imageViews, targets.colorArray(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glProgramUniform4fv(clearProgram_, k.locClearBackground, 1, kBackground);
    glUseProgram(clearProgram_);
    glDispatchCompute(divideUp(width_, k.clearGroupX), divideUp(height_, k.clearGroupY), views_);
    glUseProgram(0);
}

// The shading counters and each group's indirect dispatch: (0, 1, 0) workgroups, entry
// count 0 (lfdpr_visibility_shade_list.comp keeps x and y as maxima and sets z with the first entry).
void LfdprVisibilityShading::clearShadeDispatches(bool frameStart) const
{
    const GLuint empty[4] = {0u, 1u, 0u, 0u};
    glClearNamedBufferSubData(shadeWork_, GL_RGBA32UI, kDispatchOffset, GLsizeiptr(groupCount_) * 16,
                              GL_RGBA_INTEGER, GL_UNSIGNED_INT, empty);
    LfdprVisibilityShadeCountersGpu counters{};
    counters.repairBase = repairBase_;
    counters.repairCapacity = repairCapacity_;
    counters.tieBase = tieBase_;
    counters.tieDispatch = {0u, 1u, 1u, 0u}; // no workgroups until a point is queued
    counters.tieCapacity = tieCapacity_;
    glNamedBufferSubData(shadeWork_, 0, frameStart ? sizeof(counters) : offsetof(LfdprVisibilityShadeCountersGpu, tieDispatch),
                         &counters);
}

void LfdprVisibilityShading::splat(unsigned counters)
{
    const LfdprConstants& k = LfdprConstants::get();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboChunkMasks, chunkMasks_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewDepth, depth_);
    if (index_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboViewWinner, index_);
    // The 32-bit views path's splat queues the points that met a depth tie there.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboShadeWork, shadeWork_);
    // The 32-bit path's index pass runs only to repair, in shade(); the direct splat's
    // every frame (lfdpr_direct_fanout.glsl says why); the tie pass over the queued points
    // (zero workgroups when none met a tie) before the shading reads the records.
    splatPass(splatProgram_, counters, offsetof(LfdprVisibilityCountersGpu, splatGroupsX));
    if (direct_ && !int64_)
        splatPass(indexProgram_, counters, offsetof(LfdprVisibilityCountersGpu, splatGroupsX));
    else if (tieProgram_)
        splatPass(tieProgram_, shadeWork_, offsetof(LfdprVisibilityShadeCountersGpu, tieDispatch));
}

void LfdprVisibilityShading::splatPass(unsigned program, unsigned arguments, size_t offset) const
{
    glUseProgram(program);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, arguments);
    glDispatchComputeIndirect(GLintptr(offset));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    // Command: the tie pass's dispatch is the splat's writes.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    glUseProgram(0);
}

void LfdprVisibilityShading::updateGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials)
{
    const LfdprConstants& k = LfdprConstants::get();

    // Step 1: the groups (in lfdprMaterialGroups' order), each with the textures its
    // program samples.
    groups_ = lfdprShadeGroups(scene, texturedMaterials);
    groupCount_ = uint32_t(std::min<size_t>(groups_.size(), k.maxShadeGroups));

    // Step 2: the buffers (grown, never shrunk, so a steady scene allocates nothing).
    // The repair list after the groups' lists: one entry per repaired pixel (more repairs
    // than it holds shade every marked chunk again instead).
    repairBase_ = groupCount_ * entryCount_ * k.shadeEntryWords;
    // A repair entry lists its chunk for every group, so at most entryCount_ of them keep
    // each group's list within its room.
    repairCapacity_ = std::min<uint32_t>(entryCount_, 65535u);
    // Then the tie queue (the tie pass's path only): two words per point.
    tieBase_ = repairBase_ + repairCapacity_;
    tieCapacity_ = !tieProgram_           ? 0u
                   : testTieCapacity_ > 0 ? testTieCapacity_
                                          : std::clamp(entryCount_ * kTiePointsPerChunk, kTieCapacityMin, kTieCapacityMax);
    const size_t workBytes = kDispatchOffset + size_t(k.maxShadeGroups) * 16 +
                             (size_t(tieBase_) + 2 * size_t(tieCapacity_)) * 4;
    if (workBytes > shadeWorkBytes_) {
        shadeWork_ = gl::createBuffer(workBytes, GL_DYNAMIC_STORAGE_BIT);
        shadeWorkBytes_ = workBytes;
    }
    const size_t maskBytes = size_t(groupCount_) * entryCount_ * 2 * sizeof(uint32_t);
    if (maskBytes > chunkMaskBytes_) {
        chunkMasks_ = gl::createBuffer(maskBytes);
        chunkMaskBytes_ = maskBytes;
    }
}

void LfdprVisibilityShading::listAndShade(const GpuScene& scene, uint32_t pass)
{
    const LfdprConstants& k = LfdprConstants::get();

    // Step 1: each group's list of tile chunks from the splat's marks, and with it the
    // group's indirect dispatch (lfdpr_visibility_shade_list.comp). Pass 2 (the repair): emptied
    // again, then the repair list's chunks when it held them all, else all again
    // (lfdpr_visibility_repair_dispatch.comp sized both, the one not needed to zero workgroups).
    for (const unsigned list : {listProgram_.get(), listRepairProgram_.get()})
        if (list) // the repair list exists on the 32-bit path only
            glProgramUniform1ui(list, k.locShadeGroups, groupCount_);
    if (pass == 0) {
        const uint32_t workgroups = divideUp(entryCount_ * groupCount_, 64);
        const uint32_t width = std::min<uint32_t>(workgroups, k.shadeDispatchWidth);
        glUseProgram(listProgram_);
        glDispatchCompute(width, divideUp(workgroups, width), 1); // lfdpr_visibility_shade_list.comp's (x, y) order
    } else {
        // note: the barrier orders the first pass's shader writes to these words before the
        // clear; a clear itself is ordered with the dispatches after it.
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        clearShadeDispatches(false);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, repair_);
        glUseProgram(listRepairProgram_);
        glDispatchComputeIndirect(offsetof(LfdprVisibilityRepairGpu, listRepair));
        glUseProgram(listProgram_);
        glDispatchComputeIndirect(offsetof(LfdprVisibilityRepairGpu, listAll));
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    // Step 2: one dispatch per group over its tile chunks, its textures bound. Each pixel
    // is shaded only by its winner's group, so no barrier is needed between them.
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, shadeWork_);
    const uint32_t shared = k.maxShadeGroups - 1;
    constexpr GLsizei kMaterialUnits = 5; // base colour, metallic-roughness, normal, occlusion, emissive
    GLuint samplers[kMaterialUnits];
    // The shader's taps only when there is anisotropy to filter: at --aniso 1 every filter is
    // the one trilinear textureGrad, and the taps' code cost llvmpipe 9-10 ms of the gallery's
    // shading even untaken (its branches run under a lane mask).
    const bool taps = !hardwareAniso_ && scene.maxAnisotropy() > 1.0f;
    std::fill(std::begin(samplers), std::end(samplers), taps ? GLuint(trilinear_) : 0u);
    for (size_t g = 0; g < groups_.size(); ++g) {
        const Group& group = groups_[g];
        const uint32_t slot = g == 0 ? 0u : 1u + uint32_t((g - 1) % shared);
        const GLuint program = shadeProgram(group.textureMask, scene.cpu().vertices.mask(), taps);
        glUseProgram(program);
        if (!int64_) // only the 32-bit path's programs have the pass
            glProgramUniform1ui(program, k.locPass, pass);
        glProgramUniform1ui(program, k.locShadeGroup, slot);
        glProgramUniform1ui(program, k.locShadeMaterial, group.gpuMaterial);
        scene.bindMaterialTextures(group.material);
        glBindSamplers(bindings::kUnitBaseColor, kMaterialUnits, samplers);
        glDispatchComputeIndirect(kDispatchOffset + GLintptr(slot) * 16);
        ++dispatches_;
    }
    glBindSamplers(bindings::kUnitBaseColor, kMaterialUnits, nullptr);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glUseProgram(0);
}

// The 32-bit path's repair after the first shading pass: its dispatches sized on the GPU
// from the pass's count of raced pixels, then the index pass over every point and the
// chunks of those pixels shaded again (all with zero workgroups when nothing raced).
void LfdprVisibilityShading::repair(const GpuScene& scene)
{
    const LfdprConstants& k = LfdprConstants::get();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboRepair, repair_);
    glUseProgram(repairDispatchProgram_);
    glProgramUniform1ui(repairDispatchProgram_, k.locShadeGroups, groupCount_);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    splatPass(indexProgram_, repair_, offsetof(LfdprVisibilityRepairGpu, indexPass));
    listAndShade(scene, 2);
}

void LfdprVisibilityShading::shade(const GpuScene& scene, ViewTargets& targets)
{
    const LfdprConstants& k = LfdprConstants::get();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k.ssboShadeWork, shadeWork_);
    glBindImageTexture(k.imageViews, targets.colorArray(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glBindTextureUnit(k.unitViewDepth, depthTexels_);
    glBindTextureUnit(k.unitViewIndex, index_ ? indexTexels_.get() : 0u);
    dispatches_ = 0;
    listAndShade(scene, 0);
    if (!int64_)
        repair(scene);
    // The EIA pass samples the array, read-back copies it; the renderer copies counts.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

} // namespace lfd::player
