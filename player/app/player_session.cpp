#include "player_session.h"

#include "frame_limits.h"
#include "gpu_environment.h"
#include "renderer_lfdpr.h"

#include "image.h"
#include "quilt.h"
#include "simulated_viewer.h"

#include "lfd/framing.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <regex>
#include <stdexcept>

namespace lfd::player {

PreviewMode parsePreviewMode(const std::string& name)
{
    if (name == "off")
        return PreviewMode::Off;
    if (name == "auto")
        return PreviewMode::Auto;
    if (name == "always")
        return PreviewMode::Always;
    throw std::invalid_argument("expected off, auto or always, got '" + name + "'");
}

GpuMemoryPlan planSceneMemory(const PlayOptions& options, const Scene& scene, const std::string& packName)
{
    const GpuLimits limits = queryGpuLimits();
    std::optional<uint64_t> budget = limits.availableBytes;
    if (options.gpuMemoryBudgetMiB)
        budget = *options.gpuMemoryBudgetMiB << 20;
    GpuMemoryPlan plan = planGpuMemory(scene, packName, budget, limits.maxTextureSize);
    for (const std::string& warning : plan.warnings)
        std::fprintf(stderr, "lfd-play: warning: %s\n", warning.c_str());
    return plan;
}

void warnIfBakedForAnotherDisplay(const Scene& scene, const DisplayProfile& profile, const std::string& packName)
{
    const BakeSettings& baked = scene.settings;
    // Packs written without a bake (tests, old tools) record no display: nothing to compare.
    if (baked.displayProfile.empty() || baked.viewWidth == 0 || baked.viewHeight == 0)
        return;
    if (baked.displayProfile == profile.name) {
        // The same display's cameras at another view size: an edge's extent in view pixels
        // scales with the view's width and height, so views no larger keep the bound.
        const double scale = std::max(double(profile.viewWidth) / double(baked.viewWidth),
                                      double(profile.viewHeight) / double(baked.viewHeight));
        if (scale <= 1.0)
            return;
        std::fprintf(stderr,
                     "lfd-play: warning: %s: its tessellation bound (%g view pixels) was made for %ux%u views of "
                     "display '%s', these are %ux%u: edges may span up to %.4g view pixels\n",
                     packName.c_str(), double(baked.maxEdgePx), baked.viewWidth, baked.viewHeight,
                     baked.displayProfile.c_str(), profile.viewWidth, profile.viewHeight,
                     double(baked.maxEdgePx) * scale);
        return;
    }
    std::fprintf(stderr,
                 "lfd-play: warning: %s: its tessellation bound (%g view pixels) was made for display '%s' with "
                 "%ux%u views, this is '%s' with %ux%u views: edges may span more view pixels than the bound\n",
                 packName.c_str(), double(baked.maxEdgePx), baked.displayProfile.c_str(), baked.viewWidth,
                 baked.viewHeight, profile.name.c_str(), profile.viewWidth, profile.viewHeight);
}

// Every GL limit the frame's buffers can hit (frame_limits.h), before anything is allocated:
// one line naming the limit and a setting that fits.
static void preflightFrame(const PlayOptions& options, const DisplayProfile& profile)
{
    FrameShape shape;
    shape.views = profile.viewCount;
    shape.viewWidth = profile.viewWidth;
    shape.viewHeight = profile.viewHeight;
    shape.panelWidth = profile.panelWidth;
    shape.panelHeight = profile.panelHeight;
    shape.supersampleViews = options.supersampling == Supersampling::Angular2x ? 2 : 1;
    shape.supersampleSize = options.supersampling == Supersampling::Spatial2x ? 2 : 1;
    shape.viewBuffers = options.renderer.rfind("lfdpr", 0) == 0;
    shape.depthTargets = options.renderer.rfind("mvr", 0) == 0;
    shape.viewBufferBytesPerPixel =
        shape.viewBuffers && lfdprUseInt64(options.rendererOptions.lfdpr.atomics) ? 8 : 4;
    shape.prefilter = options.reconstruction == Reconstruction::Spatial       ? PrefilterPlanes::Layered
                      : options.reconstruction == Reconstruction::ViewSpatial ? PrefilterPlanes::Volume
                                                                              : PrefilterPlanes::None;
    if (const std::optional<std::string> problem = checkFrameLimits(shape, queryFrameLimits()))
        throw std::runtime_error(*problem);
}

PlayerSession::PlayerSession(const PlayOptions& options, const DisplayProfile& profile, Scene scene,
                             std::string packName)
    : options_(options), displayProfile_(profile), packName_(std::move(packName)),
      plan_(planSceneMemory(options, scene, packName_))
{
    preflightFrame(options, profile);
    warnIfBakedForAnotherDisplay(scene, profile, packName_);
    GpuSceneOptions sceneOptions;
    sceneOptions.plan = &plan_;
    sceneOptions.maxAnisotropy = options.aniso;
    pipeline_ = std::make_unique<FramePipeline>(profile, std::move(scene), options.turntablePeriod, sceneOptions);
    applyRenderOptions(options);
}

PlayerSession::PlayerSession(const PlayOptions& options, const DisplayProfile& profile,
                             std::shared_ptr<MappedPack> pack, std::string packName)
    : options_(options), displayProfile_(profile), packName_(std::move(packName)),
      plan_(planSceneMemory(options, pack->scene(), packName_)), mapped_(std::move(pack))
{
    preflightFrame(options, profile);
    warnIfBakedForAnotherDisplay(mapped_->scene(), profile, packName_);
    GpuSceneOptions sceneOptions;
    sceneOptions.plan = &plan_;
    sceneOptions.maxAnisotropy = options.aniso;
    sceneOptions.streamed = true;
    pipeline_ = std::make_unique<FramePipeline>(profile, mapped_->takeScene(), options.turntablePeriod, sceneOptions);
    streamer_ = std::make_unique<TextureStreamer>(pipeline_->scene(), mapped_, options.streamChunkBytes);
    applyRenderOptions(options);
}

void PlayerSession::applyRenderOptions(const PlayOptions& options)
{
    reconstruction_ = options.reconstruction;
    pipeline_->setLighting(options.lighting, uploadEnvironment(options.environment));
    pipeline_->setSupersampling(options.supersampling);
    pipeline_->setViewControls(options.controls);
    pipeline_->setPreviewShape(options.previewShape);
    switchRenderer(options.renderer);
}

PlayerSession::PlayerSession(const PlayOptions& options, const DisplayProfile& profile,
                             std::vector<std::filesystem::path> quilts)
    : options_(options), displayProfile_(profile),
      packName_(quilts.size() == 1 ? quilts.front().filename().string()
                                   : std::to_string(quilts.size()) + " quilts"),
      quilts_(std::make_unique<QuiltSlideshow>(profile, std::move(quilts), options.quiltViews, options.slideSeconds,
                                               options.quiltLayout)),
      rendererName_("quilt-in")
{
    reconstruction_ = options.reconstruction;
}

const DisplayProfile& PlayerSession::profile() const
{
    if (quilts_)
        return quilts_->profile();
    return lastQuality_ == FrameQuality::Preview ? pipeline_->previewProfileInUse() : pipeline_->profile();
}

double PlayerSession::frameTime(uint32_t k) const
{
    const double fps = quilts_ && quilts_->videoFps() > 0.0 ? quilts_->videoFps() : options_.fps;
    return double(k) / fps;
}

void PlayerSession::switchRenderer(const std::string& name)
{
    if (quilts_)
        return;
    renderer_ = createRenderer(name, options_.rendererOptions);
    rendererName_ = name;
}

void PlayerSession::setViewControls(const ViewControls& controls)
{
    if (pipeline_)
        pipeline_->setViewControls(controls);
}

const ViewTargets& PlayerSession::targets() const
{
    if (quilts_)
        return quilts_->targets();
    return lastQuality_ == FrameQuality::Preview ? pipeline_->previewTargets() : pipeline_->targets();
}

const EiaBuilder& PlayerSession::eia() const
{
    if (quilts_)
        return quilts_->eia();
    return lastQuality_ == FrameQuality::Preview ? pipeline_->previewEia() : pipeline_->eia();
}

void PlayerSession::renderFrame(double time, FrameQuality quality)
{
    if (quilts_) {
        quilts_->renderFrame(time, timer_, reconstruction_);
        lastQuality_ = FrameQuality::Full;
        return;
    }
    if (quality == FrameQuality::Preview)
        pipeline_->renderPreviewFrame(*renderer_, time, previewTimer_, reconstruction_);
    else
        pipeline_->renderFrame(*renderer_, time, timer_, reconstruction_);
    lastQuality_ = quality;
    lastTime_ = time;
}

void PlayerSession::completeLastFrame()
{
    if (!quilts_)
        pipeline_->completeFrame(*renderer_, lastTime_, reconstruction_, lastQuality_ == FrameQuality::Preview);
}

void PlayerSession::renderUntimedFrame(double time)
{
    if (quilts_) {
        renderFrame(time);
        return;
    }
    GpuTimer scratch;
    pipeline_->renderFrame(*renderer_, time, scratch, reconstruction_);
    scratch.finish();
    lastQuality_ = FrameQuality::Full;
    lastTime_ = time;
}

FrameOutputs PlayerSession::readOutputs(uint32_t frameIndex) const
{
    if (quilts_)
        return quilts_->read(frameIndex);
    if (lastQuality_ == FrameQuality::Full)
        return pipeline_->read(frameIndex);
    FrameOutputs out;
    out.frame = frameIndex;
    for (uint32_t i = 0; i < pipeline_->previewTargets().viewCount(); ++i)
        out.views.push_back(pipeline_->previewTargets().readView(i));
    out.eia = pipeline_->previewEia().read();
    return out;
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

QuiltLayout quiltLayoutFor(const PlayOptions& options, const DisplayProfile& views)
{
    const QuiltLayout layout = chooseQuiltLayout(views);
    if (!options.quiltLayout)
        return layout;
    const QuiltName& given = *options.quiltLayout;
    return overrideQuiltLayout(layout, views.viewCount, given.cols, given.rows, given.aspect);
}

bool isFramePattern(const std::filesystem::path& path)
{
    // One %d conversion (with an optional zero-padded width) in the file name, nothing else.
    static const std::regex pattern(R"(^[^%]*%0?\d{0,2}d[^%]*$)");
    return std::regex_match(path.filename().string(), pattern);
}

std::filesystem::path framePatternName(const std::filesystem::path& pattern, uint32_t frame)
{
    char name[4096];
    std::snprintf(name, sizeof(name), pattern.filename().c_str(), int(frame));
    return pattern.parent_path() / name;
}

std::filesystem::path writeQuiltFrame(const PlayOptions& options, const std::filesystem::path& base,
                                      const DisplayProfile& profile, const FrameOutputs& outputs, uint32_t frame)
{
    const QuiltLayout layout = quiltLayoutFor(options, profile);
    const std::vector<uint8_t> quilt = assembleQuilt(layout, outputs.views);
    const std::filesystem::path path = quiltSequenceFileName(base, layout, frame);
    metrics::writeImage(path, quilt.data(), layout.width(), layout.height(), 4);
    return path;
}

void writeFrameOutputs(const PlayOptions& options, const DisplayProfile& profile,
                       const FrameOutputs& outputs, std::vector<std::filesystem::path>& written)
{
    if (!options.eiaOut.empty() && !isFramePattern(options.eiaOut)) {
        metrics::writeImage(options.eiaOut, outputs.eia.data(), profile.panelWidth, profile.panelHeight, 4);
        written.push_back(options.eiaOut);
    }
    if (!options.quiltOut.empty()) {
        const QuiltLayout layout = quiltLayoutFor(options, profile);
        const std::vector<uint8_t> quilt = assembleQuilt(layout, outputs.views);
        const std::filesystem::path path = quiltFileName(options.quiltOut, layout);
        metrics::writeImage(path, quilt.data(), layout.width(), layout.height(), 4);
        written.push_back(path);
    }
    if (!options.viewsOut.empty()) {
        std::filesystem::create_directories(options.viewsOut);
        for (size_t i = 0; i < outputs.views.size(); ++i) {
            char name[32];
            std::snprintf(name, sizeof(name), "view_%03zu.png", i);
            metrics::writeImage(options.viewsOut / name, outputs.views[i].data(), profile.viewWidth,
                       profile.viewHeight, 4);
            written.push_back(options.viewsOut / name);
        }
    }
    if (!options.viewerOut.empty()) {
        const double t = options.viewerPosition >= 0.0 ? options.viewerPosition : 0.5 * profile.viewCount;
        const std::vector<uint8_t> seen = simulateViewer(profile, outputs.eia, t);
        metrics::writeImage(options.viewerOut, seen.data(), profile.viewWidth, profile.viewHeight, 4);
        written.push_back(options.viewerOut);
    }
}

} // namespace lfd::player
