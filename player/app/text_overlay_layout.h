// Lines of text as coloured rectangles in window pixels: a semi-opaque dark box in the
// window's top-left corner and the glyphs over it, built from stb_easy_font's segment
// font (Debian libstb-dev; no font files, no textures). No GL here, so the layout is
// tested on the CPU; text_overlay_drawer.h draws the rectangles.
#pragma once

#include "window_readout.h"

#include <array>
#include <cstdint>
#include <vector>

namespace lfd::player {

// Window pixels, x right and y down from the top-left corner (GLFW's convention).
struct OverlayRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::array<uint8_t, 4> rgba{};
};

inline constexpr std::array<uint8_t, 4> kOverlayBoxColor{0, 0, 0, 191}; // 75% black: the output stays visible
inline constexpr std::array<uint8_t, 4> kOverlayTextColor{255, 255, 255, 255};
inline constexpr std::array<uint8_t, 4> kOverlayHighlightColor{255, 210, 0, 255};

struct OverlayLayout {
    int scale = 1;                  // font pixels per stb_easy_font unit
    OverlayRect box;                // rects.front()
    std::vector<OverlayRect> rects; // the box, then the glyphs' segments
};

// The box and glyphs for `lines` at the largest scale (up to 2, 3 on windows 2400 pixels
// wide or more) at which the box fits in the window; 1 if none does (the box is clipped
// then). Characters outside printable ASCII show as '?'. Empty `lines`: no rectangles.
OverlayLayout layoutOverlay(const std::vector<OverlayLine>& lines, int windowWidth, int windowHeight);

} // namespace lfd::player
