#include "window_key_help.h"

#include <array>

namespace lfd::player {

namespace {

// note: window_app.cpp's onKey and cameraKey are the bindings themselves; this is what a
// user is told about them. The camera rows are the "Controls" table of
// docs/player/display.md, shortened.
constexpr std::array kBindings = {
    KeyBinding{"R", "next renderer"},
    KeyBinding{"C", "next reconstruction (--aa)"},
    KeyBinding{"O", "next output shown: EIA, quilt, single view, simulated viewer"},
    KeyBinding{"Space", "pause / resume"},
    KeyBinding{".", "one frame forward while paused"},
    KeyBinding{"Left / Right", "move the simulated viewer (and the single view shown)"},
    KeyBinding{"left drag", "orbit"},
    KeyBinding{"right or middle drag, Shift+left drag", "pan"},
    KeyBinding{"wheel", "zoom"},
    KeyBinding{"] / [", "focal plane nearer / farther"},
    KeyBinding{"= / -", "depthiness up / down"},
    KeyBinding{"T", "turntable on / off"},
    KeyBinding{"Home, Backspace", "reset the camera to the start-up state"},
    KeyBinding{"I", "readout on / off"},
    KeyBinding{"H, F1", "this key help on / off"},
    KeyBinding{"Esc", "quit"},
};

} // namespace

std::span<const KeyBinding> windowKeyBindings()
{
    return kBindings;
}

std::string keyBindingsSentence()
{
    std::string text;
    for (const KeyBinding& b : kBindings)
        text.append(text.empty() ? "" : "; ").append(b.keys).append(": ").append(b.action);
    return text + ".";
}

} // namespace lfd::player
