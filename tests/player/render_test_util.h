// The one way tests render (and the measurements their comparisons share): a scene uploaded
// as lfd-play uploads it (player::GpuScene), framed as the baker assumed (the scene's fill,
// as player::FramePipeline frames it), rendered by a renderer for some frames at one time,
// every view - and the EIA when asked - read back in image order (row 0 = top).
#pragma once

#include "frame.h"
#include "image_metrics.h"
#include "renderer.h"
#include "renderer_registry.h"

#include "lfd/scene.h"

#include <map>
#include <string>
#include <vector>

namespace lfd::test {

struct RenderRequest {
    double time = 0.0;            // animation and turntable time, seconds
    double turntablePeriod = 0.0; // seconds per revolution; 0: still
    int frames = 1;               // frames rendered into the same targets; the last is read back
    bool eia = false;             // also interleave the EIA (no reconstruction; gstd panel: its own) and read it back
    float aniso = 1.0f;           // the scene textures' max anisotropy (--aniso)
    // Exposure, tone mapping and environment (frame.h); its lights are the scene's, at
    // their nodes this frame. The default is the look without image-based lighting.
    player::FrameLighting lighting;
    // The settings renderFrame builds a renderer named by string with (quickGstdOptions: gstd
    // at 1x and 4 samples); the overload given a built renderer does not read them.
    player::RendererOptions rendererOptions;
};

struct RenderedFrame {
    player::FrameSetup setup;
    std::vector<metrics::Image> views;      // RGBA8, image order, view 0 = leftmost camera
    metrics::Image eia;                     // panel size, image order; empty unless asked for
    std::map<std::string, double> stageMs; // GpuTimer stage -> mean ms over the frames
    std::map<std::string, double> stats;   // the renderer's extraStats() after the last frame
    double seconds = 0.0;                  // wall time: upload, frames and read-back
};

// What lfd-play and lfd-bench light with by default (their flags' defaults): the neutral
// studio (prefiltered once per process) and PBR Neutral at exposure 0.
player::FrameLighting toolDefaultLighting();

// A frame at turntable angle `angle` (radians): a period of 2 pi seconds makes the time the
// angle.
RenderRequest atTurntableAngle(double angle);

// gstd at 1x and 4 samples (its defaults are 4x and 32): for tests of what gstd draws (a
// colour, a lighting preset), not of how far it converges.
player::RendererOptions quickGstdOptions();

// Needs a current GL context (GlTest); a GL error during the frame fails the test.
// `profile` already carries the view count and size.
RenderedFrame renderFrame(player::Renderer& renderer, const Scene& scene, const DisplayProfile& profile,
                          const RenderRequest& request = {});
// Same with a renderer built by name through the registry (as lfd-play builds it).
RenderedFrame renderFrame(const std::string& renderer, const Scene& scene, const DisplayProfile& profile,
                          const RenderRequest& request = {});

// The prototype profile with small views, for fast tests.
DisplayProfile smallProfile(uint32_t views, uint32_t width, uint32_t height);

// JSON text of a 384x216 panel built like the prototype at a tenth of its size (0.72 mm
// lenses at -9.66 deg, 8 views of 48x36: non-square 0.72 x 0.54 mm view pixels, as on the
// prototype), named `name`; small enough that EIAs stay cheap on llvmpipe.
std::string tenthPrototypeProfileJson(const std::string& name);
// That panel parsed, with `views` views of width x height.
DisplayProfile tenthPrototypeProfile(const std::string& name, uint32_t views, uint32_t width, uint32_t height);

// RMSE of the colour channels over the pixels where `mask` is set (0 for an empty mask).
double maskedRmse(const metrics::Image& a, const metrics::Image& b, const std::vector<uint8_t>& mask);
// SSIM (luma) over the bounding box of `mask`, grown by the 5-pixel SSIM window radius,
// so a mostly empty background does not dilute differences; 1 for an empty mask.
double ssimOverMaskBox(const metrics::Image& a, const metrics::Image& reference, const std::vector<uint8_t>& mask);

// ---- Checks of an image someone else produced (a tool's output file) ------------------

// Why `image` shows nothing, or "" when it shows something: blank when more than 99% of its
// pixels have one colour (all black, all background, any flat fill).
std::string blankReason(const metrics::Image& image);
// Why `written` is not `reference`, or "" when it is: different sizes, or a channel that
// differs by more than `tolerance` (0..255); then blankReason(written), so two equally
// blank images (a broken renderer on both sides) fail too.
std::string imageMismatch(const metrics::Image& written, const metrics::Image& reference, int tolerance);

// factor x factor box filter of RGBA8 bytes (downsamples a supersampled reference render).
metrics::Image boxDownsample(const metrics::Image& image, uint32_t factor);

// sRGB byte of a linear value, as the shaders encode it (srgb.glsl).
uint8_t srgbByte(float linear);

// ---- Coverage of one renderer against a reference (lfdpr against mvr) ----------------

// 1 where a pixel is covered: its colour differs from the renderers' clear colour
// (player::kBackground, written as is: 0.05 -> 13).
std::vector<uint8_t> coverageMask(const metrics::Image& image);

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
CoverageStats compareCoverage(const metrics::Image& reference, const metrics::Image& test);

} // namespace lfd::test
