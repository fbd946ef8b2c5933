// Interactive lfd-play: a GLFW window showing the EIA, the quilt, one view or the simulated
// viewer's view - scaled to fit in a desktop window, or with --fullscreen the EIA 1:1 on
// the panel's monitor (monitor_selection.h). Keys (window_key_help.h): R renderer, C
// reconstruction, O displayed output, space pause/resume, Left/Right move the simulated
// viewer (and pick the single view), I the on-screen readout, H / F1 the key help, Esc
// quit; camera controls (drag, wheel, [ ] - = T Home) as in camera_controls.h. The
// readout (window_readout.h) is drawn over the output in a desktop window by default and
// fullscreen only when asked for (I, H, --readout), never into --screenshot. While the camera moves, frames render at preview quality (fewer,
// smaller views) and return to full quality when input stops. The title (and, fullscreen,
// a companion window on another monitor and a line on stdout) shows fps, frame pacing and
// per-stage GPU milliseconds of full and preview frames, refreshed about twice a second.
// With --frames F it renders F frames at t = k / fps and exits (after --screenshot).
#pragma once

#include "player_session.h"

namespace lfd::player {

// Creates the window and its context, then runs until closed. Returns the exit status.
int runWindowed(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                const std::string& packName);
// The same for a mapped pack: kStreamBytesPerFrame uploaded per frame until resident
// (docs/player/streaming.md), the title shows the progress.
inline constexpr uint64_t kStreamBytesPerFrame = uint64_t(64) << 20;
int runWindowedStreamed(const PlayOptions& options, const DisplayProfile& profile, std::shared_ptr<MappedPack> pack,
                        const std::string& packName);
// The same for --quilt-in: the views come from the quilt files.
int runWindowedQuilts(const PlayOptions& options, const DisplayProfile& profile,
                      std::vector<std::filesystem::path> quilts);

// --list-monitors: one line per monitor, saying whether it matches the panel.
int listMonitorsCommand(const DisplayProfile& profile);

} // namespace lfd::player
