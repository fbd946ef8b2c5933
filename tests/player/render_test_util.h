// Renders an in-memory scene with a named renderer and reads every view back (tests).
#pragma once

#include "frame.h"
#include "image_output.h"

#include "lfd/scene.h"

#include <string>
#include <vector>

namespace lfd::test {

struct RenderedViews {
    player::FrameSetup frame;
    std::vector<player::Image> views; // RGBA8, image order (row 0 = top)
    std::vector<std::pair<std::string, double>> stageMs; // GpuTimer stages of the frame
};

// Needs a current GL context. `profile` already carries the view count and size.
RenderedViews renderScene(const Scene& scene, const std::string& renderer,
                          const DisplayProfile& profile, double time, double turntablePeriod);

// The prototype profile with small views, for fast tests.
DisplayProfile smallProfile(uint32_t views, uint32_t width, uint32_t height);

// JSON text of a 384x216 panel built like the prototype at a tenth of its size (0.72 mm
// lenses at -9.66 deg, 8 views of 48x36: non-square 0.72 x 0.54 mm view pixels, as on the
// prototype), named `name`; small enough that EIAs stay cheap on llvmpipe.
std::string tenthPrototypeProfileJson(const std::string& name);

// RMSE of the colour channels over the pixels where `mask` is set (0 for an empty mask).
double maskedRmse(const player::Image& a, const player::Image& b, const std::vector<uint8_t>& mask);
// SSIM (luma) over the bounding box of `mask`, grown by the 5-pixel SSIM window radius,
// so a mostly empty background does not dilute differences; 1 for an empty mask.
double ssimOverMaskBox(const player::Image& a, const player::Image& reference, const std::vector<uint8_t>& mask);

// factor x factor box filter of RGBA8 bytes (downsamples a supersampled reference render).
player::Image boxDownsample(const player::Image& image, uint32_t factor);

// ---- Coverage of one renderer against a reference (lfdpr against mvr) ----------------

// 1 where a pixel is covered: its colour differs from the renderers' clear colour
// (player::kBackground, written as is: 0.05 -> 13).
std::vector<uint8_t> coverageMask(const player::Image& image);

struct CoverageStats {
    size_t covered = 0;  // pixels the reference covers
    size_t interior = 0; // of those, farther than 1 px from the reference's coverage boundary
    size_t holes = 0;    // interior pixels the test image leaves empty
    size_t extra = 0;    // pixels the test image covers that the reference does not, farther than 1 px from it
    double holeRate() const { return covered ? double(holes) / double(covered) : 0.0; }
    double extraRate() const { return covered ? double(extra) / double(covered) : 0.0; }
    CoverageStats& operator+=(const CoverageStats& o)
    {
        covered += o.covered;
        interior += o.interior;
        holes += o.holes;
        extra += o.extra;
        return *this;
    }
};

// Silhouette band: a pixel is "near the boundary" if any pixel of its 3 x 3
// neighbourhood has the other coverage state in the reference image (image edges count as
// empty); holes and extra coverage are only counted outside that band.
CoverageStats compareCoverage(const player::Image& reference, const player::Image& test);

} // namespace lfd::test
