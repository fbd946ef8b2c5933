// Interactive lfd-play: a GLFW window showing the EIA, the quilt, one view or the simulated
// viewer's view, scaled to fit. Keys: R renderer, C reconstruction, O displayed output,
// space pause/resume, Left/Right move the simulated viewer (and pick the single view),
// Esc quit. The title shows per-stage GPU milliseconds, refreshed about twice a second.
// With --frames F it renders F frames at t = k / fps and exits (after --screenshot).
#pragma once

#include "player_session.h"

namespace lfd::player {

// Creates the window and its context, then runs until closed. Returns the exit status.
int runWindowed(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                const std::string& packName);

} // namespace lfd::player
