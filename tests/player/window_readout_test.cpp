// The window's on-screen readout without a window: its lines for a given state, when it
// is shown (off fullscreen until asked, the camera line while focus or depthiness change),
// the frame-time average, the text layout (box in the top-left corner, glyphs inside it,
// scale, columns), and the key help table against docs/player/display.md and the key handler. The
// drawn overlay is tested under Xvfb in display_window_test.cpp.
#include "text_overlay_layout.h"
#include "tool_run.h"
#include "window_key_help.h"
#include "window_readout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace lfd::test {
namespace {

using player::OverlayLine;

player::ReadoutState sceneState()
{
    player::ReadoutState s;
    s.renderer = "lfdpr";
    s.reconstruction = "spatial";
    s.shown = "EIA";
    s.views = 48;
    s.viewWidth = 480;
    s.viewHeight = 360;
    s.outputWidth = 3840;
    s.outputHeight = 2160;
    s.windowWidth = 1280;
    s.windowHeight = 800;
    s.frameMs = 40.0;
    s.camera = player::CameraReadout{-12.3, 1.1};
    return s;
}

std::vector<std::string> texts(const std::vector<OverlayLine>& lines)
{
    std::vector<std::string> out;
    for (const OverlayLine& l : lines)
        out.push_back(l.text);
    return out;
}

TEST(WindowReadout, LinesReportRendererViewsOutputFrameTimeAndCamera)
{
    const std::vector<OverlayLine> lines = player::readoutLines(sceneState(), false);
    EXPECT_EQ(texts(lines), (std::vector<std::string>{
                                "renderer\tlfdpr, reconstruction spatial",
                                "views\t48 of 480x360",
                                "shown\tEIA 3840x2160 in a 1280x800 window",
                                "frame\t40.0 ms, 25.0 fps",
                                "camera\tfocal plane -12.3 mm, depthiness 1.10",
                                "keys\tI readout, H key help",
                            }));
    for (const OverlayLine& l : lines)
        EXPECT_FALSE(l.highlight) << l.text;
    // Changing: the camera line is highlighted, and it is the one line shown alone.
    EXPECT_TRUE(player::readoutLines(sceneState(), true)[4].highlight);
    const std::vector<OverlayLine> alone = player::cameraLines(sceneState());
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_EQ(alone[0].text, lines[4].text);
    EXPECT_TRUE(alone[0].highlight);

    // A preview frame, paused, before any frame time, quilt input (no camera).
    player::ReadoutState s = sceneState();
    s.renderer = "quilt-in";
    s.views = 24;
    s.viewWidth = 240;
    s.viewHeight = 180;
    s.preview = s.paused = true;
    s.frameMs.reset();
    s.camera.reset();
    const std::vector<std::string> other = texts(player::readoutLines(s, true));
    EXPECT_EQ(other[1], "views\t24 of 240x180 (preview)");
    EXPECT_EQ(other[3], "frame\tmeasuring (paused)");
    EXPECT_EQ(std::count_if(other.begin(), other.end(), [](const std::string& t) { return t.starts_with("camera"); }),
              0);
    EXPECT_TRUE(player::cameraLines(s).empty());
}

TEST(WindowReadout, ShownInADesktopWindowOffFullscreenUntilAsked)
{
    const player::ReadoutState s = sceneState();
    // Defaults: a desktop window shows the readout, the panel gets nothing.
    player::ReadoutToggles window(std::nullopt, false), panel(std::nullopt, true);
    EXPECT_TRUE(window.readout());
    EXPECT_EQ(texts(window.lines(s, 0.0)), texts(player::readoutLines(s, false)));
    EXPECT_FALSE(panel.readout());
    EXPECT_TRUE(panel.lines(s, 0.0).empty());
    // --readout / --no-readout win over the default.
    EXPECT_TRUE(player::ReadoutToggles(true, true).readout());
    EXPECT_FALSE(player::ReadoutToggles(false, false).readout());
    // Asked for on the panel (I), then the key help (H) below it, a blank line between.
    panel.toggleReadout();
    panel.toggleHelp();
    const std::vector<OverlayLine> both = panel.lines(s, 0.0);
    const size_t readoutSize = player::readoutLines(s, false).size();
    ASSERT_EQ(both.size(), readoutSize + 1 + player::keyHelpLines().size());
    EXPECT_EQ(both[readoutSize].text, "");
    EXPECT_EQ(both[readoutSize + 1].text, "Keys and mouse");
    panel.toggleReadout();
    EXPECT_EQ(texts(panel.lines(s, 0.0)), texts(player::keyHelpLines()));
    panel.toggleHelp();
    EXPECT_TRUE(panel.lines(s, 0.0).empty());
}

TEST(WindowReadout, FocusAndDepthinessChangesShowForTwoSeconds)
{
    const player::ReadoutState s = sceneState();
    player::ReadoutToggles window(false, false), panel(std::nullopt, true), shown(true, false);
    for (player::ReadoutToggles* t : {&window, &panel, &shown})
        t->cameraChanged(10.0);
    // Readout off in a desktop window: the camera line alone, for kCameraHighlightSeconds.
    EXPECT_EQ(texts(window.lines(s, 10.0)), texts(player::cameraLines(s)));
    EXPECT_EQ(texts(window.lines(s, 11.9)), texts(player::cameraLines(s)));
    EXPECT_TRUE(window.lines(s, 12.0).empty());
    // Fullscreen without the readout: nothing lands on the panel.
    EXPECT_TRUE(panel.lines(s, 10.5).empty());
    // With the readout: the camera line is highlighted, then plain again.
    EXPECT_TRUE(shown.lines(s, 11.0)[4].highlight);
    EXPECT_FALSE(shown.lines(s, 12.5)[4].highlight);
}

TEST(WindowReadout, FrameTimeIsTheMeanSwapIntervalOverHalfASecond)
{
    const double kHalf = player::kFrameAverageSeconds;
    player::FrameTimeAverage average;
    EXPECT_FALSE(average.meanMs());
    // 10 ms frames: nothing until half a second has passed, then their mean.
    double t = 100.0;
    average.swapped(t);
    for (int i = 0; i < 49; ++i)
        average.swapped(t += 0.010);
    EXPECT_FALSE(average.meanMs());
    average.swapped(t += 0.010);
    ASSERT_TRUE(average.meanMs());
    EXPECT_NEAR(*average.meanMs(), 10.0, 1e-9);
    // The next period: 20 ms and 40 ms frames alternate; the number holds until half a
    // second has passed, then becomes the mean of exactly that period's intervals.
    double sum = 0.0, start = t;
    int count = 0;
    for (int i = 0; i < 30; ++i) {
        const double dt = i % 2 ? 0.040 : 0.020;
        average.swapped(t += dt);
        sum += dt;
        ++count;
        if (t - start < kHalf) {
            EXPECT_NEAR(*average.meanMs(), 10.0, 1e-9) << "published early, after " << count << " frames";
        } else {
            EXPECT_NEAR(*average.meanMs(), 1000.0 * sum / count, 1e-9);
            EXPECT_NEAR(*average.meanMs(), 30.0, 1.5);
            break;
        }
    }
}

// ---- layout ------------------------------------------------------------------------------

TEST(TextOverlayLayout, BoxInTheTopLeftCornerGlyphsInsideScaledToFit)
{
    const std::vector<OverlayLine> lines = player::readoutLines(sceneState(), true);
    const player::OverlayLayout big = player::layoutOverlay(lines, 1280, 800);
    EXPECT_EQ(big.scale, 2);
    ASSERT_GT(big.rects.size(), 200u);
    const player::OverlayRect& box = big.rects.front();
    EXPECT_EQ(box.rgba, player::kOverlayBoxColor);
    EXPECT_EQ(box.x0, 8.0f);
    EXPECT_EQ(box.y0, 8.0f);
    EXPECT_LE(box.x1, 1280.0f);
    EXPECT_LE(box.y1, 800.0f);
    // Six lines of 12 units plus padding, at scale 2.
    EXPECT_EQ(box.y1 - box.y0, float((6 * 12 + 8) * 2));
    size_t highlighted = 0;
    for (size_t i = 1; i < big.rects.size(); ++i) {
        const player::OverlayRect& r = big.rects[i];
        EXPECT_TRUE(r.x0 >= box.x0 && r.x1 <= box.x1 && r.y0 >= box.y0 && r.y1 <= box.y1) << i;
        EXPECT_LT(r.x0, r.x1);
        EXPECT_LT(r.y0, r.y1);
        // Whole pixels: segment edges land on pixel edges, so glyphs are crisp.
        EXPECT_EQ(r.x0, std::floor(r.x0));
        EXPECT_EQ(r.y1, std::floor(r.y1));
        highlighted += r.rgba == player::kOverlayHighlightColor;
        EXPECT_TRUE(r.rgba == player::kOverlayHighlightColor || r.rgba == player::kOverlayTextColor);
    }
    EXPECT_GT(highlighted, 20u) << "the camera line is drawn in the highlight colour";
    // A small window gets scale 1 (and the same box, half the size).
    const player::OverlayLayout small = player::layoutOverlay(lines, 480, 270);
    EXPECT_EQ(small.scale, 1);
    EXPECT_EQ(small.rects.size(), big.rects.size());
    EXPECT_EQ((small.box.x1 - small.box.x0) * 2, big.box.x1 - big.box.x0);
    EXPECT_EQ(player::layoutOverlay(lines, 3840, 2160).scale, 3);
    EXPECT_TRUE(player::layoutOverlay({}, 1280, 800).rects.empty());
}

TEST(TextOverlayLayout, TabsAlignAColumnAndOddCharactersShowAsQuestionMarks)
{
    // The right part of both lines is the same glyph in the same column: same x extent.
    const player::OverlayLayout layout = player::layoutOverlay({{"a\tX"}, {"abcdefgh\tX"}}, 200, 100);
    float right[2] = {0, 0};
    for (size_t i = 1; i < layout.rects.size(); ++i) {
        const player::OverlayRect& r = layout.rects[i];
        // Line i's glyphs start 4 + 12 i font units below the box's top (the padding, then a
        // 12-unit line advance); descenders reach below the next line's start, so the line is
        // found from the glyph's top less the padding, never past the last line.
        const int line = int((r.y0 - layout.box.y0 - float(4 * layout.scale)) / float(12 * layout.scale));
        ASSERT_GE(line, 0);
        ASSERT_LT(line, 2);
        right[line] = std::max(right[line], r.x1);
    }
    EXPECT_GT(right[0], 0.0f);
    EXPECT_EQ(right[0], right[1]);
    // After a blank line a new block starts its own column (the readout's values do not
    // move right for the key help's long key names).
    const player::OverlayLayout blocks = player::layoutOverlay({{"a\tX"}, {""}, {"abcdefgh\tX"}}, 200, 100);
    float blockRight[3] = {0, 0, 0};
    for (size_t i = 1; i < blocks.rects.size(); ++i) {
        const player::OverlayRect& r = blocks.rects[i];
        const int line = int((r.y0 - blocks.box.y0 - float(4 * blocks.scale)) / float(12 * blocks.scale));
        ASSERT_GE(line, 0);
        ASSERT_LT(line, 3);
        blockRight[line] = std::max(blockRight[line], r.x1);
    }
    EXPECT_EQ(blockRight[1], 0.0f);
    EXPECT_LT(blockRight[0], blockRight[2]);
    // UTF-8 (and any byte outside ' '..'~') is drawn as '?', never read past stb's tables.
    auto same = [](const player::OverlayLayout& a, const player::OverlayLayout& b) {
        if (a.rects.size() != b.rects.size())
            return false;
        for (size_t i = 0; i < a.rects.size(); ++i)
            if (a.rects[i].x0 != b.rects[i].x0 || a.rects[i].y0 != b.rects[i].y0 || a.rects[i].x1 != b.rects[i].x1)
                return false;
        return true;
    };
    EXPECT_TRUE(same(player::layoutOverlay({{"caf\xc3\xa9\x7f"}}, 200, 100),
                     player::layoutOverlay({{"caf???"}}, 200, 100)));
}

// ---- key help: one table, the manual's and the key handler's -----------------------------

// The table lives in lfd-play's manual, docs/player/display.md "On-screen readout and window keys".
TEST(WindowKeyHelp, ManualTableIsTheKeyHelpTable)
{
    const std::string manual = readBytes(std::filesystem::path(LFD_SOURCE_DIR) / "docs/player/display.md");
    const size_t begin = manual.find("<!-- window-keys -->"), end = manual.find("<!-- /window-keys -->");
    ASSERT_NE(begin, std::string::npos) << "docs/player/display.md has no <!-- window-keys --> table";
    ASSERT_NE(end, std::string::npos);
    std::istringstream block(manual.substr(begin, end - begin));
    std::vector<std::pair<std::string, std::string>> rows;
    const std::regex row(R"(^\|\s*(.*?)\s*\|\s*(.*?)\s*\|\s*$)");
    for (std::string line; std::getline(block, line);) {
        std::smatch m;
        if (!std::regex_match(line, m, row) || m[1] == "keys" || m[1].str().starts_with("---"))
            continue;
        auto plain = [](std::string s) {
            s.erase(std::remove(s.begin(), s.end(), '`'), s.end());
            return s;
        };
        rows.emplace_back(plain(m[1]), plain(m[2]));
    }
    const auto table = player::windowKeyBindings();
    ASSERT_EQ(rows.size(), table.size()) << "docs/player/display.md's window keys table and window_key_help.cpp differ in length";
    for (size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].first, table[i].keys) << "row " << i;
        EXPECT_EQ(rows[i].second, table[i].action) << "row " << i;
    }
    // The on-screen help and --help show the same rows.
    const std::vector<OverlayLine> help = player::keyHelpLines();
    ASSERT_EQ(help.size(), table.size() + 1);
    EXPECT_EQ(help[1].text, std::string(table[0].keys) + "\t" + std::string(table[0].action));
    EXPECT_NE(player::keyBindingsSentence().find("I: readout on / off; H, F1: this key help on / off"),
              std::string::npos);
}

// Every key window_app.cpp handles is in the table (keypad aliases of = and - aside).
TEST(WindowKeyHelp, EveryHandledKeyIsListed)
{
    const std::string source = readBytes(std::filesystem::path(LFD_SOURCE_DIR) / "player/app/window_app.cpp");
    const std::map<std::string, std::string> label = {
        {"SPACE", "Space"}, {"PERIOD", "."},      {"LEFT", "Left"},  {"RIGHT", "Right"},     {"ESCAPE", "Esc"},
        {"F1", "F1"},       {"RIGHT_BRACKET", "]"}, {"LEFT_BRACKET", "["}, {"EQUAL", "="},   {"MINUS", "-"},
        {"HOME", "Home"},   {"BACKSPACE", "Backspace"}};
    std::set<std::string> listed;
    for (const player::KeyBinding& b : player::windowKeyBindings()) {
        std::string keys(b.keys);
        std::replace(keys.begin(), keys.end(), ',', ' ');
        std::istringstream words(keys);
        for (std::string w; words >> w;)
            listed.insert(w);
    }
    const std::regex handled(R"(case GLFW_KEY_([A-Z0-9_]+):)");
    size_t keys = 0;
    for (std::sregex_iterator it(source.begin(), source.end(), handled), stop; it != stop; ++it) {
        const std::string name = (*it)[1];
        if (name.starts_with("KP_"))
            continue;
        const std::string expected = name.size() == 1 ? name : label.count(name) ? label.at(name) : "GLFW_KEY_" + name;
        EXPECT_TRUE(listed.count(expected)) << "GLFW_KEY_" << name << " is handled but not in the key help";
        ++keys;
    }
    EXPECT_GE(keys, 18u) << "window_app.cpp's key handler was not found";
}

} // namespace
} // namespace lfd::test
