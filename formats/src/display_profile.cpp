// Display profiles: the built-in prototype, the project's profile JSON format, validation
// and the subpixel -> view mapping. Looking Glass visual.json import lives in
// looking_glass_import.cpp. The file format is documented in formats/display_profiles.md.
#include "lfd/display_profile.h"

#include "display_profile_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <system_error>

namespace lfd {

namespace detail {

void throwProfileError(const std::string& source, const std::string& field,
                       const std::string& problem) {
    std::string message = source + ": " + field + ": " + problem;
    // note: messages quote file names and parser text; keep the promise of one line.
    std::replace_if(message.begin(), message.end(),
                    [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw DisplayProfileError(message);
}

std::string formatNumber(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.10g", value);
    return buffer;
}

uint32_t toUint32(const nlohmann::json& value, const std::string& source,
                  const std::string& field) {
    if (!value.is_number())
        throwProfileError(source, field, "must be a number, got " + std::string(value.type_name()));
    if (value.is_number_float()) {
        // Accept 2048.0 (Looking Glass files store integers as floats), reject 2048.5.
        const double d = value.get<double>();
        if (!std::isfinite(d) || d != std::floor(d))
            throwProfileError(source, field, "must be a whole number, got " + formatNumber(d));
        if (d < 0.0)
            throwProfileError(source, field, "must not be negative, got " + formatNumber(d));
        if (d > double(std::numeric_limits<uint32_t>::max()))
            throwProfileError(source, field, "too large: " + formatNumber(d));
        return uint32_t(d);
    }
    if (value.is_number_integer() && !value.is_number_unsigned())
        if (value.get<int64_t>() < 0)
            throwProfileError(source, field,
                              "must not be negative, got " + std::to_string(value.get<int64_t>()));
    const uint64_t u = value.get<uint64_t>();
    if (u > std::numeric_limits<uint32_t>::max())
        throwProfileError(source, field, "too large: " + std::to_string(u));
    return uint32_t(u);
}

std::string defaultProfileName(const std::string& source) {
    return std::filesystem::path(source).stem().string();
}

} // namespace detail

namespace {

using detail::formatNumber;
using detail::throwProfileError;
using nlohmann::json;

constexpr double kPi = std::numbers::pi;
constexpr double kDegToRad = kPi / 180.0;

// Limits a profile must respect to be renderable (views live in one 2D texture array).
constexpr uint32_t kMaxViewCount = 2048;
constexpr uint32_t kMaxViewSize = 16384;
constexpr uint64_t kMaxViewBytes = uint64_t(4) << 30; // 64-bit view buffers, all views
constexpr double kMaxTiltDeg = 60.0;
constexpr double kMaxViewConeDeg = 170.0;

constexpr const char* kFormatMarker = "lfd-display-profile/1";
constexpr uintmax_t kMaxProfileFileBytes = 16u << 20;

// van Berkel (1999) mapping in the affine form of SubpixelMapping.
//   X     = subpixels under one lens, measured horizontally = 3 W / lensCount
//   phase = fract((k + 0.5 + k_off - 3 l tan(tilt)) / X)
//         = fract(k * (1/X) + l * (-3 tan(tilt) / X) + (0.5 + k_off) / X)
// The "3 l tan(tilt)" term moves the lens by tan(tilt) pixels (3 tan(tilt) subpixel
// columns) per pixel row, i.e. the tilt is measured on the pixel grid; for square pixels
// (every panel we know of, the prototype included) that is the physical angle.
SubpixelMapping vanBerkelMapping(uint32_t panelWidth, double lensCount, double tiltDeg,
                                 double offsetSubpixels) {
    const double X = 3.0 * double(panelWidth) / lensCount;
    SubpixelMapping mapping;
    mapping.perSubpixel = 1.0 / X;
    mapping.perRow = -3.0 * std::tan(tiltDeg * kDegToRad) / X;
    // note: only the fractional part matters; keeping it in [0,1) keeps GPU floats exact.
    const double offset = (0.5 + offsetSubpixels) / X;
    mapping.offset = offset - std::floor(offset);
    return mapping;
}

void checkPositiveFinite(double value, const std::string& source, const char* field) {
    if (!std::isfinite(value))
        throwProfileError(source, field, "must be a finite number, got " + formatNumber(value));
    if (value <= 0.0)
        throwProfileError(source, field, "must be > 0, got " + formatNumber(value));
}

void checkViewSize(uint32_t size, const std::string& source, const char* field) {
    if (size == 0)
        throwProfileError(source, field, "must be > 0");
    if (size > kMaxViewSize)
        throwProfileError(source, field,
                          std::to_string(size) + " exceeds the texture limit of " +
                              std::to_string(kMaxViewSize));
}

// ---- the project's own profile format ------------------------------------------------

constexpr std::array kProjectKeys = {
    "format",          "name",           "panel_width",      "panel_height",
    "screen_width_mm", "screen_height_mm", "subpixel_order", "lens_width_mm",
    "lens_count",      "lens_tilt_deg",  "offset_subpixels", "invert_views",
    "view_count",      "view_width",     "view_height",      "view_cone_deg",
    "viewing_distance_mm",
};

const json& requireKey(const json& root, const char* key, const std::string& source) {
    auto it = root.find(key);
    if (it == root.end())
        throwProfileError(source, key, "missing (required)");
    return *it;
}

double toDouble(const json& value, const std::string& source, const char* field) {
    if (!value.is_number())
        throwProfileError(source, field,
                          "must be a number, got " + std::string(value.type_name()));
    return value.get<double>();
}

double optionalDouble(const json& root, const char* key, double fallback,
                      const std::string& source) {
    auto it = root.find(key);
    return it == root.end() ? fallback : toDouble(*it, source, key);
}

void checkProjectKeys(const json& root, const std::string& source) {
    // Reject unknown keys first, so a typo is reported as such and not as the
    // "missing" key it was meant to be.
    for (const auto& item : root.items()) {
        const std::string& key = item.key();
        if (std::find(kProjectKeys.begin(), kProjectKeys.end(), key) == kProjectKeys.end())
            throwProfileError(source, key,
                              "unknown key (see formats/display_profiles.md for the keys)");
    }
    if (auto it = root.find("format"); it != root.end()) {
        if (!it->is_string() || it->get<std::string>() != kFormatMarker)
            throwProfileError(source, "format",
                              std::string("must be \"") + kFormatMarker + "\", got " + it->dump());
    }
}

void readProjectName(const json& root, const std::string& source, DisplayProfile& p) {
    // Name (optional, defaults to the file stem).
    if (auto it = root.find("name"); it != root.end()) {
        if (!it->is_string())
            throwProfileError(source, "name", "must be a string");
        p.name = it->get<std::string>();
    }
    if (p.name.empty())
        p.name = detail::defaultProfileName(source);
}

void readProjectPanel(const json& root, const std::string& source, DisplayProfile& p) {
    // Panel.
    p.panelWidth = detail::toUint32(requireKey(root, "panel_width", source), source, "panel_width");
    p.panelHeight =
        detail::toUint32(requireKey(root, "panel_height", source), source, "panel_height");
    p.screenWidthMm =
        toDouble(requireKey(root, "screen_width_mm", source), source, "screen_width_mm");
    p.screenHeightMm =
        toDouble(requireKey(root, "screen_height_mm", source), source, "screen_height_mm");
    if (auto it = root.find("subpixel_order"); it != root.end()) {
        const std::string order = it->is_string() ? it->get<std::string>() : std::string();
        if (order == "RGB")
            p.subpixelOrder = SubpixelOrder::RGB;
        else if (order == "BGR")
            p.subpixelOrder = SubpixelOrder::BGR;
        else
            throwProfileError(source, "subpixel_order",
                              "must be \"RGB\" or \"BGR\", got " + it->dump());
    }
}

void readProjectLenticularSheet(const json& root, const std::string& source, DisplayProfile& p) {
    // Lenticular sheet. lens_count (the measured ratio screen width / lens width)
    // wins over lens_width_mm for the mapping when both are given, as for the prototype.
    const auto lensWidthIt = root.find("lens_width_mm");
    const auto lensCountIt = root.find("lens_count");
    if (lensWidthIt == root.end() && lensCountIt == root.end())
        throwProfileError(source, "lens_width_mm", "missing (give lens_width_mm or lens_count)");
    checkPositiveFinite(p.screenWidthMm, source, "screen_width_mm");
    double lensCount = 0.0;
    if (lensCountIt != root.end()) {
        lensCount = toDouble(*lensCountIt, source, "lens_count");
        checkPositiveFinite(lensCount, source, "lens_count");
    }
    if (lensWidthIt != root.end()) {
        p.lensWidthMm = toDouble(*lensWidthIt, source, "lens_width_mm");
        checkPositiveFinite(p.lensWidthMm, source, "lens_width_mm");
    }
    if (lensCountIt == root.end())
        lensCount = p.screenWidthMm / p.lensWidthMm;
    if (lensWidthIt == root.end())
        p.lensWidthMm = p.screenWidthMm / lensCount;
    p.lensTiltDeg = toDouble(requireKey(root, "lens_tilt_deg", source), source, "lens_tilt_deg");
    p.offsetSubpixels = optionalDouble(root, "offset_subpixels", 0.0, source);
    if (!std::isfinite(p.offsetSubpixels))
        throwProfileError(source, "offset_subpixels", "must be a finite number");
    bool invert = false;
    if (auto it = root.find("invert_views"); it != root.end()) {
        if (!it->is_boolean())
            throwProfileError(source, "invert_views", "must be true or false");
        invert = it->get<bool>();
    }
    if (p.panelWidth > 0) {
        p.mapping = vanBerkelMapping(p.panelWidth, lensCount, p.lensTiltDeg, p.offsetSubpixels);
        p.mapping.invert = invert;
    }
}

void readProjectViews(const json& root, const std::string& source, DisplayProfile& p) {
    // Views and viewing geometry; cone and distance have documented defaults.
    p.viewCount = detail::toUint32(requireKey(root, "view_count", source), source, "view_count");
    p.viewWidth = detail::toUint32(requireKey(root, "view_width", source), source, "view_width");
    p.viewHeight = detail::toUint32(requireKey(root, "view_height", source), source, "view_height");
    p.viewConeDeg = optionalDouble(root, "view_cone_deg", detail::kDefaultViewConeDeg, source);
    p.viewingDistanceMm = optionalDouble(
        root, "viewing_distance_mm",
        detail::kDefaultViewingDistanceScreenHeights * p.screenHeightMm, source);
}

DisplayProfile parseProjectProfile(const json& root, const std::string& source) {
    checkProjectKeys(root, source);
    DisplayProfile p;
    readProjectName(root, source, p);
    readProjectPanel(root, source, p);
    readProjectLenticularSheet(root, source, p);
    readProjectViews(root, source, p);
    return p;
}

} // namespace

DisplayProfile prototypeDisplayProfile() {
    DisplayProfile p;
    p.name = "prototype";
    p.panelWidth = 3840;
    p.panelHeight = 2160;
    p.screenWidthMm = 345.40;
    p.screenHeightMm = 194.30;
    p.subpixelOrder = SubpixelOrder::RGB;
    p.lensWidthMm = 0.72;
    p.lensTiltDeg = -9.66;
    p.offsetSubpixels = 0.0;
    // The paper's measured lens count (479.36), not the ideal 345.40 / 0.72 = 479.72.
    p.mapping = vanBerkelMapping(p.panelWidth, 479.36, p.lensTiltDeg, p.offsetSubpixels);
    p.viewCount = 48;
    p.viewWidth = 480;
    p.viewHeight = 360;
    // Not given by the paper: our assumptions (formats/display_profiles.md).
    p.viewConeDeg = 40.0;
    p.viewingDistanceMm = 600.0;
    return p;
}

void validateDisplayProfile(const DisplayProfile& p, const std::string& source) {
    // Panel.
    if (p.panelWidth == 0)
        throwProfileError(source, "panel_width", "must be > 0");
    if (p.panelHeight == 0)
        throwProfileError(source, "panel_height", "must be > 0");
    checkPositiveFinite(p.screenWidthMm, source, "screen_width_mm");
    checkPositiveFinite(p.screenHeightMm, source, "screen_height_mm");
    if (p.subpixelOrder != SubpixelOrder::RGB && p.subpixelOrder != SubpixelOrder::BGR)
        throwProfileError(source, "subpixel_order", "must be RGB or BGR");

    // Lenticular sheet and its derived mapping.
    checkPositiveFinite(p.lensWidthMm, source, "lens_width_mm");
    if (!std::isfinite(p.lensTiltDeg) || p.lensTiltDeg <= -kMaxTiltDeg ||
        p.lensTiltDeg >= kMaxTiltDeg)
        throwProfileError(source, "lens_tilt_deg",
                          "must lie in (-60, 60) degrees, got " + formatNumber(p.lensTiltDeg));
    if (!std::isfinite(p.offsetSubpixels))
        throwProfileError(source, "offset_subpixels", "must be a finite number");
    // lens count = 3 W / X = perSubpixel * 3 W
    checkPositiveFinite(p.mapping.perSubpixel * 3.0 * double(p.panelWidth), source, "lens_count");
    if (!std::isfinite(p.mapping.perRow))
        throwProfileError(source, "mapping.per_row", "must be a finite number");
    if (!std::isfinite(p.mapping.offset))
        throwProfileError(source, "mapping.offset", "must be a finite number");

    // Views: they must fit one 2D texture array of 64-bit view buffers.
    if (p.viewCount == 0)
        throwProfileError(source, "view_count", "must be > 0");
    if (p.viewCount > kMaxViewCount)
        throwProfileError(source, "view_count",
                          std::to_string(p.viewCount) + " exceeds the limit of " +
                              std::to_string(kMaxViewCount));
    checkViewSize(p.viewWidth, source, "view_width");
    checkViewSize(p.viewHeight, source, "view_height");
    const uint64_t viewBytes = uint64_t(p.viewWidth) * p.viewHeight * p.viewCount * 8u;
    if (viewBytes > kMaxViewBytes)
        throwProfileError(source, "view_count",
                          std::to_string(p.viewCount) + " views of " +
                              std::to_string(p.viewWidth) + "x" + std::to_string(p.viewHeight) +
                              " need " + std::to_string(viewBytes >> 20) +
                              " MiB of 64-bit view buffers, more than the 4 GiB limit");

    // Viewing geometry.
    if (!std::isfinite(p.viewConeDeg) || p.viewConeDeg <= 0.0 || p.viewConeDeg >= kMaxViewConeDeg)
        throwProfileError(source, "view_cone_deg",
                          "must lie in (0, 170) degrees, got " + formatNumber(p.viewConeDeg));
    checkPositiveFinite(p.viewingDistanceMm, source, "viewing_distance_mm");
    // The fitted scene sphere (fill 1) has the radius of half the smaller screen side and
    // is centred on the screen: the cameras must stay outside it.
    const double halfSide = 0.5 * std::min(p.screenWidthMm, p.screenHeightMm);
    if (p.viewingDistanceMm <= halfSide)
        throwProfileError(source, "viewing_distance_mm",
                          formatNumber(p.viewingDistanceMm) +
                              " mm must exceed half the smaller screen side (" +
                              formatNumber(halfSide) +
                              " mm) so the fitted scene stays in front of every camera");
}

DisplayProfile parseDisplayProfile(const std::string& jsonText, const std::string& source) {
    json root;
    try {
        root = json::parse(jsonText);
    } catch (const json::exception& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ..."
        // (or out_of_range.406 "number overflow parsing '1e400'").
        std::string what = e.what();
        if (auto pos = what.find("] "); pos != std::string::npos)
            what = what.substr(pos + 2);
        throwProfileError(source, "invalid JSON", what);
    }
    if (!root.is_object())
        throwProfileError(source, "top level", "must be a JSON object, got " +
                                                   std::string(root.type_name()));

    DisplayProfile profile;
    try {
        profile = detail::isLookingGlassVisual(root)
                      ? detail::importLookingGlassVisual(root, source)
                      : parseProjectProfile(root, source);
    } catch (const json::exception& e) {
        // Defensive: every access above is type-checked, but never let a library
        // exception escape with a multi-line or source-less message.
        throwProfileError(source, "JSON", e.what());
    }
    validateDisplayProfile(profile, source);
    return profile;
}

DisplayProfile loadDisplayProfile(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throwProfileError(source, "file", "not found");
    if (std::filesystem::is_directory(status))
        throwProfileError(source, "file", "is a directory, not a profile JSON file");
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxProfileFileBytes)
        throwProfileError(source, "file", "too large for a display profile (" +
                                              std::to_string(size) + " bytes)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throwProfileError(source, "file", "cannot be opened for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throwProfileError(source, "file", "read error");
    return parseDisplayProfile(text.str(), source);
}

DisplayProfile withViews(DisplayProfile profile, uint32_t viewCount, uint32_t viewWidth,
                         uint32_t viewHeight) {
    if (viewCount != 0)
        profile.viewCount = viewCount;
    if (viewWidth != 0)
        profile.viewWidth = viewWidth;
    if (viewHeight != 0)
        profile.viewHeight = viewHeight;
    validateDisplayProfile(profile, profile.name + " (with view overrides)");
    return profile;
}

} // namespace lfd
