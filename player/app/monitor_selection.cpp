#include "monitor_selection.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace lfd::player {

namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string modeText(uint32_t w, uint32_t h) { return std::to_string(w) + "x" + std::to_string(h); }

bool matchesPanel(const MonitorInfo& m, uint32_t panelWidth, uint32_t panelHeight)
{
    return m.width == panelWidth && m.height == panelHeight;
}

bool looksLikeLookingGlass(const MonitorInfo& m)
{
    const std::string name = lower(m.name);
    return name.find("lkg") != std::string::npos || name.find("looking glass") != std::string::npos;
}

std::string label(const std::vector<MonitorInfo>& monitors, size_t i)
{
    return "monitor " + std::to_string(i) + " '" + monitors[i].name + "'";
}

// An index ("1") or a name; throws MonitorError when nothing or more than one matches.
size_t findRequested(const std::vector<MonitorInfo>& monitors, const std::string& request)
{
    size_t index = 0;
    const auto [end, ec] = std::from_chars(request.data(), request.data() + request.size(), index);
    if (ec == std::errc() && end == request.data() + request.size()) {
        if (index >= monitors.size())
            throw MonitorError("--monitor: no monitor " + request + " (" + std::to_string(monitors.size()) +
                               " connected; see --list-monitors)");
        return index;
    }
    for (size_t i = 0; i < monitors.size(); ++i)
        if (monitors[i].name == request)
            return i;
    std::vector<size_t> partial;
    for (size_t i = 0; i < monitors.size(); ++i)
        if (lower(monitors[i].name).find(lower(request)) != std::string::npos)
            partial.push_back(i);
    if (partial.size() == 1)
        return partial[0];
    throw MonitorError("--monitor: " + std::string(partial.empty() ? "no" : "more than one") + " monitor named '" +
                       request + "' (see --list-monitors)");
}

// Automatic choice among the monitors whose mode is the panel's, or npos.
size_t findMatching(const std::vector<MonitorInfo>& monitors, uint32_t panelWidth, uint32_t panelHeight)
{
    size_t best = std::string::npos;
    int bestRank = -1;
    for (size_t i = 0; i < monitors.size(); ++i) {
        if (!matchesPanel(monitors[i], panelWidth, panelHeight))
            continue;
        const int rank = 2 * int(looksLikeLookingGlass(monitors[i])) + int(!monitors[i].primary);
        if (rank > bestRank) {
            best = i;
            bestRank = rank;
        }
    }
    return best;
}

} // namespace

std::vector<MonitorInfo> listMonitors()
{
    if (!glfwInit())
        throw MonitorError("cannot list monitors: GLFW cannot connect to a display (is DISPLAY set?)");
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    std::vector<MonitorInfo> list;
    for (int i = 0; i < count; ++i) {
        MonitorInfo info;
        const char* name = glfwGetMonitorName(monitors[i]);
        info.name = name ? name : "";
        glfwGetMonitorPos(monitors[i], &info.x, &info.y);
        if (const GLFWvidmode* mode = glfwGetVideoMode(monitors[i])) {
            info.width = uint32_t(mode->width);
            info.height = uint32_t(mode->height);
            info.refreshHz = mode->refreshRate;
        }
        info.primary = monitors[i] == glfwGetPrimaryMonitor();
        list.push_back(info);
    }
    return list;
}

std::string describeMonitors(const std::vector<MonitorInfo>& monitors, uint32_t panelWidth, uint32_t panelHeight)
{
    std::string text;
    for (size_t i = 0; i < monitors.size(); ++i) {
        const MonitorInfo& m = monitors[i];
        char line[256];
        std::snprintf(line, sizeof(line), "%zu: %s %s @ %d Hz at %+d%+d%s - %s the panel %s\n", i, m.name.c_str(),
                      modeText(m.width, m.height).c_str(), m.refreshHz, m.x, m.y, m.primary ? " (primary)" : "",
                      matchesPanel(m, panelWidth, panelHeight) ? "matches" : "does not match",
                      modeText(panelWidth, panelHeight).c_str());
        text += line;
    }
    return text;
}

size_t selectMonitor(const std::vector<MonitorInfo>& monitors, const std::string& request, uint32_t panelWidth,
                     uint32_t panelHeight, bool allowMismatch)
{
    if (monitors.empty())
        throw MonitorError("no monitor connected");
    const std::string panel = modeText(panelWidth, panelHeight);
    if (request.empty()) {
        const size_t match = findMatching(monitors, panelWidth, panelHeight);
        if (match != std::string::npos)
            return match;
        if (allowMismatch)
            return 0; // the primary, centred
        std::string modes;
        for (size_t i = 0; i < monitors.size(); ++i)
            modes += (i ? ", " : "") + label(monitors, i) + " " + modeText(monitors[i].width, monitors[i].height);
        throw MonitorError("no monitor runs at the display profile's panel size " + panel + " (" + modes +
                           "): refused, the lenticular mapping needs the EIA pixel for pixel (--allow-mismatch "
                           "centres it unscaled)");
    }
    const size_t i = findRequested(monitors, request);
    if (!matchesPanel(monitors[i], panelWidth, panelHeight) && !allowMismatch)
        throw MonitorError(label(monitors, i) + " runs at " + modeText(monitors[i].width, monitors[i].height) +
                           " but the display profile's panel is " + panel +
                           ": the lenticular mapping needs it pixel for pixel (refused; --allow-mismatch "
                           "centres the EIA unscaled)");
    return i;
}

PanelPlacement placePanel(uint32_t monitorWidth, uint32_t monitorHeight, uint32_t panelWidth, uint32_t panelHeight)
{
    // floor(free / 2), also for a negative margin (a panel larger than the monitor): an odd
    // spare pixel goes right/bottom, an odd cropped pixel comes off the left/top.
    auto centre = [](int64_t free) { return int(free >= 0 ? free / 2 : -((-free + 1) / 2)); };
    return {centre(int64_t(monitorWidth) - int64_t(panelWidth)), centre(int64_t(monitorHeight) - int64_t(panelHeight))};
}

} // namespace lfd::player
