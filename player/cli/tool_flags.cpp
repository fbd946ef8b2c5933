#include "tool_flags.h"

#include "cli_support.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace lfd::player {

using cli::UsageError;

namespace {

// --views, --frames, --aa / --reconstruction, --ss: one value in lfd-play, lists in lfd-bench.
void addFrameFlags(CLI::App& app, SharedFlags& flags)
{
    const std::string list = flags.lists ? "; a comma-separated list runs the matrix once per value" : "";
    flags.viewsOpt = app.add_option("--views", flags.viewsText, "number of views, 1..2048 (overrides the profile)" + list);
    flags.framesOpt = app.add_option("--frames", flags.frames,
                                     flags.lists ? "timed frames per renderer"
                                                 : "frames to render (timing; windowed: exit after them; with "
                                                   "--quilt: a sequence)")
                          ->capture_default_str();
    app.add_option("--aa,--reconstruction", flags.aaText,
                   "EIA reconstruction: none|spatial|view|view-spatial (spatial: the paper's 2.25 view-pixel "
                   "Gaussian; view: a tent over 2 view intervals; computed exactly)" + list)
        ->capture_default_str();
    app.add_option("--ss", flags.ssText,
                   "supersampling: 1 | 2s (views at twice the resolution) | 2v (twice the views, random angles in "
                   "each view interval), averaged down" + list)
        ->capture_default_str();
}

// lfdpr's switches; in lfd-bench they apply to lfdpr and every lfdpr-* variant.
void addLfdprFlags(CLI::App& app, SharedFlags& flags)
{
    app.add_flag("--no-lfd-sampling", flags.noLfdSampling, "lfdpr: isotropic sampling at the finer density (iVIR)");
    app.add_flag("--no-texture-splatting", flags.noTextureSplatting, "lfdpr: no density reduction by texture");
    app.add_flag("--no-mv-mipmapping", flags.noMvMipmapping,
                 "lfdpr paper pipeline: texture values at LOD 0 (no multiview mipmapping)");
    app.add_flag("--no-pixel-culling", flags.noPixelCulling,
                 "lfdpr: sample every triangle, also those that hold no view pixel centre");
    app.add_flag("--no-margin-trim", flags.noMarginTrim,
                 "lfdpr visibility pipeline: also sample the cells of the sampling box's margin, as the paper");
    app.add_flag("--lfdpr-work-counters", flags.lfdprWorkCounters,
                 "lfdpr visibility pipeline: count the splat's and the shading's work on the GPU (work_* stats: "
                 "point-views culled, samples, atomics, words lowered, shadings; docs/player/8k-panels.md)");
    app.add_option("--lfdpr-cell-scale", flags.lfdprCellScale,
                   "lfdpr visibility pipeline: point cells of N x N sampling spacings (1 = the paper's density; "
                   "the views are the same for every N)")
        ->check(CLI::Range(1u, 8u))
        ->capture_default_str();
    app.add_option("--atomics", flags.atomicsText, "lfdpr depth resolve: auto|64|32")->capture_default_str();
    app.add_option("--lfdpr-pipeline", flags.pipelineText,
                   "lfdpr: visibility (compute points, per-pixel shading) | paper (the paper's pipeline)")
        ->capture_default_str();
}

// "24,48" -> {24, 48}: each 1..2048; lfd-play (lists false) takes exactly one.
std::vector<uint32_t> parseViewCounts(const SharedFlags& flags)
{
    std::vector<uint32_t> counts;
    for (const std::string& item : cli::splitList(flags.viewsText)) {
        char* end = nullptr;
        const unsigned long n = std::strtoul(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || item[0] == '-' || n == 0 || n > 2048)
            throw UsageError("--views: expected 1..2048, got '" + item + "'");
        counts.push_back(uint32_t(n));
    }
    if (counts.empty())
        throw UsageError("--views: empty list");
    if (!flags.lists && counts.size() > 1)
        throw UsageError("--views: one view count, got '" + flags.viewsText + "' (lfd-bench takes a list)");
    return counts;
}

// "none,view" -> the modes, each typed by `parse`; one value unless the tool takes lists.
template <class Parse>
auto parseModes(const SharedFlags& flags, const std::string& flag, const std::string& text, Parse parse)
{
    const std::vector<std::string> names = cli::splitList(text);
    if (names.empty())
        throw UsageError(flag + ": empty list");
    if (!flags.lists && names.size() > 1)
        throw UsageError(flag + ": one value, got '" + text + "' (lfd-bench takes a list)");
    std::vector<decltype(parse(flag, text))> modes;
    for (const std::string& n : names)
        modes.push_back(parse(flag, n));
    return modes;
}

// --views, --frames, --aa, --ss, --no-turntable and lfdpr's switches, typed.
void finishFrameAndLfdprFlags(SharedFlags& flags)
{
    if (flags.frames == 0)
        throw UsageError("--frames: must be at least 1, got 0");
    if (*flags.viewsOpt)
        flags.viewCounts = parseViewCounts(flags);
    flags.aa = parseModes(flags, "--aa", flags.aaText, parseReconstructionFlag);
    flags.ss = parseModes(flags, "--ss", flags.ssText, parseSupersamplingFlag);
    flags.turntable = !flags.noTurntable;
    flags.lfdSampling = !flags.noLfdSampling;
    flags.textureSplatting = !flags.noTextureSplatting;
    flags.mvMipmapping = !flags.noMvMipmapping;
    flags.pixelCulling = !flags.noPixelCulling;
    flags.marginTrim = !flags.noMarginTrim;
    try { // the parsers name their flag
        flags.atomics = parseLfdprAtomics(flags.atomicsText);
        flags.pipeline = parseLfdprPipeline(flags.pipelineText);
    } catch (const std::exception& e) {
        throw UsageError(e.what());
    }
}

} // namespace

void addSharedFlags(CLI::App& app, SharedFlags& flags)
{
    app.add_option("--display", flags.displayProfile,
                   "display profile JSON or Looking Glass visual.json (default: the paper's prototype)");
    flags.viewSizeOpt = app.add_option("--view-size", flags.viewSizeText, "view size WxH (overrides the profile)");
    app.add_option("--fps", flags.fps, "frame k is at time k / fps")->capture_default_str();
    app.add_option("--turntable-period", flags.turntablePeriod, "seconds per turntable revolution (0 = still)")
        ->capture_default_str();
    app.add_option("--gstd-factor", flags.gstdFactor,
                   "gstd: sub-views render at this many times the view resolution (slow gold standard)")
        ->capture_default_str();
    app.add_option("--gstd-model", flags.gstdModelText,
                   "gstd: panel (every subpixel integrates its own angular interval and a view pixel at its lens: the limit "
                   "of the display) | views (the paper's: N views from 2 sub-views each, interleaved like any method)")
        ->capture_default_str();
    app.add_option("--gstd-sub-views", flags.gstdSubViews,
                   "gstd: sub-views per view interval, 1..16 (0 = the model's: panel 4, views 2)")
        ->capture_default_str();
    app.add_option("--lfdpr-work", flags.lfdprWorkText,
                   "lfdpr visibility pipeline work shape: auto (cpu on software rasterisers, else gpu) | gpu (many "
                   "short invocations) | cpu (long invocations); the views are the same")
        ->capture_default_str();
    app.add_option("--lfdpr-aniso", flags.lfdprAnisoText,
                   "lfdpr visibility pipeline, --aniso above 1: auto (taps on software rasterisers, else hardware) | "
                   "hardware (the texture unit's anisotropic filter at the exact footprint) | taps (trilinear taps "
                   "along the footprint's major axis)")
        ->capture_default_str();
    app.add_option("--aniso", flags.aniso,
                   "anisotropic texture filtering for every renderer: 1 (trilinear), 2, 4, 8 or 16 (clamped to the "
                   "driver's limit; gstd always filters at 16)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u}))
        ->capture_default_str();
    app.add_option("--environment", flags.environment,
                   "image-based lighting: neutral (a built-in studio) | none (the fixed directional light and a "
                   "constant ambient term) | an equirectangular Radiance .hdr file")
        ->capture_default_str();
    app.add_option("--environment-rotation", flags.environmentRotationDeg,
                   "turn the environment about the vertical by this many degrees (counter-clockwise seen from above)")
        ->capture_default_str();
    app.add_option("--exposure", flags.exposureEv, "exposure in stops: radiance x 2^EV before tone mapping")
        ->capture_default_str();
    app.add_option("--tone-map", flags.toneMapText,
                   "tone mapper before the sRGB encode: pbr-neutral (Khronos PBR Neutral) | none (clamp)")
        ->capture_default_str();
    app.add_flag("--gl-debug", flags.glDebug,
                 "debug GL context: print every KHR_debug message; a GL error fails the run naming the call");
    app.add_flag("--no-turntable", flags.noTurntable, "no turntable rotation: a still scene (as --turntable-period 0)");
    addFrameFlags(app, flags);
    addLfdprFlags(app, flags);
}

std::vector<std::string> sharedFlagNames()
{
    CLI::App app;
    SharedFlags flags;
    addSharedFlags(app, flags);
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options())
        for (const std::string& name : option->get_lnames())
            names.push_back("--" + name);
    // CLI11's own --help is not one of ours.
    std::erase(names, "--help");
    return names;
}

void finishSharedFlags(SharedFlags& flags)
{
    if (*flags.viewSizeOpt)
        flags.viewSize = cli::parseSize("--view-size", flags.viewSizeText);
    if (!std::isfinite(flags.fps) || flags.fps <= 0.0)
        throw UsageError("--fps: must be a positive number, got " + cli::numberText(flags.fps));
    if (!std::isfinite(flags.turntablePeriod) || flags.turntablePeriod < 0.0)
        throw UsageError("--turntable-period: must be >= 0 seconds, got " + cli::numberText(flags.turntablePeriod));
    finishFrameAndLfdprFlags(flags);
    GstdOptions gstd;
    gstd.factor = flags.gstdFactor;
    try {
        validateGstdOptions(gstd);
    } catch (const std::exception& e) {
        throw UsageError(std::string("--gstd-factor: ") + e.what());
    }
    try {
        flags.gstdModel = parseGstdModel(flags.gstdModelText);
    } catch (const std::exception& e) {
        throw UsageError(std::string("--gstd-model: ") + e.what());
    }
    gstd.subViews = flags.gstdSubViews;
    try {
        validateGstdOptions(gstd);
    } catch (const std::exception& e) {
        throw UsageError(std::string("--gstd-sub-views: ") + e.what());
    }
    if (!std::isfinite(flags.environmentRotationDeg))
        throw UsageError("--environment-rotation: must be a finite number of degrees, got " +
                         cli::numberText(flags.environmentRotationDeg));
    if (!std::isfinite(flags.exposureEv) || std::abs(flags.exposureEv) > 64.0)
        throw UsageError("--exposure: must be a number of stops between -64 and 64, got " +
                         cli::numberText(flags.exposureEv));
    if (flags.toneMapText == "pbr-neutral")
        flags.toneMap = ToneMap::PbrNeutral;
    else if (flags.toneMapText == "none")
        flags.toneMap = ToneMap::None;
    else
        throw UsageError("--tone-map: '" + flags.toneMapText + "' is not one of pbr-neutral, none");
    if (flags.environment.empty())
        throw UsageError("--environment: empty (neutral, none or a .hdr file)");
    try {
        flags.environmentChoice = lighting::chooseEnvironment(flags.environment);
    } catch (const std::exception& e) {
        throw UsageError(std::string("--environment: ") + e.what());
    }
    try {
        flags.lfdprWork = parseLfdprWorkShape(flags.lfdprWorkText);
        flags.lfdprAniso = parseLfdprAnisoFilter(flags.lfdprAnisoText);
    } catch (const std::exception& e) {
        throw UsageError(e.what());
    }
}

void applySharedFlags(const SharedFlags& flags, RendererOptions& options)
{
    options.gstd.factor = flags.gstdFactor;
    options.gstd.model = flags.gstdModel;
    options.gstd.subViews = flags.gstdSubViews;
    options.lfdpr.workShape = flags.lfdprWork;
    options.lfdpr.anisoFilter = flags.lfdprAniso;
    options.lfdpr.lfdBiasedSampling = flags.lfdSampling;
    options.lfdpr.textureSplatting = flags.textureSplatting;
    options.lfdpr.multiviewMipmapping = flags.mvMipmapping;
    options.lfdpr.pixelCentreCulling = flags.pixelCulling;
    options.lfdpr.trimSamplingMargin = flags.marginTrim;
    options.lfdpr.cellScale = flags.lfdprCellScale;
    options.lfdpr.countWork = flags.lfdprWorkCounters;
    options.lfdpr.atomics = flags.atomics;
    options.lfdpr.pipeline = flags.pipeline;
}

Reconstruction parseReconstructionFlag(const std::string& flag, const std::string& text)
{
    try {
        return parseReconstruction(text);
    } catch (const std::exception& e) {
        throw UsageError(flag + ": " + e.what());
    }
}

Supersampling parseSupersamplingFlag(const std::string& flag, const std::string& text)
{
    try {
        return parseSupersampling(text);
    } catch (const std::exception& e) {
        throw UsageError(flag + ": " + e.what());
    }
}

FrameLighting frameLightingFromFlags(const SharedFlags& flags)
{
    FrameLighting lighting;
    lighting.environmentRotationDeg = flags.environmentRotationDeg;
    lighting.exposureEv = flags.exposureEv;
    lighting.toneMap = flags.toneMap;
    return lighting;
}

} // namespace lfd::player
