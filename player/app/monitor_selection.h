// Which monitor drives the light field panel, and where the EIA lands on it. A lenticular
// panel is driven as a monitor and needs its image pixel for pixel, so the choice is
// strict: the monitor's current mode must be the profile's panel size, or the run is
// refused (--allow-mismatch: the EIA is centred unscaled, cropped where it is larger).
// Pure logic over a monitor list, so it is unit-tested without a display; the GLFW
// enumeration is listMonitors().
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::player {

class MonitorError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct MonitorInfo {
    std::string name;
    int x = 0, y = 0;                  // position on the virtual desktop
    uint32_t width = 0, height = 0;    // current video mode, pixels
    int refreshHz = 0;
    bool primary = false;
};

// The monitors GLFW sees (glfwGetMonitors order: the primary first). Initialises GLFW if
// needed; throws MonitorError when there is no display connection.
std::vector<MonitorInfo> listMonitors();

// One line per monitor for --list-monitors:
//   "0: DP-1 3840x2160 @ 60 Hz at +0+0 (primary) - matches the panel 3840x2160"
std::string describeMonitors(const std::vector<MonitorInfo>& monitors, uint32_t panelWidth, uint32_t panelHeight);

// The monitor to use. `request`: empty = automatic, a decimal index, or a name (exact,
// else the only monitor whose name contains it, case-insensitive). Automatic picks the
// monitor whose mode is the panel size (for a Looking Glass visual.json that is the
// calibration's screenW x screenH), preferring a Looking Glass name ("LKG", "Looking
// Glass") and then a non-primary monitor (the panel is usually the second screen); with
// no match it refuses, or with allowMismatch takes the primary. An explicit monitor whose
// mode differs is refused unless allowMismatch. Throws MonitorError (one line).
size_t selectMonitor(const std::vector<MonitorInfo>& monitors, const std::string& request, uint32_t panelWidth,
                     uint32_t panelHeight, bool allowMismatch);

// Where the panel's top-left pixel lands on a monitor of the given mode: centred, unscaled,
// in image coordinates (row 0 = top); negative when the panel is larger (cropped).
struct PanelPlacement {
    int left = 0, top = 0;
};
PanelPlacement placePanel(uint32_t monitorWidth, uint32_t monitorHeight, uint32_t panelWidth, uint32_t panelHeight);

} // namespace lfd::player
