// The direct subpixel splat's panel-side buffers and passes (LfdprOptions::Direct::Nearest,
// renderer lfdpr-direct; docs/player/direct-splat.md). The visibility pipeline's points and
// splat stay as they are, compiled with LFDPR_DIRECT so each sample is fanned out to the
// panel subpixels that show its view pixel (shaders/lfdpr_direct_fanout.glsl, through the
// table of lfdpr_direct_fanout.h); this class owns what replaces the views:
//   * the inverse map (uploaded once per profile and view size) and the S = 3 W H
//     64-bit subpixel words, cleared every frame as the views path clears its view words;
//   * the shading: per shading group one dispatch over every panel pixel, each subpixel the
//     group won shaded for its own channel (shaders/lfdpr_direct_shade.comp) into R8 planes;
//   * the pack of those planes into the RGBA8 panel (shaders/lfdpr_direct_pack.comp).
#pragma once

#include "gl_handles.h"
#include "lfdpr_visibility_shading.h"

#include "lfd/display_profile.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace lfd::player {

class GpuScene;

class LfdprDirectPanel {
public:
    // defines: the visibility pipeline's program defines (atomics, work shape, counters);
    // hardwareAniso as LfdprVisibilityShading's.
    // int64: 64-bit words (GL_NV_shader_atomic_int64), else a key and a record per subpixel.
    // exactRay: LfdprOptions::Direct::ExactRay (LFDPR_DIRECT_EXACT in the shading).
    LfdprDirectPanel(std::vector<std::string> defines, bool int64, bool hardwareAniso, bool exactRay);

    // Builds the inverse map and the buffers for `profile` (panel, mapping, views) when
    // they changed; the CPU work of a new profile happens here, once.
    void resize(const DisplayProfile& profile);
    // The frame's clears: every subpixel word empty, the channel planes to the background.
    // No barrier: the caller puts one after all its clears.
    void beginFrame(const GpuScene& scene, const std::vector<int32_t>& texturedMaterials);
    // Binds the map and the words for the splat (LFDPR_DIRECT).
    void bindForSplat() const;
    // Shades every won subpixel into its channel plane.
    void shade(const GpuScene& scene);
    // The RGBA8 panel image from the planes, into `eiaTexture` (panel size).
    void writePanel(unsigned eiaTexture) const;

    // Bytes the frame's clears write (words and planes) and the buffers held (map, words,
    // planes).
    size_t clearedBytes() const { return subpixels_ * 9; }
    size_t bufferBytes() const { return mapBytes_ + subpixels_ * 9; } // 8 B of words + 1 B of plane
    uint32_t lastShadingDispatches() const { return dispatches_; }

private:
    using Group = LfdprShadeGroup;
    unsigned shadeProgram(uint32_t textureMask, uint32_t streams, bool taps);
    void setPhaseUniforms(unsigned program) const;

    std::vector<std::string> defines_;
    bool int64_, hardwareAniso_, exactRay_;
    gl::Program packProgram_;
    std::map<uint64_t, gl::Program> shadePrograms_; // by LFD_TEXTURE_MASK << 33 | LFD_STREAMS << 1 | taps
    gl::Sampler trilinear_; // as LfdprVisibilityShading's: the shader's anisotropic taps
    DisplayProfile profile_;
    bool sized_ = false;
    gl::Buffer offsets_, subpixelList_, words_, index_; // index_: the 32-bit path's records
    gl::Texture wordTexels_, planes_;
    size_t subpixels_ = 0, mapBytes_ = 0;
    std::vector<Group> groups_;
    uint32_t dispatches_ = 0;
};

} // namespace lfd::player
