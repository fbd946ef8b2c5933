// gstd: the slow gold standard every other renderer's quality is measured against. Two
// definitions (GstdModel), selectable so every claim can be compared both ways:
//
// panel (the default): the limit of the display. Sub-views tile the view cone (4 per view
// interval by default), each rendered at `factor` times the view resolution with mvr's PBR
// shading and anisotropic texture filtering; every panel subpixel integrates them over its
// own angular interval (the lenticular phase across its area) and one view pixel's area
// centred on its lens, gstd_panel.h. The EIA is that integral, not an
// interleave of views, so angular detail inside a view interval reaches the reference.
//
// views: the paper's GStd (Gavane & Watson 2024, section 5). Per output view two sub-views
// at their exact angles (2N cameras), Gaussian reconstruction (32 seeded random samples)
// averaged in linear light; the EIA is interleaved from those N views like every method's.
//
// Both models fill the same ViewTargets with their views (the Gaussian reconstruction of
// each view interval's sub-views), so views are compared the same way.
#pragma once

#include "gstd_progress.h"
#include "renderer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lfd::player {

enum class GstdModel : uint32_t { Panel = 0, Views = 1 };
// "panel", "views"; throws std::invalid_argument naming the choices.
GstdModel parseGstdModel(const std::string& name);
std::string gstdModelName(GstdModel model);

struct GstdOptions {
    GstdModel model = GstdModel::Panel;
    // Sub-views per view interval; 0 = the model's own: 4 for panel, 2 for views (the
    // paper's "twice the views at their exact angles").
    uint32_t subViews = 0;
    uint32_t subViewCount() const { return subViews ? subViews : (model == GstdModel::Panel ? 4u : 2u); }

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
    // Progress reports of each frame (gstd_progress.h): the plan before drawing, then one
    // per finished batch of sub-views. Set, the renderer waits for the GPU after each batch
    // (glFinish) so the reports say what is done, not what is queued; that wait is why it
    // is off by default and lfd-bench sets it only for an untimed reference. Not part of
    // the pixels (gstdSettingsKey ignores it).
    GstdProgressCallback progress;
};

// Throws std::invalid_argument for factor 0, samples 0, sub-views above 16, a non-positive
// diameter or an anisotropy below 1.
void validateGstdOptions(const GstdOptions& options);

// The reconstruction sample offsets (view pixels, relative to the pixel centre), one set of
// options.samples per sub-view (options.subViewCount() sets): 2D Gaussian of sigma = diameter / 6 by Box-Muller from a
// splitmix64 stream seeded with options.seed, resampled where it falls outside the
// support. Pure CPU and platform-independent (no std::normal_distribution), so a seed
// means the same offsets everywhere.
std::vector<glm::vec2> gstdSampleOffsets(const GstdOptions& options);

// Everything that changes gstd's pixels, as text (for the disk cache key).
std::string gstdSettingsKey(const GstdOptions& options);

std::unique_ptr<Renderer> createGstdRenderer(const GstdOptions& options = {});

} // namespace lfd::player
