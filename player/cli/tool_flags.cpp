#include "tool_flags.h"

#include "cli_support.h"

#include <cmath>

namespace lfd::player {

using cli::UsageError;

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
}

void finishSharedFlags(SharedFlags& flags)
{
    if (*flags.viewSizeOpt)
        flags.viewSize = cli::parseSize("--view-size", flags.viewSizeText);
    if (!std::isfinite(flags.fps) || flags.fps <= 0.0)
        throw UsageError("--fps: must be a positive number");
    if (!std::isfinite(flags.turntablePeriod) || flags.turntablePeriod < 0.0)
        throw UsageError("--turntable-period: must be >= 0");
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
        throw UsageError("--environment-rotation: must be a finite number of degrees");
    if (!std::isfinite(flags.exposureEv) || std::abs(flags.exposureEv) > 64.0)
        throw UsageError("--exposure: must be a number of stops between -64 and 64");
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
