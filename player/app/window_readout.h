// What the window's on-screen readout says and when it is shown, without any GL: the
// lines (renderer, views, shown output, frame time and fps, focal plane and depthiness),
// the key help's lines, the frame-time average behind the numbers, and the toggles.
// text_overlay_layout.h turns the lines into rectangles, text_overlay_drawer.h draws them
// into the window after the output (never into --screenshot, --out or headless images).
//
// Shown by default in a desktop window; off when the window is fullscreen on the panel,
// so the EIA reaches the lenses untouched, until asked for (I / H, or --readout).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lfd::player {

// One line of the overlay. A '\t' in `text` moves the rest to a column shared by the
// lines of its block (up to a blank line): the readout's values, the key help's actions.
// `highlight` draws the line in the accent colour.
struct OverlayLine {
    std::string text;
    bool highlight = false;
};

// The focal plane and depthiness steered by ] [ = - (docs/player/display.md "Controls").
struct CameraReadout {
    double focalDepthMm = 0.0;
    double depthiness = 1.0;
};

// A frame's state as the readout reports it.
struct ReadoutState {
    std::string renderer;       // "mvr", ...; "quilt-in" for quilt input
    std::string reconstruction; // --aa name
    std::string shown;          // "EIA", "quilt", "single view", "simulated viewer"
    uint32_t views = 0, viewWidth = 0, viewHeight = 0; // of the last frame (a preview's are fewer, smaller)
    uint32_t outputWidth = 0, outputHeight = 0;        // the shown output's own size
    uint32_t windowWidth = 0, windowHeight = 0;
    bool preview = false, paused = false;
    std::optional<double> frameMs;       // mean frame interval (FrameTimeAverage); none yet
    std::optional<CameraReadout> camera; // none for quilt input (no camera to steer)
};

// The readout's lines; the camera line is highlighted when `highlightCamera`.
std::vector<OverlayLine> readoutLines(const ReadoutState& state, bool highlightCamera);
// The camera line alone (highlighted): shown briefly while focus or depthiness change
// with the readout off. Empty without a camera.
std::vector<OverlayLine> cameraLines(const ReadoutState& state);
// A title line and one line per windowKeyBindings() row, keys and action in two columns.
std::vector<OverlayLine> keyHelpLines();

// Mean interval between buffer swaps, published once per kFrameAverageSeconds so the
// digits stay readable (a per-frame number flickers).
inline constexpr double kFrameAverageSeconds = 0.5;
class FrameTimeAverage {
public:
    void swapped(double nowSeconds);
    // The last published mean in milliseconds; none before the first full period.
    std::optional<double> meanMs() const { return meanMs_; }

private:
    double last_ = -1.0, periodStart_ = -1.0, sum_ = 0.0;
    uint32_t count_ = 0;
    std::optional<double> meanMs_;
};

// How long the focal plane and depthiness stay highlighted (or shown alone) after a change.
inline constexpr double kCameraHighlightSeconds = 2.0;

// Which parts of the overlay are shown: I toggles the readout, H the key help.
class ReadoutToggles {
public:
    // `flag`: --readout (true) / --no-readout (false), unset: shown unless fullscreen.
    ReadoutToggles(std::optional<bool> flag, bool fullscreen)
        : readout_(flag.value_or(!fullscreen)), fullscreen_(fullscreen)
    {
    }
    void toggleReadout() { readout_ = !readout_; }
    void toggleHelp() { help_ = !help_; }
    // The focal plane or depthiness changed at `now` (seconds).
    void cameraChanged(double now) { cameraChangedAt_ = now; }

    bool readout() const { return readout_; }
    bool help() const { return help_; }
    bool cameraRecent(double now) const { return now - cameraChangedAt_ < kCameraHighlightSeconds; }
    // The camera line alone while it changes with the readout off - in a desktop window
    // only: on the panel nothing is drawn that was not asked for.
    bool cameraAlone(double now) const { return !readout_ && !fullscreen_ && cameraRecent(now); }

    // The overlay's lines now: readout, key help (a blank line between), or the camera
    // line alone; empty when nothing is shown.
    std::vector<OverlayLine> lines(const ReadoutState& state, double now) const;

private:
    bool readout_, fullscreen_;
    bool help_ = false;
    double cameraChangedAt_ = -1e300;
};

} // namespace lfd::player
