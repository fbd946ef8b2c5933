// EIA construction (formats/display_profiles.md section 2): one compute pass over the panel's subpixels.
// For each subpixel (column k = 3x + i, row l) the view phase comes from the profile's
// SubpixelMapping; nearest-view mode takes that subpixel's channel from view
// floor(phase * N), sampled at the subpixel's screen position (each view covers the whole
// screen). The reconstruction modes of the paper's section 4 (`--aa`) filter around that
// sample with a Gaussian - spatial (2.25 view-pixel diameter), view (angular, a support of
// 2 view intervals) or both - integrated with 8 seeded random Gaussian samples, the same
// offsets for every subpixel, averaged in linear light.
#pragma once

#include "eia_bindings_gpu.h"
#include "gl_handles.h"

#include "lfd/display_profile.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::player {

class ViewTargets;
class GpuTimer;

// Values are EIA_MODE_* of shaders/eia_bindings.glsl (static_assert in eia_builder.cpp).
enum class Reconstruction : uint32_t { None = 0, Spatial = 1, View = 2, ViewSpatial = 3 };
// "none", "spatial", "view", "view-spatial"; throws invalid_argument naming the choices.
Reconstruction parseReconstruction(const std::string& name);
std::string reconstructionName(Reconstruction mode);
std::vector<std::string> reconstructionNames(); // in enum order (the window's C key cycle)

// The reconstruction filters (paper section 4).
struct ReconstructionFilter {
    static constexpr uint32_t kSamples = eia_bindings::kSamples;
    static constexpr double kSpatialDiameter = 2.25; // view pixels, = 6 sigma
    static constexpr double kViewSupport = 2.0;      // view intervals, = 6 sigma
    static constexpr uint64_t kDefaultSeed = 0x5eed'0e1a'0000'0001ull;
};

// The mode's kSamples filter offsets: x, y in view pixels (image order, +y down), z in view
// intervals; components the mode does not filter are 0. Gaussian by Box-Muller over a
// splitmix64 stream seeded with `seed`, resampled outside the 3-sigma support; pure CPU and
// platform-independent, so the GPU pass and the CPU reference use the same offsets.
std::vector<glm::vec3> reconstructionSamples(Reconstruction mode,
                                             uint64_t seed = ReconstructionFilter::kDefaultSeed);

class EiaBuilder {
public:
    // Panel-size RGBA8 output texture; `seed` picks the reconstruction samples.
    explicit EiaBuilder(const DisplayProfile& profile, uint64_t seed = ReconstructionFilter::kDefaultSeed);
    EiaBuilder(const EiaBuilder&) = delete;
    EiaBuilder& operator=(const EiaBuilder&) = delete;

    void build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer); // stage "eia"
    unsigned texture() const { return eia_.get(); }
    std::vector<uint8_t> read() const; // RGBA8, panel size, rows top to bottom
    uint64_t bytes() const;            // GPU memory of the EIA texture

private:
    DisplayProfile profile_;
    uint64_t seed_;
    gl::Texture eia_;
    gl::Sampler nearest_; // keeps the view array complete whatever its own filter state
    // One program per Reconstruction mode (EIA_MODE compiled in), built on first use.
    gl::Program programs_[4];
    unsigned program(Reconstruction mode);
};

// CPU reference of the same mapping (tests, simulated viewer): views are RGBA8 images in
// image order (row 0 = top), all of size viewWidth x viewHeight. Mode none is bit-identical
// to the GPU pass; the filtered modes use the same samples, decoding table and float
// arithmetic, and differ from it by at most one 8-bit level where the GPU fuses a
// multiply-add or rounds pow differently (eia_test states the tolerance).
std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight,
                                 Reconstruction mode = Reconstruction::None,
                                 uint64_t seed = ReconstructionFilter::kDefaultSeed);

} // namespace lfd::player
