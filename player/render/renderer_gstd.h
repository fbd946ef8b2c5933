// gstd: the slow gold standard every other renderer's quality is measured against (Gavane
// & Watson 2024, section 5, "GStd"). Per output view it renders two sub-views at their
// exact angles (2N cameras), each at `factor` times the view resolution with mvr's PBR
// shading and anisotropic texture filtering, and reconstructs every output pixel with a
// Gaussian filter integrated with 32 seeded random samples, averaged over the two
// sub-views in linear light. The result lands in the same ViewTargets as every other
// method, so the EIA is built the same way.
#pragma once

#include "renderer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lfd::player {

struct GstdOptions {
    // Spatial supersampling factor: a 480x360 view renders at 1920x1440 with the default
    // (the paper renders 4K views; 4 keeps a small scene within minutes on a CPU).
    uint32_t factor = 4;
    // Gaussian samples per output pixel and sub-view (the paper's 32).
    uint32_t samples = 32;
    // Seed of the sample offsets: the same seed gives bit-identical views.
    uint64_t seed = 0x9e3779b97f4a7c15ull;
    // Gaussian reconstruction filter: support diameter in view pixels (the paper's
    // 2.25, section 4: its spatial reconstruction width), truncated at 3 sigma, so
    // sigma = diameter / 6 = 0.375 view pixels.
    double filterDiameter = 2.25;
    // Largest anisotropy of the scene textures' filtering (clamped to the driver's; 1 =
    // trilinear only, for ablation and tests).
    float maxAnisotropy = 16.0f;
    // Sub-views per output view ("twice the views at their exact angles").
    static constexpr uint32_t kSubViews = 2;
};

// Throws std::invalid_argument for factor 0, samples 0, a non-positive diameter or an
// anisotropy below 1.
void validateGstdOptions(const GstdOptions& options);

// The reconstruction sample offsets (view pixels, relative to the pixel centre), one set of
// options.samples per sub-view: 2D Gaussian of sigma = diameter / 6 by Box-Muller from a
// splitmix64 stream seeded with options.seed, resampled where it falls outside the
// support. Pure CPU and platform-independent (no std::normal_distribution), so a seed
// means the same offsets everywhere.
std::vector<glm::vec2> gstdSampleOffsets(const GstdOptions& options);

// Everything that changes gstd's pixels, as text (for the disk cache key).
std::string gstdSettingsKey(const GstdOptions& options);

std::unique_ptr<Renderer> createGstdRenderer(const GstdOptions& options = {});

} // namespace lfd::player
