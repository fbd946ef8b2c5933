#include "lfd/looking_glass_devices.h"

#include <array>
#include <cmath>

namespace lfd {

namespace {

struct Device {
    const char* name;
    uint32_t panelWidth, panelHeight;
    double screenWidthMm; // separates panels of equal resolution (32" and 65")
    uint32_t cols, rows, quiltWidth, quiltHeight;
};

// Looking Glass' published quilt settings per device (formats/display_profiles.md 3.;
// docs.lookingglassfactory.com/keyconcepts/quilts, "Quilt Settings by Device").
constexpr std::array<Device, 7> kDevices = {{
    {"Looking Glass Portrait", 1536, 2048, 120.4, 8, 6, 3360, 3360},
    {"Looking Glass Go", 1440, 2560, 74.7, 11, 6, 4092, 4092},
    {"Looking Glass 16\" Spatial Display (landscape)", 3840, 2160, 345.4, 7, 7, 5999, 5999},
    {"Looking Glass 16\" Spatial Display (portrait)", 2160, 3840, 194.3, 11, 6, 5995, 6000},
    {"Looking Glass 32\" Spatial Display (landscape)", 7680, 4320, 697.4, 7, 7, 8190, 8190},
    {"Looking Glass 32\" Spatial Display (portrait)", 4320, 7680, 392.3, 11, 6, 8184, 8184},
    {"Looking Glass 65\"", 7680, 4320, 1428.0, 8, 9, 8192, 8192},
}};

constexpr double kWidthTolerance = 0.03;

} // namespace

std::optional<StandardQuilt> standardQuiltFor(uint32_t panelWidth, uint32_t panelHeight, double screenWidthMm)
{
    for (const Device& d : kDevices)
        if (d.panelWidth == panelWidth && d.panelHeight == panelHeight &&
            std::abs(screenWidthMm / d.screenWidthMm - 1.0) <= kWidthTolerance)
            return StandardQuilt{d.name, d.cols, d.rows, d.quiltWidth, d.quiltHeight};
    return std::nullopt;
}

} // namespace lfd
