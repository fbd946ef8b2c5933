// The flags lfd-play and lfd-bench both take, declared once (addSharedFlags) and parsed
// once into typed values (finishSharedFlags), and the typed --aa / --ss parsers both tools'
// flags go through. Each tool copies the values into its own options. A flag both tools
// take is declared here and nowhere else (issue 42: lfd-play took --no-turntable and
// lfd-bench refused it), so a name, an alias or a check cannot drift between them;
// tests/player/shared_flags_test.cpp runs both tools with every flag sharedFlagNames()
// lists. Where lfd-bench runs a matrix, --views, --aa and --ss take comma-separated lists
// (SharedFlags::lists); lfd-play takes one value of each.
#pragma once

#include "eia_builder.h"
#include "environment_choice.h"
#include "frame_pipeline.h"
#include "renderer_registry.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lfd::player {

struct SharedFlags {
    // Set before addSharedFlags: lfd-bench's --views, --aa and --ss take lists.
    bool lists = false;
    // Typed values, after finishSharedFlags.
    std::string displayProfile;                             // --display; empty: the paper's prototype
    std::optional<std::pair<uint32_t, uint32_t>> viewSize; // --view-size
    double fps = 60.0;                                      // --fps: frame k is at time k / fps
    double turntablePeriod = 10.0;                          // --turntable-period: 0 = still
    uint32_t gstdFactor = GstdOptions{}.factor;             // --gstd-factor
    std::string gstdModelText = "panel";                    // --gstd-model
    GstdModel gstdModel = GstdModel::Panel;
    uint32_t gstdSubViews = 0;                              // --gstd-sub-views: 0 = the model's
    LfdprOptions::WorkShape lfdprWork = LfdprOptions::WorkShape::Auto; // --lfdpr-work
    LfdprOptions::AnisoFilter lfdprAniso = LfdprOptions::AnisoFilter::Auto; // --lfdpr-aniso
    bool glDebug = false;                                   // --gl-debug
    bool turntable = true;                                  // --no-turntable: false (a still scene)
    uint32_t frames = 1;                                    // --frames (each tool sets its default first)
    std::vector<uint32_t> viewCounts;                       // --views; empty: the profile's
    std::vector<Reconstruction> aa;                         // --aa / --reconstruction
    std::vector<Supersampling> ss;                          // --ss
    // lfdpr's switches (the lfdpr-* variants of the registry start from them).
    bool lfdSampling = true, textureSplatting = true, mvMipmapping = true, pixelCulling = true, marginTrim = true;
    uint32_t lfdprCellScale = LfdprOptions{}.cellScale;     // --lfdpr-cell-scale
    bool lfdprWorkCounters = false;                         // --lfdpr-work-counters
    LfdprOptions::Atomics atomics = LfdprOptions{}.atomics;  // --atomics
    LfdprOptions::Pipeline pipeline = LfdprOptions{}.pipeline; // --lfdpr-pipeline
    uint32_t aniso = 1;                                     // --aniso: 1, 2, 4, 8 or 16
    // Lighting (docs/lighting.md): the environment ("neutral", "none" or a Radiance .hdr),
    // its rotation about the vertical, the exposure and the tone mapper.
    std::string environment = "neutral";                    // --environment
    lighting::EnvironmentChoice environmentChoice;          // read by finishSharedFlags
    double environmentRotationDeg = 0.0;                    // --environment-rotation
    double exposureEv = 0.0;                                // --exposure
    std::string toneMapText = "pbr-neutral";                // --tone-map
    ToneMap toneMap = ToneMap::PbrNeutral;
    // As CLI11 fills them.
    std::string viewSizeText, lfdprWorkText = "auto", lfdprAnisoText = "auto";
    std::string viewsText, aaText = "none", ssText = "1", atomicsText = "auto", pipelineText = "visibility";
    bool noTurntable = false, noLfdSampling = false, noTextureSplatting = false, noMvMipmapping = false,
         noPixelCulling = false, noMarginTrim = false;
    CLI::Option *viewSizeOpt = nullptr, *viewsOpt = nullptr, *framesOpt = nullptr;
};

void addSharedFlags(CLI::App& app, SharedFlags& flags);
// Every flag addSharedFlags declares, by its long name ("--display", ...), in declaration order.
std::vector<std::string> sharedFlagNames();
// Checks and types the parsed flags; cli::UsageError naming the flag.
void finishSharedFlags(SharedFlags& flags);
// The frame lighting the flags ask for (its environment, environmentChoice, is uploaded by
// the tool once it has a GL context: uploadEnvironment).
FrameLighting frameLightingFromFlags(const SharedFlags& flags);
// --gstd-*, --lfdpr-work / --lfdpr-aniso and lfdpr's switches into the renderers' options.
void applySharedFlags(const SharedFlags& flags, RendererOptions& options);

// --aa / --ss values; cli::UsageError naming `flag` and the choices.
Reconstruction parseReconstructionFlag(const std::string& flag, const std::string& text);
Supersampling parseSupersamplingFlag(const std::string& flag, const std::string& text);

} // namespace lfd::player
