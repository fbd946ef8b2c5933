// Driving a display under Xvfb: --fullscreen on a screen of the panel's size shows the
// headless EIA pixel for pixel (captured from the X server's framebuffer, not from the
// program), a monitor of another size is refused (or, with --allow-mismatch, shows the EIA
// centred and unscaled), --list-monitors, the camera controls and the responsive
// preview driven by mouse and keys through xdotool, and the on-screen readout and key help
// (I, H: over the output in a window, on the panel only when asked, never in a
// --screenshot). Skipped without Xvfb / xdotool.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"
#include "tool_run.h"
#include "xvfb_support.h"

#include "image_metrics.h"
#include "quilt_video.h"
#include "text_overlay_layout.h"

#include "lfd/pack.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <climits>
#include <csignal>
#include <functional>
#include <cstdio>
#include <fstream>
#include <thread>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;


// Where two screen captures differ: how many pixels, and their bounding box.
struct Difference {
    size_t count = 0;
    uint32_t x0 = UINT_MAX, y0 = UINT_MAX, x1 = 0, y1 = 0;
};
Difference difference(const metrics::Image& a, const metrics::Image& b)
{
    Difference d;
    for (uint32_t y = 0; y < std::min(a.height, b.height); ++y)
        for (uint32_t x = 0; x < std::min(a.width, b.width); ++x) {
            const size_t i = (size_t(y) * a.width + x) * 3;
            if (a.pixels[i] == b.pixels[i] && a.pixels[i + 1] == b.pixels[i + 1] && a.pixels[i + 2] == b.pixels[i + 2])
                continue;
            ++d.count;
            d.x0 = std::min(d.x0, x);
            d.y0 = std::min(d.y0, y);
            d.x1 = std::max(d.x1, x);
            d.y1 = std::max(d.y1, y);
        }
    return d;
}

bool isColour(const metrics::Image& image, size_t pixel, const std::array<uint8_t, 4>& rgba)
{
    return std::equal(rgba.begin(), rgba.begin() + 3, image.pixels.begin() + std::ptrdiff_t(pixel * 3));
}

// Pixels that are the overlay colour `rgba` in `after` and were not in `before`: glyphs,
// drawn opaque in exact colours (the box under them leaves a quarter of the output).
size_t becameColour(const metrics::Image& before, const metrics::Image& after, const std::array<uint8_t, 4>& rgba)
{
    size_t count = 0;
    for (size_t p = 0; p < size_t(after.width) * after.height && p * 3 < before.pixels.size(); ++p)
        count += isColour(after, p, rgba) && !isColour(before, p, rgba);
    return count;
}

// Xvfb of a given screen with a pack and the 384x216 test panel profile in a fresh folder.
class DisplayWindowTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (findXvfb().empty() || !fs::exists("/usr/bin/xdotool"))
            LFD_SKIP_OR_FAIL("Xvfb or xdotool not installed; driving a display not tested");
        ASSERT_TRUE(fs::exists(kPlay)) << kPlay << " not built";
        dir_ = testOutputDir(std::string("display_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        writePack(dir_ / "scene.lfdpack", cubeAndSphereScene());
        std::ofstream(dir_ / "panel.json") << tenthPrototypeProfileJson("panel-384");
        common_ = quoted(dir_ / "scene.lfdpack") + " --display " + quoted(dir_ / "panel.json") + " --views 8 --view-size 48x36";
    }
    void startServer(const std::string& screen)
    {
        fs::create_directories(dir_ / "fb");
        server_ = std::make_unique<XvfbServer>(findXvfb(), screen, dir_ / "fb");
        ASSERT_FALSE(server_->display().empty()) << "could not start Xvfb";
        env_ = "DISPLAY=" + server_->display() + " ";
    }
    // Runs lfd-play to the end; returns the exit status, stderr in `err`.
    int run(const std::string& args, std::string& err)
    {
        const int raw = std::system((env_ + quoted(kPlay) + " " + args + " > " + quoted(dir_ / "out.txt") + " 2> " +
                                     quoted(dir_ / "err.txt"))
                                        .c_str());
        err = readBytes(dir_ / "err.txt");
        return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    }
    // Starts lfd-play in the background and waits for its window to have drawn a frame
    // (the title carries frame times after the first swap); returns the window id.
    std::string start(const std::string& args)
    {
        const fs::path pidFile = dir_ / "play.pid";
        const std::string command = env_ + quoted(kPlay) + " " + args + " > " + quoted(dir_ / "play.log") + " 2>&1 & echo $! > " +
                                    quoted(pidFile);
        EXPECT_EQ(std::system(command.c_str()), 0);
        std::ifstream(pidFile) >> pid_;
        std::string window;
        for (int i = 0; i < 300 && window.empty(); ++i) {
            window = capture(env_ + "xdotool search --name '^lfd-play' 2>/dev/null | head -n 1");
            if (window.empty())
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        EXPECT_FALSE(window.empty()) << "no lfd-play window: " << readBytes(dir_ / "play.log");
        window_ = window;
        if (!window.empty())
            titleContains("| full: total");
        return window;
    }
    // Waits until the title contains `text` (refreshed about twice a second).
    std::string titleContains(const std::string& text, int tenths = 200)
    {
        std::string title;
        for (int i = 0; i < tenths; ++i) {
            title = capture(env_ + "xdotool getwindowname " + window_);
            if (title.find(text) != std::string::npos)
                return title;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        ADD_FAILURE() << "window title never contained \"" << text << "\"; last: " << title;
        return title;
    }
    // Reads the screen until `done` holds for it (about 30 s at most); returns the last read.
    metrics::Image screenUntil(const std::function<bool(const metrics::Image&)>& done, const std::string& what)
    {
        metrics::Image screen;
        for (int i = 0; i < 300; ++i) {
            screen = server_->readScreen();
            // Xvfb writes its framebuffer file while we read it: a read can hold the top of
            // one frame and the bottom of the next. Only a screen read twice alike counts.
            if (done(screen)) {
                std::this_thread::sleep_for(std::chrono::milliseconds(30));
                if (server_->readScreen().pixels == screen.pixels)
                    return screen;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        ADD_FAILURE() << "the screen never showed " << what;
        return screen;
    }
    void send(const std::string& what) { std::system((env_ + "xdotool " + what + " >/dev/null 2>&1").c_str()); }
    void quit()
    {
        send("key --window " + window_ + " Escape");
        bool gone = false;
        for (int i = 0; i < 100 && !gone; ++i) {
            gone = pid_ <= 0 || kill(pid_, 0) != 0;
            if (!gone)
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        if (!gone) {
            kill(pid_, SIGTERM);
            ADD_FAILURE() << "lfd-play did not quit on Escape";
        }
        pid_ = -1;
    }
    void TearDown() override
    {
        if (pid_ > 0)
            kill(pid_, SIGTERM);
    }
    // The headless EIA of the same frame (no turntable, so every frame is this one).
    metrics::Image headlessEia()
    {
        std::string err;
        EXPECT_EQ(run("--headless " + common_ + " --no-turntable --out " + quoted(dir_ / "eia.png"), err), 0) << err;
        return metrics::readImage(dir_ / "eia.png", 3);
    }

    fs::path dir_;
    std::string common_, env_, window_;
    std::unique_ptr<XvfbServer> server_;
    pid_t pid_ = -1;
};

// The acceptance check: on a screen of the panel's size, what the X server shows
// equals the headless EIA of the same frame, exactly (no scaling, filtering, sRGB
// conversion or offset).
TEST_F(DisplayWindowTest, FullscreenShowsTheHeadlessEiaPixelForPixel)
{
    startServer("384x216x24");
    const metrics::Image eia = headlessEia();
    start(common_ + " --no-turntable --fullscreen");
    const metrics::Image screen = server_->readScreen();
    ASSERT_EQ(screen.width, 384u);
    ASSERT_EQ(screen.height, 216u);
    EXPECT_TRUE(screen.pixels == eia.pixels) << "max difference " << metrics::maxAbsDiff(screen, eia);
    metrics::writeImage(dir_ / "screen.png", screen);
    quit();
    const std::string log = readBytes(dir_ / "play.log");
    EXPECT_NE(log.find("fullscreen on monitor 0 'screen' 384x216"), std::string::npos) << log;
    EXPECT_NE(log.find("(pixel for pixel)"), std::string::npos) << log;
    EXPECT_NE(log.find("lfd-play: "), std::string::npos);
    EXPECT_NE(log.find("| full: total"), std::string::npos) << "stdout readout (no title bar fullscreen): " << log;
    EXPECT_NE(log.find("fps over the run"), std::string::npos) << log;

    // The back buffer (--screenshot) agrees too.
    std::string err;
    ASSERT_EQ(run(common_ + " --no-turntable --fullscreen --frames 2 --screenshot " + quoted(dir_ / "shot.png"), err), 0)
        << err;
    EXPECT_TRUE(metrics::readImage(dir_ / "shot.png", 3).pixels == eia.pixels);
}

// --first-frame in a window: with --frames N the window renders frames F .. F + N - 1, so the
// back buffer after the last one is the headless EIA of frame F + N - 1 (turntable on, so
// every frame differs).
TEST_F(DisplayWindowTest, FirstFrameStartsTheWindowsAnimationThere)
{
    startServer("384x216x24");
    std::string err;
    const std::string timing = common_ + " --fps 4";
    ASSERT_EQ(run("--headless " + timing + " --first-frame 5 --out " + quoted(dir_ / "eia5.png"), err), 0) << err;
    ASSERT_EQ(run("--headless " + timing + " --out " + quoted(dir_ / "eia0.png"), err), 0) << err;
    const metrics::Image frame5 = metrics::readImage(dir_ / "eia5.png", 3);
    ASSERT_GT(metrics::rmse(frame5, metrics::readImage(dir_ / "eia0.png", 3)), 1.0) << "the turntable turns";
    ASSERT_EQ(run(timing + " --fullscreen --first-frame 3 --frames 3 --screenshot " + quoted(dir_ / "shot5.png"), err), 0)
        << err;
    const metrics::Image shot = metrics::readImage(dir_ / "shot5.png", 3);
    EXPECT_TRUE(shot.pixels == frame5.pixels) << "max difference " << metrics::maxAbsDiff(shot, frame5);
}

TEST_F(DisplayWindowTest, MismatchedMonitorIsRefusedOrCentredUnscaled)
{
    startServer("640x400x24");
    std::string err;
    EXPECT_EQ(run(common_ + " --fullscreen", err), 1);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("640x400"), std::string::npos) << err;
    EXPECT_NE(err.find("384x216"), std::string::npos) << err;
    EXPECT_NE(err.find("refused"), std::string::npos) << err;
    EXPECT_EQ(run(common_ + " --fullscreen --monitor 0", err), 1);
    EXPECT_NE(err.find("monitor 0 'screen' runs at 640x400"), std::string::npos) << err;

    ASSERT_EQ(run("--list-monitors --display " + quoted(dir_ / "panel.json"), err), 0) << err;
    EXPECT_EQ(readBytes(dir_ / "out.txt"), "0: screen 640x400 @ 0 Hz at +0+0 (primary) - does not match the panel 384x216\n");

    // --allow-mismatch: the EIA unscaled at ((640 - 384) / 2, (400 - 216) / 2) = (128, 92), black around it.
    const metrics::Image eia = headlessEia();
    start(common_ + " --no-turntable --fullscreen --allow-mismatch");
    const metrics::Image screen = server_->readScreen();
    quit();
    // The readout lines start once something is measured: no empty "lfd-play: " line, also
    // for a one-frame run whose only readout comes before any frame time is known.
    const std::string log = readBytes(dir_ / "play.log");
    EXPECT_EQ(("\n" + log).find("\nlfd-play: \n"), std::string::npos) << log;
    EXPECT_NE(log.find("mismatch allowed"), std::string::npos) << log;
    ASSERT_EQ(run(common_ + " --fullscreen --allow-mismatch --frames 1", err), 0) << err;
    const std::string oneFrame = readBytes(dir_ / "out.txt");
    EXPECT_EQ(("\n" + oneFrame).find("\nlfd-play: \n"), std::string::npos) << oneFrame;
    ASSERT_EQ(screen.width, 640u);
    size_t differing = 0, litOutside = 0;
    for (uint32_t y = 0; y < 400; ++y)
        for (uint32_t x = 0; x < 640; ++x) {
            const uint8_t* s = &screen.pixels[(size_t(y) * 640 + x) * 3];
            const bool inside = x >= 128 && x < 512 && y >= 92 && y < 308;
            if (!inside) {
                litOutside += s[0] + s[1] + s[2] > 0;
                continue;
            }
            const uint8_t* e = &eia.pixels[(size_t(y - 92) * 384 + (x - 128)) * 3];
            differing += s[0] != e[0] || s[1] != e[1] || s[2] != e[2];
        }
    EXPECT_EQ(differing, 0u);
    EXPECT_EQ(litOutside, 0u);
}

// Mouse and keys change the camera as documented (the title reports the state), and a
// drag renders preview frames, returning to full quality once input stops.
TEST_F(DisplayWindowTest, CameraControlsAndPreviewFromMouseAndKeys)
{
    startServer("1280x800x24");
    // 320x200 window: the 384x216 EIA is shown at 0.8333x, so one window pixel is
    // 34.54 / 320 = 0.108 mm on the screen. Scene radius 9.715 mm: focal steps of 0.97 mm.
    const std::string w = start(common_ + " --window-size 320x200 --no-turntable --preview-hold 2");
    titleContains("- full | yaw 0.0 pitch 0.0 zoom 1.00 pan 0.0,0.0 mm focal 0.0 mm depthiness 1.0 turntable off");

    // Left drag 100 px right and 20 px down: yaw 30, pitch 6 (0.3 deg per pixel) - in preview.
    send("mousemove --window " + w + " 100 100");
    send("mousedown 1");
    for (int i = 0; i < 5; ++i)
        send("mousemove_relative -- 20 4");
    send("mouseup 1");
    titleContains("yaw 30.0 pitch 6.0");
    titleContains("- preview |");
    titleContains("- full |"); // 2 s after the drag
    const std::string both = titleContains("| preview: total");
    EXPECT_NE(both.find("| full: total"), std::string::npos) << both;

    // Right drag 50 px: pan 50 * 0.108 = 5.4 mm.
    send("mousemove --window " + w + " 100 100");
    send("mousedown 3");
    send("mousemove_relative -- 50 0");
    send("mouseup 3");
    titleContains("pan 5.4,0.0 mm");

    send("click --window " + w + " 4"); // wheel up: zoom x 1.1
    titleContains("zoom 1.10");
    send("key --window " + w + " bracketright bracketright");
    titleContains("focal 1.9 mm");
    send("key --window " + w + " equal");
    titleContains("depthiness 1.1");
    send("key --window " + w + " minus minus minus");
    titleContains("depthiness 0.8");
    send("key --window " + w + " t");
    titleContains("turntable on");
    send("key --window " + w + " Home");
    titleContains("yaw 0.0 pitch 0.0 zoom 1.00 pan 0.0,0.0 mm focal 0.0 mm depthiness 1.0 turntable off");
    quit();
    const std::string log = readBytes(dir_ / "play.log");
    EXPECT_NE(log.find("preview frames (total"), std::string::npos) << log;
}

// Quilt input plays in the window too, fullscreen pixel for pixel like a scene.
TEST_F(DisplayWindowTest, QuiltInputFullscreenEqualsItsHeadlessEia)
{
    startServer("384x216x24");
    std::string err;
    ASSERT_EQ(run("--headless " + common_ + " --no-turntable --quilt " + quoted(dir_ / "q.png"), err), 0) << err;
    const fs::path quilt = dir_ / "q_qs3x3a1.78.png";
    ASSERT_TRUE(fs::exists(quilt));
    const std::string quiltArgs = "--quilt-in " + quoted(quilt) + " --quilt-views 8 --display " + quoted(dir_ / "panel.json");
    ASSERT_EQ(run("--headless " + quiltArgs + " --out " + quoted(dir_ / "quilt_eia.png"), err), 0) << err;
    start(quiltArgs + " --fullscreen");
    titleContains("q_qs3x3a1.78.png");
    const metrics::Image screen = server_->readScreen();
    quit();
    EXPECT_TRUE(screen.pixels == metrics::readImage(dir_ / "quilt_eia.png", 3).pixels);
}

// A quilt video plays in the window at its own rate and loops; space pauses, '.' steps one
// frame forward while paused (the title says which frame is shown).
TEST_F(DisplayWindowTest, QuiltVideoPausesAndStepsOneFrame)
{
    if (player::findOnPath("ffmpeg").empty())
        GTEST_SKIP() << "ffmpeg not installed: no quilt video to play";
    startServer("1280x800x24");
    std::string err;
    ASSERT_EQ(run("--headless " + common_ + " --frames 3 --fps 4 --quilt-video " + quoted(dir_ / "clip.mp4"), err), 0)
        << err;
    const fs::path video = dir_ / "clip_qs3x3a1.78.mp4";
    ASSERT_TRUE(fs::exists(video));
    const std::string w = start("--quilt-in " + quoted(video) + " --quilt-views 8 --display " + quoted(dir_ / "panel.json") +
                                " --window-size 320x200");
    titleContains(" of 3");
    send("key --window " + w + " space");
    const std::string paused = titleContains("paused");
    unsigned shown = 0, count = 0;
    ASSERT_NE(paused.find("mp4 frame "), std::string::npos) << paused;
    ASSERT_EQ(std::sscanf(paused.c_str() + paused.find("mp4 frame "), "mp4 frame %u of %u", &shown, &count), 2)
        << paused;
    EXPECT_EQ(count, 3u);
    send("key --window " + w + " period");
    titleContains("mp4 frame " + std::to_string((shown + 1) % 3) + " of 3");
    send("key --window " + w + " period");
    titleContains("mp4 frame " + std::to_string((shown + 2) % 3) + " of 3");
    quit();
}

} // namespace
} // namespace lfd::test

namespace lfd::test {
namespace {

// The readout in a desktop window: I shows it over the output's top-left corner - glyphs in exact
// white over a dark box, the rest of the window untouched - H adds the key help, ] shows the focal
// plane alone for two seconds, and the back buffer saved by --screenshot never carries it. This
// capture is docs/readout.png (docs/player/display.md "On-screen readout and window keys").
TEST_F(DisplayWindowTest, ReadoutTogglesOverTheWindowAndStaysOutOfScreenshots)
{
    startServer("1280x720x24");
    const std::string args = common_ + " --no-turntable --window-size 1280x720";
    std::string err;
    ASSERT_EQ(run(args + " --readout --frames 2 --screenshot " + quoted(dir_ / "shot.png"), err), 0) << err;
    const std::string w = start(args + " --no-readout");
    metrics::Image last;
    const metrics::Image plain = screenUntil(
        [&](const metrics::Image& s) {
            const bool steady = s.pixels == last.pixels; // the streamed textures are in
            last = s;
            return steady;
        },
        "a steady frame");
    ASSERT_EQ(plain.width, 1280u);
    const metrics::Image shot = metrics::readImage(dir_ / "shot.png", 3);
    EXPECT_TRUE(shot.pixels == plain.pixels) << "--readout --screenshot: the saved image differs from the window "
                                                "without the readout (max difference "
                                             << metrics::maxAbsDiff(shot, plain) << ")";

    const auto& white = player::kOverlayTextColor;
    const auto& accent = player::kOverlayHighlightColor;
    send("key --window " + w + " i");
    const metrics::Image shown =
        screenUntil([&](const metrics::Image& s) { return becameColour(plain, s, white) > 1000; }, "the readout");
    metrics::writeImage(dir_ / "readout.png", shown);
    const Difference d = difference(plain, shown);
    // A box from the corner's margin (4 font units at scale 2) over at most the top-left
    // quarter; everything else is the output as it was.
    EXPECT_GE(d.x0, 8u);
    EXPECT_GE(d.y0, 8u);
    EXPECT_LT(d.x1, 640u);
    EXPECT_LT(d.y1, 360u);
    // Text-like: glyph pixels with dark box pixels right beside them (crisp edges), and
    // every other changed pixel darker than before (the box).
    size_t edges = 0, brighter = 0;
    for (uint32_t y = d.y0; y <= d.y1; ++y)
        for (uint32_t x = d.x0; x < d.x1; ++x) {
            const size_t p = size_t(y) * 1280 + x;
            const uint8_t* n = &shown.pixels[(p + 1) * 3];
            edges += isColour(shown, p, white) && std::max({n[0], n[1], n[2]}) <= 80;
            const uint8_t *a = &plain.pixels[p * 3], *b = &shown.pixels[p * 3];
            brighter += !isColour(shown, p, white) && b[0] + b[1] + b[2] > a[0] + a[1] + a[2];
        }
    EXPECT_GT(edges, 300u);
    EXPECT_EQ(brighter, 0u);

    // H: the key help below the readout, its title in the accent colour.
    send("key --window " + w + " h");
    const metrics::Image help = screenUntil(
        [&](const metrics::Image& s) { return difference(plain, s).y1 > d.y1 + 200; }, "the key help");
    metrics::writeImage(dir_ / "help.png", help);
    EXPECT_GT(becameColour(plain, help, accent), 100u);
    EXPECT_GE(difference(plain, help).x0, 8u);

    // Both off: the window is the output again, byte for byte.
    send("key --window " + w + " h i");
    screenUntil([&](const metrics::Image& s) { return s.pixels == plain.pixels; }, "the output without overlay");

    // ] with the readout off: the focal plane alone, in the accent colour, for two seconds.
    send("key --window " + w + " bracketright");
    screenUntil([&](const metrics::Image& s) { return becameColour(plain, s, accent) > 200; }, "the camera line");
    screenUntil([&](const metrics::Image& s) { return becameColour(plain, s, accent) < 20; },
                "the camera line gone after two seconds");
    quit();
}

// Fullscreen on the panel the EIA arrives untouched until the readout is asked for: with
// I (and gone again with I), or from the start with --readout. A headless run has no
// readout to show: the flag is refused with one line.
TEST_F(DisplayWindowTest, ReadoutOnThePanelOnlyWhenAsked)
{
    startServer("384x216x24");
    const metrics::Image eia = headlessEia();
    start(common_ + " --no-turntable --fullscreen");
    EXPECT_TRUE(server_->readScreen().pixels == eia.pixels);
    const auto& white = player::kOverlayTextColor;
    send("key --window " + window_ + " i");
    const metrics::Image asked =
        screenUntil([&](const metrics::Image& s) { return becameColour(eia, s, white) > 300; }, "the readout");
    metrics::writeImage(dir_ / "asked.png", asked);
    const Difference d = difference(eia, asked);
    EXPECT_GE(d.x0, 4u); // scale 1 on a 384x216 panel
    EXPECT_GE(d.y0, 4u);
    send("key --window " + window_ + " i");
    screenUntil([&](const metrics::Image& s) { return s.pixels == eia.pixels; }, "the EIA untouched again");
    quit();

    start(common_ + " --no-turntable --fullscreen --readout");
    screenUntil([&](const metrics::Image& s) { return becameColour(eia, s, white) > 300; }, "the readout at start");
    quit();

    std::string err;
    EXPECT_EQ(run("--headless " + common_ + " --readout", err), 2);
    EXPECT_EQ(err, "lfd-play: --readout: needs a window (headless images never carry the readout)\n");
}

} // namespace
} // namespace lfd::test
