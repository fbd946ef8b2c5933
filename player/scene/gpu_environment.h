// The scene's environment on the GPU, for image-based lighting (pbr_shading.glsl): the
// GGX-prefiltered specular cube (mip level l holds roughness l / (levels - 1)), the
// split-sum BRDF table and the irradiance's SH9 coefficients. The CPU side that makes them
// is player/lighting/ (environment_prefilter.h); this class only uploads and binds.
#pragma once

#include "gl_handles.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace lfd::player {

// What GpuEnvironment uploads, as lfd_lighting produces it.
struct EnvironmentMaps {
    // Specular cube: levels[l] holds 6 faces of (faceSize >> l)^2 texels each, faces in GL
    // order (+X, -X, +Y, -Y, +Z, -Z), rows from t = 0, linear radiance.
    uint32_t faceSize = 0;
    std::vector<std::vector<glm::vec3>> levels;
    // E(n) / pi as SH9 (pbr_shading.glsl's lfdIrradianceSh evaluates them).
    std::array<glm::vec3, 9> irradianceSh{};
    // The BRDF table: brdfSize^2 texels (A, B, C), x = n.v and y = roughness at texel
    // centres, row 0 at roughness 0.
    uint32_t brdfSize = 0;
    std::vector<glm::vec3> brdfTable;
};

class GpuEnvironment {
public:
    // Needs a current GL context; throws gl::GlError on inconsistent maps.
    explicit GpuEnvironment(const EnvironmentMaps& maps);

    // Binds the cube and the table to LFD_UNIT_ENVIRONMENT / LFD_UNIT_BRDF_TABLE.
    void bind() const;
    const std::array<glm::vec3, 9>& irradianceSh() const { return sh_; }
    float maxLevel() const { return maxLevel_; } // the cube's last level (roughness 1)
    size_t gpuBytes() const { return gpuBytes_; }

private:
    gl::Texture cube_, brdf_;
    std::array<glm::vec3, 9> sh_{};
    float maxLevel_ = 0.0f;
    size_t gpuBytes_ = 0;
};

} // namespace lfd::player
