// The window's keys and mouse controls as one table. The on-screen key help (H or F1,
// window_readout.h), lfd-play --help's footer and the window keys table of
// docs/player/display.md "On-screen readout and window keys" all show this table;
// tests/player/window_readout_test.cpp holds that manual to it, so a key added
// here and not there (or the other way round) fails a test instead of going undocumented.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace lfd::player {

struct KeyBinding {
    std::string_view keys;   // as the manual writes them, e.g. "] / [" or "Home, Backspace"
    std::string_view action; // what they do, short enough for one line of the key help
};

// In the order the key help lists them.
std::span<const KeyBinding> windowKeyBindings();

// "R: next renderer; C: next reconstruction (--aa); ..." for lfd-play --help.
std::string keyBindingsSentence();

} // namespace lfd::player
