#include "window_readout.h"

#include "window_key_help.h"

#include <cstdio>

namespace lfd::player {

namespace {

std::string format(const char* pattern, auto... values)
{
    char text[160];
    std::snprintf(text, sizeof(text), pattern, values...);
    return text;
}

} // namespace

std::vector<OverlayLine> readoutLines(const ReadoutState& s, bool highlightCamera)
{
    std::vector<OverlayLine> lines;
    lines.push_back({"renderer\t" + s.renderer + ", reconstruction " + s.reconstruction});
    lines.push_back({format("views\t%u of %ux%u%s", s.views, s.viewWidth, s.viewHeight,
                            s.preview ? " (preview)" : "")});
    lines.push_back({format("shown\t%s %ux%u in a %ux%u window", s.shown.c_str(), s.outputWidth, s.outputHeight,
                            s.windowWidth, s.windowHeight)});
    std::string frame = s.frameMs ? format("frame\t%.1f ms, %.1f fps", *s.frameMs, 1000.0 / *s.frameMs)
                                  : std::string("frame\tmeasuring");
    lines.push_back({frame + (s.paused ? " (paused)" : "")});
    if (s.camera)
        lines.push_back({cameraLines(s).front().text, highlightCamera});
    lines.push_back({"keys\tI readout, H key help"});
    return lines;
}

std::vector<OverlayLine> cameraLines(const ReadoutState& s)
{
    if (!s.camera)
        return {};
    return {{format("camera\tfocal plane %+.1f mm, depthiness %.2f", s.camera->focalDepthMm, s.camera->depthiness),
             true}};
}

std::vector<OverlayLine> keyHelpLines()
{
    std::vector<OverlayLine> lines{{"Keys and mouse", true}};
    for (const KeyBinding& b : windowKeyBindings())
        lines.push_back({std::string(b.keys) + "\t" + std::string(b.action)});
    return lines;
}

void FrameTimeAverage::swapped(double now)
{
    if (last_ >= 0.0) {
        sum_ += now - last_;
        ++count_;
    } else {
        periodStart_ = now;
    }
    last_ = now;
    if (count_ > 0 && now - periodStart_ >= kFrameAverageSeconds) {
        meanMs_ = 1000.0 * sum_ / count_;
        sum_ = 0.0;
        count_ = 0;
        periodStart_ = now;
    }
}

std::vector<OverlayLine> ReadoutToggles::lines(const ReadoutState& state, double now) const
{
    std::vector<OverlayLine> lines;
    if (readout_)
        lines = readoutLines(state, cameraRecent(now));
    else if (cameraAlone(now))
        lines = cameraLines(state);
    if (help_) {
        if (!lines.empty())
            lines.push_back({});
        for (OverlayLine& line : keyHelpLines())
            lines.push_back(std::move(line));
    }
    return lines;
}

} // namespace lfd::player
