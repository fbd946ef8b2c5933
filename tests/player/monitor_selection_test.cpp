// Monitor selection for --fullscreen (CPU only): which monitor drives the panel, the
// refusal of a mismatched mode, and where the EIA lands with --allow-mismatch.
#include "monitor_selection.h"

#include <gtest/gtest.h>

namespace lfd::player {
namespace {

MonitorInfo monitor(const std::string& name, uint32_t w, uint32_t h, bool primary = false)
{
    MonitorInfo m;
    m.name = name;
    m.width = w;
    m.height = h;
    m.refreshHz = 60;
    m.primary = primary;
    return m;
}

// A laptop panel, a 4K monitor and a Looking Glass Portrait (1536x2048).
const std::vector<MonitorInfo> kDesk = {monitor("eDP-1", 1920, 1080, true), monitor("DP-2", 3840, 2160),
                                        monitor("LKG-P03", 1536, 2048)};

std::string errorOf(const std::vector<MonitorInfo>& monitors, const std::string& request, uint32_t w, uint32_t h,
                    bool allow = false)
{
    try {
        selectMonitor(monitors, request, w, h, allow);
    } catch (const MonitorError& e) {
        return e.what();
    }
    return {};
}

TEST(MonitorSelection, AutomaticPicksTheMonitorRunningAtThePanelSize)
{
    EXPECT_EQ(selectMonitor(kDesk, "", 3840, 2160, false), 1u);
    // A Looking Glass visual.json's screenW x screenH (the Portrait's 1536x2048).
    EXPECT_EQ(selectMonitor(kDesk, "", 1536, 2048, false), 2u);
    // Several at the panel size: a Looking Glass name first, then a non-primary monitor.
    const std::vector<MonitorInfo> three4k = {monitor("HDMI-1", 3840, 2160, true), monitor("DP-1", 3840, 2160),
                                              monitor("LKG-2K", 3840, 2160)};
    EXPECT_EQ(selectMonitor(three4k, "", 3840, 2160, false), 2u);
    const std::vector<MonitorInfo> two4k = {three4k[0], three4k[1]};
    EXPECT_EQ(selectMonitor(two4k, "", 3840, 2160, false), 1u);
}

TEST(MonitorSelection, NoMatchingMonitorIsRefusedUnlessAllowed)
{
    const std::string e = errorOf(kDesk, "", 2560, 1600);
    EXPECT_NE(e.find("2560x1600"), std::string::npos) << e;
    EXPECT_NE(e.find("monitor 0 'eDP-1' 1920x1080"), std::string::npos) << e;
    EXPECT_NE(e.find("--allow-mismatch"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
    EXPECT_EQ(selectMonitor(kDesk, "", 2560, 1600, true), 0u); // the primary
    EXPECT_NE(errorOf({}, "", 10, 10, true).find("no monitor"), std::string::npos);
}

TEST(MonitorSelection, ExplicitIndexOrName)
{
    EXPECT_EQ(selectMonitor(kDesk, "1", 3840, 2160, false), 1u);
    EXPECT_EQ(selectMonitor(kDesk, "DP-2", 3840, 2160, false), 1u);
    EXPECT_EQ(selectMonitor(kDesk, "lkg", 1536, 2048, false), 2u); // the only name containing it
    EXPECT_NE(errorOf(kDesk, "dp", 3840, 2160).find("more than one monitor named 'dp'"), std::string::npos);
    EXPECT_NE(errorOf(kDesk, "HDMI", 3840, 2160).find("no monitor named 'HDMI'"), std::string::npos);
    EXPECT_NE(errorOf(kDesk, "9", 3840, 2160).find("no monitor 9 (3 connected"), std::string::npos);
}

TEST(MonitorSelection, ExplicitMonitorOfAnotherModeIsRefusedUnlessAllowed)
{
    const std::string e = errorOf(kDesk, "0", 3840, 2160);
    EXPECT_EQ(e, "monitor 0 'eDP-1' runs at 1920x1080 but the display profile's panel is 3840x2160: the "
                 "lenticular mapping needs it pixel for pixel (refused; --allow-mismatch centres the EIA unscaled)");
    EXPECT_EQ(selectMonitor(kDesk, "0", 3840, 2160, true), 0u);
}

TEST(MonitorSelection, PanelIsCentredUnscaled)
{
    const PanelPlacement same = placePanel(384, 216, 384, 216);
    EXPECT_EQ(same.left, 0);
    EXPECT_EQ(same.top, 0);
    const PanelPlacement larger = placePanel(640, 400, 384, 216);
    EXPECT_EQ(larger.left, 128);
    EXPECT_EQ(larger.top, 92);
    const PanelPlacement odd = placePanel(385, 217, 384, 216); // the spare pixel right / bottom
    EXPECT_EQ(odd.left, 0);
    EXPECT_EQ(odd.top, 0);
    const PanelPlacement cropped = placePanel(1920, 1080, 3840, 2160);
    EXPECT_EQ(cropped.left, -960);
    EXPECT_EQ(cropped.top, -540);
    EXPECT_EQ(placePanel(383, 215, 384, 216).left, -1); // the cropped pixel comes off the left
}

TEST(MonitorSelection, ListingSaysWhichMonitorMatches)
{
    const std::string text = describeMonitors(kDesk, 3840, 2160);
    EXPECT_NE(text.find("0: eDP-1 1920x1080 @ 60 Hz at +0+0 (primary) - does not match the panel 3840x2160\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("1: DP-2 3840x2160 @ 60 Hz at +0+0 - matches the panel 3840x2160\n"), std::string::npos)
        << text;
}

} // namespace
} // namespace lfd::player
