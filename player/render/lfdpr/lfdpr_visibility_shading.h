// LFDPR visibility splatting and per-pixel shading (the visibility pipeline;
// shaders/lfdpr_visibility_splat.comp, lfdpr_visibility_shade_list.comp, lfdpr_visibility_shade.comp,
// lfdpr_visibility_repair_dispatch.comp): the per-view depth and winner (triangle record) buffers for
// either atomics path, the splat pass(es), which also mark per shading group the tile
// chunks (a tile position over a run of views) and views its points wrote, and shading in
// two steps - list each group's marked chunks (which sizes the group's indirect dispatch
// on the GPU), then one indirect dispatch per group over its chunks only, with a program
// compiled for that group's textures.
#pragma once

#include "gl_handles.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace lfd::player {

class GpuScene;
class ViewTargets;

// The shading group of every GPU material (index: GpuScene::gpuMaterialIndex): 0 for the
// untextured ones, then 1 + i for textured material texturedMaterials[i] (scene material
// indices), shared modulo the LFDPR_MAX_SHADE_GROUPS - 1 textured slots. The draw table
// carries each draw's group (LfdprVisibilityDrawGpu::group), which the splat marks by and the
// shading checks a pixel's winner against.
std::vector<uint32_t> lfdprMaterialGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials);

// One shading dispatch's material: group 0 is every untextured material, then one per
// textured material, in lfdprMaterialGroups' order (the draws carry each one's slot).
struct LfdprShadeGroup {
    int32_t material;     // kNone for group 0 (untextured materials)
    uint32_t gpuMaterial; // u_shadeMaterial
    uint32_t textureMask; // LFD_TEXTURE_MASK of its program
};
std::vector<LfdprShadeGroup> lfdprShadeGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials);

// The defines of a shading program: `base` (the atomics path's), then the textures it
// samples, the vertex streams it reads and whether it takes anisotropic taps.
std::vector<std::string> lfdprShadeDefines(std::vector<std::string> base, uint32_t textureMask, uint32_t streams,
                                           bool taps);

class LfdprVisibilityShading {
public:
    // int64: one 64-bit atomicMin pass (GL_NV_shader_atomic_int64; its shaders are only
    // compiled then); otherwise a depth pass and a record (index) pass over 32-bit words.
    // gpuWork: LFDPR_WORK_GPU for every program (lfdpr_work_shape.glsl).
    // hardwareAniso: LfdprOptions::AnisoFilter::Hardware (the shading samples through the
    // textures' own state; else the trilinear sampler and the shader's taps).
    // testIndexRaces: LfdprOptions::testIndexRaces (32-bit path only).
    // countWork: LfdprOptions::countWork (LFDPR_COUNT_WORK: the splat and the shading count
    // their work into the LfdprVisibilityCountersGpu block, lfdpr_work_counters.glsl).
    // direct: LfdprOptions::Direct::Nearest - the splat is compiled with LFDPR_DIRECT (its
    // samples fanned out to panel subpixels, lfdpr_direct_fanout.glsl; on the 32-bit path
    // followed by its record pass every frame); the caller then uses LfdprDirectPanel
    // instead of resize(), beginFrame() and shade().
    LfdprVisibilityShading(bool int64, bool gpuWork, bool hardwareAniso, uint32_t testIndexRaces = 0,
                           bool countWork = false, bool direct = false);
    ~LfdprVisibilityShading();
    LfdprVisibilityShading(const LfdprVisibilityShading&) = delete;
    LfdprVisibilityShading& operator=(const LfdprVisibilityShading&) = delete;
    // LfdprOptions::testTieCapacity: the tie queue's points (0: sized with the views).
    void setTestTieCapacity(uint32_t points) { testTieCapacity_ = points; }

    bool int64() const { return int64_; }
    bool hardwareAniso() const { return hardwareAniso_; }
    // Every program's defines (atomics path, work shape, counters), for LfdprDirectPanel's.
    const std::vector<std::string>& programDefines() const { return defines_; }
    void resize(uint32_t viewCount, uint32_t width, uint32_t height);
    // 8 bytes per view pixel (depth + the winner's record, or the 64-bit word).
    size_t viewBufferBytes() const;
    // The shading work: per group a dispatch, a list of tile chunks and the splat's marks.
    size_t shadeWorkBytes() const;
    // Bytes beginFrame clears: the splat's marks, the shading's dispatches, the view words
    // (8 per view pixel) and the RGBA8 view colours.
    size_t clearedBytes() const
    {
        return chunkMaskBytes_ + size_t(groupCount_) * 16 + viewBufferBytes() + size_t(views_) * width_ * height_ * 4;
    }

    // Every clear of a frame, before point generation: the splat's marks, the view words,
    // the shading's dispatches and the views' background (targets). Shading groups: 0 =
    // every untextured material, then one per textured material the scene draws with
    // (`texturedMaterials`, scene material indices). On the GPU work shape the view words
    // and colours are cleared by a dispatch (lfdpr_visibility_clear.comp), else by clear
    // calls. No barrier: the caller puts one after all its clears.
    void beginFrame(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials, ViewTargets& targets);
    // Splats the points into every view (one pass on either path; an indirect dispatch from
    // `counters`, the LfdprVisibilityCountersGpu block whose splat arguments point generation
    // kept), marking for each shading group the tile chunks and views its points wrote. The
    // caller has bound the scene, the LFDPR buffers and the constants.
    void splat(unsigned counters);
    // Shades every visible pixel into targets and writes the background elsewhere, one
    // dispatch per group over the chunks splat() marked for it. On the 32-bit path, pixels
    // whose record lost a race to a nearer point are repaired - the index pass over every
    // point (its count from the bound LfdprVisibilityCountersGpu block), then their chunks shaded
    // again - with dispatches the GPU sizes from its own count (lfdpr_visibility_repair_dispatch.comp),
    // so nothing is read back; the count of repaired pixels is at repairCountOffset() in
    // repairBuffer().
    void shade(const GpuScene& scene, ViewTargets& targets);
    // 32-bit path: the LfdprVisibilityRepairGpu block (0 on the 64-bit path) and where in it the
    // number of pixels repaired by the last shade() is.
    unsigned repairBuffer() const { return repair_.get(); }
    static size_t repairCountOffset();
    // Whether the splat queues the points that meet a depth tie for a tie pass (the 32-bit
    // views path on the GPU work shape); then the shading work buffer holds, at
    // tiePointsOffset(), the number of points the last splat queued (lfdpr_visibility_splat.comp
    // queueTies).
    bool tiePass() const { return bool(tieProgram_); }
    unsigned shadeWorkBuffer() const { return shadeWork_.get(); }
    static size_t tiePointsOffset();
    // Shading dispatches of the last shade() (one per group and pass).
    uint32_t lastShadingDispatches() const { return dispatches_; }

private:
    using Group = LfdprShadeGroup;
    void splatPass(unsigned program, unsigned arguments, size_t offset) const;
    // frameStart: also the tie queue's counters (the repair's pass 2 leaves them for the
    // read-back).
    void clearShadeDispatches(bool frameStart) const;
    void clearViews(ViewTargets& targets) const;
    void updateGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials);
    // pass 0: every marked chunk; pass 2: after a repair, the chunks of the repaired pixels
    // when the repair list held them all, else every marked chunk again (both lists are
    // dispatched indirectly, the one not needed with zero workgroups).
    void listAndShade(const GpuScene& scene, uint32_t pass);
    void repair(const GpuScene& scene);
    // taps: LFDPR_ANISO_TAPS (the shader's anisotropic taps), else one textureGrad.
    unsigned shadeProgram(uint32_t textureMask, uint32_t streams, bool taps);

    bool int64_;
    bool direct_; // LFDPR_DIRECT splat (LfdprDirectPanel holds its words)
    bool hardwareAniso_;
    std::vector<std::string> defines_; // every program's: atomics path, work shape
    gl::Program splatProgram_, indexProgram_; // 32-bit path: the depth pass, the index pass
    gl::Program tieProgram_; // 32-bit views path: the index pass over the points queued at a tie
    gl::Program listProgram_, listRepairProgram_; // lfdpr_visibility_shade_list.comp: marks, repair list
    gl::Program repairDispatchProgram_;
    gl::Program clearProgram_; // lfdpr_visibility_clear.comp (the GPU work shape only)
    // Trilinear, no anisotropy: bound to the material units while shading with the taps, so
    // the textures' own --aniso state does not filter lfdpr's shader taps a second time (the
    // taps are the anisotropic filter; lfdpr_visibility_shade.comp, lfdSampleFootprint).
    // Not bound otherwise (hardwareAniso_, or --aniso 1): the textures' own state filters.
    gl::Sampler trilinear_;
    std::map<uint64_t, gl::Program> shadePrograms_; // by LFD_TEXTURE_MASK << 33 | LFD_STREAMS << 1 | taps
    gl::Buffer depth_, index_; // 64-bit path: depth_ holds the words
    gl::Texture depthTexels_, indexTexels_; // the same, read as buffer textures
    gl::Buffer shadeWork_, chunkMasks_, repair_;
    size_t shadeWorkBytes_ = 0, chunkMaskBytes_ = 0;
    std::vector<Group> groups_;
    uint32_t groupCount_ = 0;            // dispatch slots in use (<= LFDPR_MAX_SHADE_GROUPS)
    uint32_t repairBase_ = 0, repairCapacity_ = 0; // the repair list in the shade work buffer
    uint32_t tieBase_ = 0; // after it, the tie queue (lfdpr_visibility_splat.comp queueTies)
    uint32_t tieCapacity_ = 0, testTieCapacity_ = 0; // points it holds (0 without a tie pass)
    uint32_t views_ = 0, width_ = 0, height_ = 0;
    uint32_t tilesX_ = 0, tilesY_ = 0, chunks_ = 0, entryCount_ = 0; // tile chunks (lfdpr_shade_chunks.glsl)
    uint32_t dispatches_ = 0;
};

} // namespace lfd::player
