// The scene's environment on the GPU, for image-based lighting (pbr_shading.glsl): the
// GGX-prefiltered specular cube (level 0 the mirror, level l holds GGX alpha
// 2^(l + 1 - levels), then one wide level; lighting/prefilter.h), the diffuse irradiance
// cube (E / pi), the split-sum BRDF table (A, B, C; lighting/brdf_table.h) and the lobe tap
// table of the two specular lookups (lighting/lobe_taps.h). The CPU side that makes them is
// player/lighting/; this class prefilters through it once, uploads and binds.
#pragma once

#include "gl_handles.h"

#include "brdf_table.h"
#include "environment_choice.h"
#include "lobe_taps.h"
#include "prefilter.h"

#include <cstdint>
#include <memory>
#include <string>

namespace lfd::player {

class GpuEnvironment {
public:
    // Prefilters `source` with `settings` (lfd_lighting, on every core) and uploads the
    // cubes and `table`. `key` names the source for caches (e.g. "neutral",
    // "file:<content hash>"). Needs a current GL context.
    GpuEnvironment(std::shared_ptr<const lighting::Environment> source, std::string key,
                   const lighting::PrefilterSettings& settings, const lighting::BrdfTable& table);

    // Binds the cubes and the tables to LFD_UNIT_ENVIRONMENT, LFD_UNIT_IRRADIANCE,
    // LFD_UNIT_BRDF_TABLE and LFD_UNIT_LOBE_TAPS.
    void bind() const;
    float maxLevel() const { return maxLevel_; } // the specular cube's last level: the wide one
    const std::string& key() const { return key_; }
    const lighting::PrefilterSettings& settings() const { return settings_; }
    const std::shared_ptr<const lighting::Environment>& source() const { return source_; }
    size_t gpuBytes() const { return gpuBytes_; }
    double prefilterSeconds() const { return prefilterSeconds_; }

private:
    std::shared_ptr<const lighting::Environment> source_;
    std::string key_;
    lighting::PrefilterSettings settings_;
    gl::Texture specular_, irradiance_, brdf_, lobeTaps_;
    float maxLevel_ = 0.0f;
    size_t gpuBytes_ = 0;
    double prefilterSeconds_ = 0.0;
};

// The split-sum table the shaders read (LFD_BRDF_TABLE_SIZE^2 at 2048 samples per texel:
// within 2e-4 of the exact terms, lighting/brdf_table.h), computed once per process.
const lighting::BrdfTable& shaderBrdfTable();

// The environment a tool chose (lighting::chooseEnvironment) prefiltered with the player's
// settings and uploaded; null for "none" (the constant ambient term).
std::shared_ptr<const GpuEnvironment> uploadEnvironment(const lighting::EnvironmentChoice& choice);

// The same source prefiltered with other settings (gstd's reference preset).
std::shared_ptr<const GpuEnvironment> withSettings(const GpuEnvironment& environment,
                                                   const lighting::PrefilterSettings& settings);

} // namespace lfd::player
