// The one registry of renderers: name + options -> renderer, used by lfd-play, the window
// (R key), lfd-bench and the tests alike, so a renderer is never rebuilt with options other
// than the user's. The lfdpr variants (the paper's pipeline and the ablations with one of
// the paper's innovations off) are registered names too: each starts from the caller's
// lfdpr options (so --atomics and the --no-* flags still apply) and changes one thing.
#pragma once

#include "renderer.h"
#include "renderer_gstd.h"
#include "renderer_lfdpr.h"

#include <memory>
#include <string>
#include <vector>

namespace lfd::player {

// Options of every configurable renderer; each renderer reads its own part.
struct RendererOptions {
    LfdprOptions lfdpr; // "lfdpr" and the lfdpr-* variants
    GstdOptions gstd;   // "gstd"
};

// The methods: mvr, mvr-layered, lfdpr, gstd.
std::vector<std::string> rendererNames();
// The lfdpr variants: lfdpr-paper, lfdpr-no-lfd-sampling, lfdpr-no-texture-splatting,
// lfdpr-no-pixel-culling, lfdpr-no-margin-trim, lfdpr-no-cell-scaling, lfdpr-no-mv-mipmapping.
std::vector<std::string> lfdprVariantNames();
// Every name createRenderer accepts: the methods, then the variants, and the experiments
// selectable by name only (lfdpr-direct, docs/player/direct-splat.md).
std::vector<std::string> allRendererNames();
bool isKnownRenderer(const std::string& name);

// Needs a current GL 4.5 context. Throws std::invalid_argument listing the known names for
// an unknown one, and whatever the renderer's constructor throws (gl::GlError for options
// the driver cannot run, std::invalid_argument for invalid options).
std::unique_ptr<Renderer> createRenderer(const std::string& name, const RendererOptions& options = {});

} // namespace lfd::player
