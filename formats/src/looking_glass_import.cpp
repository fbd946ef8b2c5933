// Looking Glass visual.json calibration -> DisplayProfile.
//
// A visual.json holds the calibration Looking Glass' own lenticular shader consumes. Its
// values are wrapped as {"value": x} (bare numbers are accepted too). We keep the
// shader's behaviour exactly (the calibrated `center` was measured against it) and only
// rewrite it in the affine SubpixelMapping form; the derivation is below.
#include "display_profile_json.h"

#include "lfd/looking_glass_devices.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::detail {

namespace {

using nlohmann::json;

constexpr double kMmPerInch = 25.4;
// A known device (looking_glass_devices.h) gets the views of its standard quilt (the
// Portrait's 8 x 6 tiles of 420 x 560); other panels get 48 views, 560 pixels high, of the
// panel's aspect ratio.
constexpr uint32_t kDefaultViewCount = 48;
constexpr uint32_t kDefaultViewHeight = 560;

// Unwraps {"value": x}; accepts bare numbers and booleans. nullptr when absent.
const json* findEntry(const json& root, const char* key, const std::string& source) {
    auto it = root.find(key);
    if (it == root.end())
        return nullptr;
    const json* entry = &*it;
    if (entry->is_object()) {
        auto valueIt = entry->find("value");
        if (valueIt == entry->end())
            throwProfileError(source, key, "object has no \"value\"");
        entry = &*valueIt;
    }
    if (!entry->is_number() && !entry->is_boolean())
        throwProfileError(source, key, "must be a number, got " + std::string(entry->type_name()));
    return entry;
}

double numberOf(const json& entry) {
    return entry.is_boolean() ? (entry.get<bool>() ? 1.0 : 0.0) : entry.get<double>();
}

double requireNumber(const json& root, const char* key, const std::string& source) {
    const json* entry = findEntry(root, key, source);
    if (!entry)
        throwProfileError(source, key, "missing (required in a Looking Glass visual.json)");
    const double value = numberOf(*entry);
    if (!std::isfinite(value))
        throwProfileError(source, key, "must be a finite number");
    return value;
}

double optionalNumber(const json& root, const char* key, double fallback,
                      const std::string& source) {
    const json* entry = findEntry(root, key, source);
    if (!entry)
        return fallback;
    const double value = numberOf(*entry);
    if (!std::isfinite(value))
        throwProfileError(source, key, "must be a finite number");
    return value;
}

bool optionalFlag(const json& root, const char* key, const std::string& source) {
    const double value = optionalNumber(root, key, 0.0, source);
    if (value != 0.0 && value != 1.0)
        throwProfileError(source, key, "must be 0 or 1, got " + formatNumber(value));
    return value == 1.0;
}

uint32_t requirePixels(const json& root, const char* key, const std::string& source) {
    const json* entry = findEntry(root, key, source);
    if (!entry)
        throwProfileError(source, key, "missing (required in a Looking Glass visual.json)");
    const uint32_t value = toUint32(*entry, source, key);
    if (value == 0)
        throwProfileError(source, key, "must be > 0");
    return value;
}

// Nothing in our model mirrors the views vertically or knows subpixel cell patterns
// (newer panels): refuse them rather than show a wrong image.
void refuseUnsupportedCalibration(const json& root, const std::string& source) {
    if (optionalFlag(root, "flipImageY", source))
        throwProfileError(source, "flipImageY", "vertically mirrored panels are not supported");
    if (optionalNumber(root, "CellPatternMode", 0.0, source) != 0.0)
        throwProfileError(source, "CellPatternMode", "subpixel cell patterns are not supported");
}

// The views: a known device's standard quilt tiles, else the documented defaults at the
// panel's aspect; the viewing geometry's defaults.
void setLookingGlassViews(DisplayProfile& p, double viewConeDeg) {
    const uint32_t W = p.panelWidth, H = p.panelHeight;
    if (const auto quilt = standardQuiltFor(W, H, p.screenWidthMm)) {
        p.viewCount = quilt->cols * quilt->rows;
        p.viewWidth = quilt->tileWidth();
        p.viewHeight = quilt->tileHeight();
    } else {
        p.viewCount = kDefaultViewCount;
        p.viewHeight = kDefaultViewHeight;
        const double viewWidth = std::round(double(kDefaultViewHeight) * double(W) / double(H));
        p.viewWidth = uint32_t(std::clamp(viewWidth, 1.0, 1e9)); // validation rejects > 16384
    }
    p.viewConeDeg = viewConeDeg;
    p.viewingDistanceMm = kDefaultViewingDistanceScreenHeights * p.screenHeightMm;
}

} // namespace

bool isLookingGlassVisual(const json& root) {
    return root.is_object() && root.contains("pitch") && root.contains("slope");
}

DisplayProfile importLookingGlassVisual(const json& root, const std::string& source) {
    // Step 1: read the calibration.
    const double pitch = requireNumber(root, "pitch", source); // lenses per inch
    const double slope = requireNumber(root, "slope", source);
    const double center = requireNumber(root, "center", source);
    const double dpi = requireNumber(root, "DPI", source);
    const uint32_t W = requirePixels(root, "screenW", source);
    const uint32_t H = requirePixels(root, "screenH", source);
    const double viewCone = optionalNumber(root, "viewCone", kDefaultViewConeDeg, source);
    const bool invView = optionalFlag(root, "invView", source);
    const bool flipImageX = optionalFlag(root, "flipImageX", source);
    const bool flipSubp = optionalFlag(root, "flipSubp", source);
    refuseUnsupportedCalibration(root, source);
    if (pitch <= 0.0)
        throwProfileError(source, "pitch", "must be > 0, got " + formatNumber(pitch));
    if (slope == 0.0)
        throwProfileError(source, "slope", "must not be 0");
    if (dpi <= 0.0)
        throwProfileError(source, "DPI", "must be > 0, got " + formatNumber(dpi));
    if (viewCone <= 0.0 || viewCone >= 170.0)
        throwProfileError(source, "viewCone",
                          "must lie in (0, 170) degrees, got " + formatNumber(viewCone));

    // Step 2: the shader's derived uniforms (formats/display_profiles.md section 3).
    const double screenWidthIn = double(W) / dpi;
    const double pitchU = pitch * screenWidthIn * std::cos(std::atan(1.0 / slope));
    const double tilt = (double(H) / (double(W) * slope)) * (flipImageX ? -1.0 : 1.0);

    // Step 3: rewrite the shader in SubpixelMapping form.
    // The shader runs per pixel with texture coordinates (u, v) in [0,1]^2, v = 0 at the
    // BOTTOM row (GL window coordinates), and for each subpixel i = 0, 1, 2 computes
    //   a_i = fract((u + i * subp + v * tilt) * pitch_u - center),  subp = 1 / (3 W)
    //   a_i = 1 - a_i if invView;   view = a_i * N
    // At the centre of pixel (x, l), with our row l counted from the TOP:
    //   u = (x + 0.5) / W,   v = (H - 1 - l + 0.5) / H = 1 - (l + 0.5) / H.
    // With subpixel column k = 3 x + i:
    //   u + i * subp = (3 x + i + 1.5) / (3 W) = (k + 1.5) / (3 W)
    // (the shader samples subpixel i one subpixel right of its centre (k + 0.5) / (3 W);
    // we keep that, since `center` was calibrated with it). Hence
    //   a = fract(k * pitch_u / (3 W)
    //             + l * (-pitch_u * tilt / H)
    //             + pitch_u * (0.5 / W + tilt * (1 - 0.5 / H)) - center)
    // i.e. perSubpixel = pitch_u / (3 W), perRow = -pitch_u * tilt / H, and the constant
    // term is the offset. flipSubp makes the shader take red from i = 2 and blue from
    // i = 0: a BGR panel; the mapping itself is on physical columns and does not change.
    DisplayProfile p;
    p.panelWidth = W;
    p.panelHeight = H;
    p.mapping.perSubpixel = pitchU / (3.0 * double(W));
    p.mapping.perRow = -pitchU * tilt / double(H);
    const double offset = pitchU * (0.5 / double(W) + tilt * (1.0 - 0.5 / double(H))) - center;
    p.mapping.offset = offset - std::floor(offset); // only the fraction matters
    p.mapping.invert = invView;
    p.subpixelOrder = flipSubp ? SubpixelOrder::BGR : SubpixelOrder::RGB;

    // Step 4: the descriptive lens fields, in van Berkel terms (display_profile.cpp):
    // pitch_u is the lens count across the screen width, so X = 3 W / pitch_u; matching
    // perRow = -3 tan(tilt_vB) / X gives tan(tilt_vB) = tilt * W / H (= 1/slope, or its
    // negation with flipImageX); and offset = (0.5 + k_off) / X gives k_off.
    p.screenWidthMm = double(W) / dpi * kMmPerInch;
    p.screenHeightMm = double(H) / dpi * kMmPerInch;
    p.lensWidthMm = p.screenWidthMm / pitchU;
    p.lensTiltDeg = std::atan(tilt * double(W) / double(H)) * 180.0 / std::numbers::pi;
    p.offsetSubpixels = p.mapping.offset * (3.0 * double(W) / pitchU) - 0.5;

    // Step 5: views and viewing geometry (defaults documented in display_profiles.md).
    p.name = defaultProfileName(source);
    setLookingGlassViews(p, viewCone);
    return p;
}

} // namespace lfd::detail
