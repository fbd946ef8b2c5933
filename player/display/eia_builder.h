// EIA construction (formats/display_profiles.md section 2): one compute pass over the panel's subpixels.
// For each subpixel (column k = 3x + i, row l) the view phase comes from the profile's
// SubpixelMapping; nearest-view mode takes that subpixel's channel from view
// floor(phase * N), sampled at the subpixel's screen position (each view covers the whole
// screen). The reconstruction modes of the paper's section 4 (`--aa`) filter around that
// sample in linear light - spatial (the spread of a 2.25 view-pixel Gaussian), view (a
// tent over the 2 view intervals around it) or both - computed exactly, with one filtered
// fetch per subpixel after a prefilter pass (docs/player/reconstruction.md).
#pragma once

#include "eia_bindings_gpu.h"
#include "gl_handles.h"

#include "lfd/display_profile.h"

#include <glm/glm.hpp>

#include <array>
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
    static constexpr double kSpatialDiameter = 2.25; // view pixels, = 6 sigma
    static constexpr double kViewSupport = 2.0;      // view intervals: the tent between the two nearest view centres
    static constexpr double kSpatialSigma = kSpatialDiameter / 6.0;
    // The prefilter's 3-tap kernel [a, 1 - 2a, a] has variance 2a = sigma^2: with the
    // bilinear read after it, the spatial filter spreads light as the Gaussian integral of
    // the bilinear image does (variance 1/6 + sigma^2 per axis).
    static constexpr double kSpatialTap = kSpatialSigma * kSpatialSigma / 2.0;
};

// The filtered modes' linear -> 8-bit sRGB level (IEC 61966-2-1, rounded to nearest, but
// within 1e-4 levels of a rounding edge), as
// eia_construct.comp's encodeSrgb computes it: through srgbEncodeTable, entry i for
// sqrt(linear) * kEncodeBuckets in [i, i + 1) (at most 0.71 levels): level + f / 2, f where the level rises by
// one inside the bucket (1: it does not).
uint8_t encodeSrgbLevel(float linear);
// The prefilter's sRGB byte -> linear value (eia_prefilter.comp's linearTexel): the linear
// segment exactly, above it the polynomial of eia_bindings.glsl (within 3.0e-4 relative).
float prefilterLinear(uint8_t byte);
const std::array<float, eia_bindings::kEncodeBuckets>& srgbEncodeTable();

class EiaBuilder {
public:
    // Panel-size RGBA8 output texture.
    explicit EiaBuilder(const DisplayProfile& profile);
    EiaBuilder(const EiaBuilder&) = delete;
    EiaBuilder& operator=(const EiaBuilder&) = delete;

    void build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer); // stage "eia"
    unsigned texture() const { return eia_.get(); }
    std::vector<uint8_t> read() const; // RGBA8, panel size, rows top to bottom
    uint64_t bytes() const;            // GPU memory of the EIA texture

private:
    DisplayProfile profile_;
    uint32_t lensStride_ = 1; // invocation order: pixels per stride (lfd::samePhasePixelStride)
    gl::Texture eia_;
    gl::Buffer encodeTable_; // srgbEncodeTable, read by the filtered modes
    gl::Sampler nearest_;  // keeps the view array complete whatever its own filter state
    gl::Sampler bilinear_; // the prefiltered views: linear filtering, edges clamped
    // One program per Reconstruction mode (EIA_MODE compiled in), built on first use.
    gl::Program programs_[4];
    // The spatial modes' prefiltered linear views, one R16F plane per channel side by side
    // (3 view widths wide): [0] a 3D texture (z = view) for view-spatial's trilinear read,
    // [1] an array (layer = view) for spatial's bilinear read; each with its
    // eia_prefilter.comp program, built and sized on first use.
    struct Prefiltered {
        gl::Program program;
        gl::Texture texture;
        uint32_t size[3] = {0, 0, 0}; // view width, height, count
    };
    Prefiltered prefiltered_[2];
    unsigned program(Reconstruction mode);
    // Runs the prefilter for `mode` (spatial or view-spatial); returns the texture to read.
    unsigned prefilter(const ViewTargets& views, Reconstruction mode);
};

// View texel (image order: row 0 = top) under subpixel column k on panel row l, as the EIA
// pass reads it in mode none (eia_construct.comp, viewTexelUnder) and the direct subpixel
// splat's inverse map inverts it (lfdpr_direct_fanout.h): the view
// pixel containing the subpixel's screen position ((k + 0.5) / 3W, (l + 0.5) / H),
// computed without rounding as floor((2k + 1) w / 6W) and floor((2l + 1) h / 2H).
inline uint32_t viewColumnUnder(uint32_t k, uint32_t panelWidth, uint32_t viewWidth) {
    return uint32_t((uint64_t(2 * k + 1) * viewWidth) / (6ull * panelWidth));
}
inline uint32_t viewRowUnder(uint32_t l, uint32_t panelHeight, uint32_t viewHeight) {
    return uint32_t((uint64_t(2 * l + 1) * viewHeight) / (2ull * panelHeight));
}

// CPU reference of the same mapping (tests, simulated viewer): views are RGBA8 images in
// image order (row 0 = top), all of size viewWidth x viewHeight. Mode none is bit-identical
// to the GPU pass; the filtered modes follow the GPU's steps (the prefilter stored as
// half floats, bilinear reads, sRGB decoded through the same table) in float, and differ
// from it by at most one 8-bit level where the GPU fuses a multiply-add, takes a power or
// filters with other rounding (reconstruction_test states the tolerance).
std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight,
                                 Reconstruction mode = Reconstruction::None);

} // namespace lfd::player
