// The built-in neutral studio (`--environment neutral`, the default): generated here,
// deterministic, nothing to ship. A grey room whose walls brighten towards the ceiling
// over a darker floor, joined across a soft horizon, and three rectangular softboxes: a key
// light above and to the left of glTF's default camera (which stands at +Z looking at -Z,
// +X to its right; 44 x 28 degrees, 45 degrees left, 35 up), a tall fill strip low on its
// right (16 x 48, 60 right, 10 up) and a wide rim light high behind the object (56 x 16,
// 55 up). Pure grey (R = G = B), so it adds no colour cast; a mirror sphere shows the
// boxes, the horizon and the floor, a rough one a gradient from the key.
// Radiances: softboxes 3, the room 0.06 (floor) to 0.12 (walls at the horizon) to 0.25
// (zenith). A white Lambert surface facing up (E / pi = 0.636) lands at sRGB level 203 at
// exposure 0 after PBR Neutral (tone_map.h). The edges are soft (softboxes +-6 degrees,
// horizon +-4): the split sum cannot follow a sharp bright edge under a rough lobe
// (ibl_accuracy_test), and a studio's diffusers are soft anyway. 1024 x 512.
#pragma once

#include "environment.h"

namespace lfd::lighting {

constexpr uint32_t kNeutralEnvironmentWidth = 1024;
constexpr uint32_t kNeutralEnvironmentHeight = 512;

Environment neutralEnvironment();

} // namespace lfd::lighting
