// Display profiles: the physical panel, its lenticular mapping and the views rendered
// for it. The paper's prototype (formats/display_profiles.md section 1) is the built-in default.
//
// Profiles are JSON files (samples/profiles/*.json); Looking Glass visual.json
// calibrations are imported into the same struct. Every loaded profile is validated
// (validateDisplayProfile); errors are DisplayProfileError with one line naming the file
// and the field.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace lfd {

class DisplayProfileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class SubpixelOrder : uint32_t { RGB = 0, BGR = 1 };

// Subpixel -> view mapping, reduced to one affine form that covers both van Berkel
// (1999) slanted lenticulars and Looking Glass calibrations:
//   phase(k, l) = fract(perSubpixel * k + perRow * l + offset)      k: subpixel column 0..3W-1
//   if (invert) phase = 1 - phase                                    l: pixel row 0..H-1 (top = 0)
//   view = phase * viewCount     (floor for nearest view)
// evaluated exactly in 64-bit fixed point (lfd/subpixel_phase.h).
// van Berkel: phase = fract((k + 0.5 + k_off - 3 l tan(tilt)) / X), X = subpixels per lens.
struct SubpixelMapping {
    double perSubpixel = 0.0;
    double perRow = 0.0;
    double offset = 0.0;
    bool invert = false;
};

struct DisplayProfile {
    std::string name;

    // Panel.
    uint32_t panelWidth = 0; // pixels
    uint32_t panelHeight = 0;
    double screenWidthMm = 0.0;
    double screenHeightMm = 0.0;
    SubpixelOrder subpixelOrder = SubpixelOrder::RGB;

    // Lenticular sheet (as given in the profile; `mapping` is derived from these).
    double lensWidthMm = 0.0;     // horizontal lens pitch on the panel
    double lensTiltDeg = 0.0;     // lens tilt from vertical
    double offsetSubpixels = 0.0; // k_off
    SubpixelMapping mapping;

    // Views and viewing geometry.
    uint32_t viewCount = 0;
    uint32_t viewWidth = 0;
    uint32_t viewHeight = 0;
    double viewConeDeg = 0.0;        // total horizontal angle spanned by the view cameras
    double viewingDistanceMm = 0.0;  // camera line distance from the screen plane
};

// The paper's prototype: 3840x2160, 345.40x194.30 mm, RGB stripe, lens 0.72 mm,
// tilt -9.66 deg, lens count 479.36, 48 views of 480x360.
DisplayProfile prototypeDisplayProfile();

// Throws DisplayProfileError naming `source` and the offending field.
void validateDisplayProfile(const DisplayProfile& profile, const std::string& source);

// Loads a profile JSON file: either the project's own format (formats/display_profiles.md,
// section 1) or a Looking Glass visual.json calibration (detected by its keys).
// The result is validated. Throws DisplayProfileError.
DisplayProfile loadDisplayProfile(const std::filesystem::path& path);
DisplayProfile parseDisplayProfile(const std::string& jsonText, const std::string& source);

// Replaces view count / view size (command-line overrides) and re-validates.
DisplayProfile withViews(DisplayProfile profile, uint32_t viewCount, uint32_t viewWidth,
                         uint32_t viewHeight);

// Phase in [0,1) of subpixel column k (0..3W-1) on pixel row l (0..H-1, top = 0): the
// fixed-point phase of lfd/subpixel_phase.h (defined in subpixel_phase.cpp), to 53 bits.
double subpixelPhase(const DisplayProfile& profile, uint32_t k, uint32_t l);
// Nearest view index in [0, viewCount) of that subpixel, from the exact fixed-point phase.
uint32_t subpixelView(const DisplayProfile& profile, uint32_t k, uint32_t l);

} // namespace lfd
