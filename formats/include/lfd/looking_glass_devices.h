// The Looking Glass devices the toolkit knows, each with its vendor's standard quilt (the
// layout Looking Glass tools render and expect for that display). A profile is matched to
// a device by its panel's pixels and physical width (within 3%), so a visual.json of that
// device - or any profile describing the same panel - gets the device's quilt. The values
// and their source are listed in formats/display_profiles.md section 3.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace lfd {

struct StandardQuilt {
    std::string device;          // "Looking Glass Portrait"
    uint32_t cols = 0, rows = 0; // tiles; views = cols * rows
    uint32_t width = 0, height = 0; // whole quilt in pixels (may exceed cols * tile)
    uint32_t tileWidth() const { return width / cols; }
    uint32_t tileHeight() const { return height / rows; }
};

// The standard quilt of the device with this panel, or nullopt for other panels.
std::optional<StandardQuilt> standardQuiltFor(uint32_t panelWidth, uint32_t panelHeight, double screenWidthMm);

} // namespace lfd
