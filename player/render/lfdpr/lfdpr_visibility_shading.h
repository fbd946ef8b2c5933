// LFDPR visibility splatting and per-pixel shading (the visibility pipeline;
// shaders/lfdpr_visibility.comp, lfdpr_classify.comp, lfdpr_shade_dispatch.comp,
// lfdpr_shade.comp): the per-view depth and point index buffers for either atomics path,
// the splat pass(es), and shading in three steps - classify every view pixel (background,
// or the shading group of its point's material, listing each tile once per group it
// holds), size each group's dispatch on the GPU, then one indirect dispatch per group over
// its tiles only, with a program compiled for that group's textures.
#pragma once

#include "gl_handles.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace lfd::player {

class GpuScene;
class ViewTargets;

class LfdprVisibilityShading {
public:
    // int64: one 64-bit atomicMin pass (GL_NV_shader_atomic_int64; its shaders are only
    // compiled then); otherwise a depth pass and a point-index pass over 32-bit words.
    // testIndexRaces: LfdprOptions::testIndexRaces (32-bit path only).
    explicit LfdprVisibilityShading(bool int64, uint32_t testIndexRaces = 0);
    ~LfdprVisibilityShading();
    LfdprVisibilityShading(const LfdprVisibilityShading&) = delete;
    LfdprVisibilityShading& operator=(const LfdprVisibilityShading&) = delete;

    bool int64() const { return int64_; }
    void resize(uint32_t viewCount, uint32_t width, uint32_t height);
    // 8 bytes per view pixel (depth + point index) plus 4 (the pixel's shading state).
    size_t viewBufferBytes() const;
    // The shading work lists: per group a dispatch and a list of tiles.
    size_t shadeWorkBytes() const;

    // Clears the view buffers and splats `points` points into every view (one pass on
    // either path). The caller has bound the scene, the LFDPR buffers and the constants.
    void splat(uint32_t points) const;
    // Shades every visible pixel into targets and writes the background elsewhere. Shading
    // groups: 0 = every untextured material, then one per textured material the scene
    // draws with (`texturedMaterials`, scene material indices); `untexturedDrawn`: some draw
    // shades in group 0 (when only one group can occur, classification reads coverage
    // only, not each pixel's material). On the 32-bit path, pixels
    // whose point index lost a race to a nearer point are repaired - the index pass over
    // all `points`, then their classification and shading - and their number is returned
    // (0 on the 64-bit path).
    uint32_t shade(const GpuScene& scene, ViewTargets& targets, const std::vector<int32_t>& texturedMaterials,
                   bool untexturedDrawn, uint32_t points);
    // Shading dispatches of the last shade() (groups with their programs; repairs add more).
    uint32_t lastShadingDispatches() const { return dispatches_; }

private:
    struct Group {
        int32_t material;     // kNone for group 0 (untextured materials)
        uint32_t gpuMaterial; // u_shadeMaterial
        uint32_t textureMask; // LFD_TEXTURE_MASK of its program
    };
    void splatPass(uint32_t points, unsigned program) const;
    void updateGroups(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials, bool untexturedDrawn);
    // pass 0: every pixel; pass 2: the repaired pixels (`repairs` of them, listed by tile
    // when the repair list held them all).
    void classifyAndShade(const GpuScene& scene, uint32_t pass, uint32_t repairs);
    unsigned shadeProgram(uint32_t textureMask, uint32_t streams);
    // The classify program: general (-1), or for scenes where every drawn pixel shades in
    // group `onlyGroup` (LFDPR_ONLY_GROUP); `repairList`: the repair pass over the listed
    // tiles (LFDPR_REPAIR_LIST).
    unsigned classifyProgram(int32_t onlyGroup, bool repairList);

    bool int64_;
    gl::Program splatProgram_, indexProgram_; // 32-bit path: the depth pass, the index pass
    std::map<int, gl::Program> classifyPrograms_; // by onlyGroup + 1 + 3 * repairList
    gl::Program dispatchProgram_;
    std::map<uint64_t, gl::Program> shadePrograms_; // by LFD_TEXTURE_MASK << 32 | LFD_STREAMS
    gl::Buffer depth_, index_, pixelStates_; // 64-bit path: depth_ holds the words
    gl::Texture depthTexels_, indexTexels_, stateTexels_; // the same, read as buffer textures
    gl::Texture materialGroupTexels_;                     // materialGroups_ as a buffer texture
    gl::Buffer shadeWork_, materialGroups_;
    size_t shadeWorkBytes_ = 0, materialGroupsBytes_ = 0;
    std::vector<Group> groups_;
    std::vector<uint32_t> groupOfMaterial_; // per GPU material
    uint32_t groupCount_ = 0;            // dispatch slots in use (<= LFDPR_MAX_SHADE_GROUPS)
    int32_t onlyGroup_ = -1;             // the one group every drawn pixel shades in, or -1
    uint32_t repairBase_ = 0, repairCapacity_ = 0; // the repair list in the shade work buffer
    uint32_t views_ = 0, width_ = 0, height_ = 0, tileCount_ = 0;
    uint32_t tilesX_ = 0, tilesY_ = 0, chunks_ = 0, entryCount_ = 0; // tile chunks (lfdpr_shade_chunks.glsl)
    uint32_t dispatches_ = 0;
};

} // namespace lfd::player
