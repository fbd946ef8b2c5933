#include "player_session.h"

#include "image_output.h"
#include "quilt.h"
#include "simulated_viewer.h"

#include "lfd/framing.h"

#include <algorithm>
#include <cstdio>

namespace lfd::player {

PlayerSession::PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                             std::string packName)
    : options_(options), packName_(std::move(packName)), pipeline_(profile, scene, options.turntablePeriod)
{
    reconstruction_ = parseReconstruction(options.reconstruction);
    pipeline_.setSupersampling(parseSupersampling(options.supersampling));
    switchRenderer(options.renderer);
}

void PlayerSession::switchRenderer(const std::string& name)
{
    renderer_ = createRenderer(name, options_.rendererOptions);
    rendererName_ = name;
}

void PlayerSession::renderFrame(double time)
{
    pipeline_.renderFrame(*renderer_, time, timer_, reconstruction_);
}

FrameOutputs PlayerSession::readOutputs(uint32_t frameIndex) const
{
    return pipeline_.read(frameIndex);
}

std::vector<std::string> windowRendererCycle(const std::string& current)
{
    std::vector<std::string> cycle = rendererNames();
    if (current != "gstd")
        std::erase(cycle, std::string("gstd"));
    if (std::find(cycle.begin(), cycle.end(), current) == cycle.end())
        cycle.push_back(current);
    // Rotate so the list starts after `current`.
    const auto at = std::find(cycle.begin(), cycle.end(), current);
    std::rotate(cycle.begin(), at + 1, cycle.end());
    return cycle;
}

void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written)
{
    if (!options.eiaOut.empty()) {
        writeImage(options.eiaOut, outputs.eia.data(), profile.panelWidth, profile.panelHeight, 4);
        written.push_back(options.eiaOut);
    }
    if (!options.quiltOut.empty()) {
        const QuiltLayout layout = chooseQuiltLayout(profile);
        const std::vector<uint8_t> quilt = assembleQuilt(layout, outputs.views);
        const std::filesystem::path path =
            quiltFileName(options.quiltOut, layout.cols, layout.rows, layout.aspect());
        writeImage(path, quilt.data(), layout.width(), layout.height(), 4);
        written.push_back(path);
    }
    if (!options.viewsOut.empty()) {
        std::filesystem::create_directories(options.viewsOut);
        for (size_t i = 0; i < outputs.views.size(); ++i) {
            char name[32];
            std::snprintf(name, sizeof(name), "view_%03zu.png", i);
            writeImage(options.viewsOut / name, outputs.views[i].data(), profile.viewWidth,
                       profile.viewHeight, 4);
            written.push_back(options.viewsOut / name);
        }
    }
    if (!options.viewerOut.empty()) {
        const double t = options.viewerPosition >= 0.0 ? options.viewerPosition : 0.5 * profile.viewCount;
        const std::vector<uint8_t> seen = simulateViewer(profile, outputs.eia, t);
        writeImage(options.viewerOut, seen.data(), profile.viewWidth, profile.viewHeight, 4);
        written.push_back(options.viewerOut);
    }
}

} // namespace lfd::player
