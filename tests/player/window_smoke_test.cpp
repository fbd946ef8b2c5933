// Windowed lfd-play under Xvfb: a GLFW window with a GL 4.5 core context renders a few
// frames and saves a screenshot of its back buffer. Skipped when Xvfb is not installed.
#include "gl_test_support.h"
#include "test_scenes.h"
#include "xvfb_support.h"

#include "image_metrics.h"

#include "lfd/pack.h"

#include "skip_or_fail.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

TEST(WindowSmoke, RendersEveryOutputAndSavesScreenshotsUnderXvfb)
{
    const std::string xvfb = findXvfb();
    if (xvfb.empty())
        LFD_SKIP_OR_FAIL("Xvfb not installed; windowed mode not tested");
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    ASSERT_TRUE(fs::exists(play)) << play << " not built";

    const fs::path dir = testOutputDir("window_smoke");
    writePack(dir / "scene.lfdpack", cubeAndSphereScene());
    XvfbServer server(xvfb);
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";

    // Every displayed output once: EIA (the default), quilt, single view, simulated viewer.
    for (const char* show : {"eia", "quilt", "view", "viewer"}) {
        SCOPED_TRACE(show);
        const fs::path shot = dir / (std::string("shot_") + show + ".png");
        const fs::path logPath = dir / (std::string("log_") + show + ".txt");
        const std::string command = "DISPLAY=" + server.display() + " '" + play.string() + "' '" +
                                    (dir / "scene.lfdpack").string() +
                                    "' --views 4 --view-size 96x72 --frames 5 --window-size 320x200 --show " + show +
                                    " --screenshot '" + shot.string() + "' > '" + logPath.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        std::ifstream logFile(logPath);
        const std::string log((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
        ASSERT_TRUE(fs::exists(shot)) << log;

        const metrics::Image image = metrics::readImage(shot, 3);
        EXPECT_EQ(image.width, 320u);
        EXPECT_EQ(image.height, 200u);
        // Not uniform: the scene shows up (many pixels differ from the first one).
        size_t differing = 0;
        for (size_t i = 3; i < image.pixels.size(); ++i)
            differing += image.pixels[i] != image.pixels[i % 3];
        EXPECT_GT(differing, image.pixels.size() / 20) << "screenshot is (nearly) uniform";
    }
}

// Interactive controls, driven through the X server with xdotool: the window title reports
// renderer, reconstruction, displayed output, viewer position and pause state. (The camera
// keys, drags and the wheel are tested in display_window_test.cpp.)
TEST(WindowSmoke, KeysAndMouseSwitchRendererOutputViewerAndPause)
{
    const std::string xvfb = findXvfb();
    if (xvfb.empty() || !fs::exists("/usr/bin/xdotool"))
        LFD_SKIP_OR_FAIL("Xvfb or xdotool not installed; interactive controls not tested");
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    ASSERT_TRUE(fs::exists(play)) << play << " not built";
    const fs::path dir = testOutputDir("window_controls");
    writePack(dir / "scene.lfdpack", cubeAndSphereScene());
    XvfbServer server(xvfb);
    ASSERT_FALSE(server.display().empty()) << "could not start Xvfb";
    const std::string env = "DISPLAY=" + server.display() + " ";

    // Start lfd-play in the background (no --frames: it runs until Esc).
    const std::string pidFile = (dir / "play.pid").string();
    const std::string start = env + "'" + play.string() + "' '" + (dir / "scene.lfdpack").string() +
                              "' --views 8 --view-size 64x48 --window-size 320x200 > '" +
                              (dir / "play.log").string() + "' 2>&1 & echo $! > '" + pidFile + "'";
    ASSERT_EQ(std::system(start.c_str()), 0);
    pid_t pid = 0;
    std::ifstream(pidFile) >> pid;
    ASSERT_GT(pid, 0);

    std::string window;
    for (int i = 0; i < 200 && window.empty(); ++i) {
        window = capture(env + "xdotool search --name '^lfd-play' 2>/dev/null | head -n 1");
        if (window.empty())
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_FALSE(window.empty()) << "no lfd-play window appeared";
    // Waits until the title contains `text` (the title is refreshed about twice a second).
    auto titleContains = [&](const std::string& text) {
        std::string title;
        for (int i = 0; i < 150; ++i) {
            title = capture(env + "xdotool getwindowname " + window);
            if (title.find(text) != std::string::npos)
                return title;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        ADD_FAILURE() << "window title never contained \"" << text << "\"; last: " << title;
        return title;
    };
    auto send = [&](const std::string& what) { std::system((env + "xdotool " + what + " >/dev/null 2>&1").c_str()); };

    titleContains("- mvr - none - EIA");
    send("key --window " + window + " o");
    titleContains("- quilt");
    send("key --window " + window + " r");
    titleContains("- mvr-layered -");
    send("key --window " + window + " o"); // next output: single view
    titleContains("single view (viewer 4.0)");
    send("key --window " + window + " Right Right");
    titleContains("(viewer 6.0)");
    send("key --window " + window + " Left"); // the wheel zooms now; Left/Right move the viewer
    titleContains("(viewer 5.0)");
    send("key --window " + window + " space");
    titleContains("- paused");
    send("key --window " + window + " Escape");

    // lfd-play was started by a shell that has exited, so it is not our child: poll it.
    bool quit = false;
    for (int i = 0; i < 100 && !quit; ++i) {
        quit = kill(pid, 0) != 0;
        if (!quit)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!quit) {
        kill(pid, SIGTERM);
        ADD_FAILURE() << "lfd-play did not quit on Escape";
    }
}

} // namespace
} // namespace lfd::test
