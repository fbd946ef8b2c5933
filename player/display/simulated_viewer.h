// Simulated viewer: what one eye sees through the lenticular sheet, reconstructed from an
// EIA. It closes the loop views -> EIA -> views, so the EIA mapping can be tested without a
// physical display (the "EIA round trip") and EIAs can be previewed as ordinary images.
//
// Model: an eye at horizontal viewing position t in [0, N) (view units: t = i + 0.5 is the
// centre of view i's interval, t wraps around with the lens period) sees, through each
// lens, the subpixels whose phase * N is closest to t. For every output pixel (view
// resolution, same screen position as a view pixel) and every colour channel, the panel
// subpixels of that channel inside the pixel's screen footprint (widened horizontally to at
// least one lens width, so every phase of the lens is present) are gathered; those with
// phase * N - t in [-1/2, 1/2) (circularly) are averaged — for t = i + 0.5 these are
// exactly the subpixels the nearest-view EIA took from view i. If none falls in that
// interval (a footprint of one lens by R rows holds X R / (3N) subpixels per view and
// colour, ~1 on the prototype, so it happens), the nearest subpixels below and above t
// are interpolated linearly.
#pragma once

#include "lfd/display_profile.h"

#include <cstdint>
#include <vector>

namespace lfd::player {

// eia: RGBA8, panel size, rows top to bottom. Returns RGBA8 of profile.viewWidth x
// profile.viewHeight, rows top to bottom, alpha 255. Multithreaded over output rows.
// Throws std::invalid_argument on a wrong EIA size or a t outside [0, N).
std::vector<uint8_t> simulateViewer(const DisplayProfile& profile,
                                    const std::vector<uint8_t>& eia, double t);

} // namespace lfd::player
