// EIA construction (formats/display_profiles.md section 2): one compute pass over the panel's subpixels.
// For each subpixel (column k = 3x + i, row l) the view phase comes from the profile's
// SubpixelMapping; nearest-view mode takes that subpixel's channel from view
// floor(phase * N), sampled at the subpixel's screen position (each view covers the whole
// screen). Reconstruction modes (spatial / view / view-spatial Gaussian filters, issue
// "quality") plug in as further Reconstruction values handled by the same shader.
#pragma once

#include "lfd/display_profile.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::player {

class ViewTargets;
class GpuTimer;

enum class Reconstruction : uint32_t { None = 0 };
Reconstruction parseReconstruction(const std::string& name); // "none"; throws invalid_argument

class EiaBuilder {
public:
    explicit EiaBuilder(const DisplayProfile& profile); // panel-size RGBA8 output texture
    ~EiaBuilder();
    EiaBuilder(const EiaBuilder&) = delete;
    EiaBuilder& operator=(const EiaBuilder&) = delete;

    void build(const ViewTargets& views, Reconstruction mode, GpuTimer& timer); // stage "eia"
    unsigned texture() const { return eia_; }
    std::vector<uint8_t> read() const; // RGBA8, panel size, rows top to bottom

private:
    DisplayProfile profile_;
    unsigned eia_ = 0;
    unsigned program_ = 0;
};

// CPU reference of the same mapping (tests, simulated viewer): views are RGBA8 images in
// image order (row 0 = top), all of size viewWidth x viewHeight.
std::vector<uint8_t> buildEiaCpu(const DisplayProfile& profile,
                                 const std::vector<std::vector<uint8_t>>& views,
                                 uint32_t viewWidth, uint32_t viewHeight);

} // namespace lfd::player
