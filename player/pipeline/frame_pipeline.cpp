#include "frame_pipeline.h"

#include "frame_stages.h"
#include "view_downsample_bindings_gpu.h"
#include "shader_library.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <algorithm>

namespace lfd::player {

namespace {

// splitmix64 finaliser: a well-mixed 64-bit hash (for per-frame, per-view jitter).
uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Uniform in [0, 1) from a hash.
double unitFromHash(uint64_t h) { return double(h >> 11) * 0x1.0p-53; }

} // namespace

std::vector<std::string> supersamplingNames() { return {"1", "2s", "2v"}; }

Supersampling parseSupersampling(const std::string& name)
{
    const std::vector<std::string> names = supersamplingNames();
    for (size_t i = 0; i < names.size(); ++i)
        if (name == names[i])
            return Supersampling(uint32_t(i));
    throw std::invalid_argument("unknown supersampling '" + name + "' (expected: 1, 2s or 2v)");
}

std::string supersamplingName(Supersampling ss)
{
    const std::vector<std::string> names = supersamplingNames();
    if (size_t(ss) >= names.size())
        throw std::invalid_argument("unknown supersampling mode " + std::to_string(uint32_t(ss)));
    return names[size_t(ss)];
}

FrameSetup supersampledFrame(const FrameSetup& frame, Supersampling ss, uint64_t seed)
{
    if (ss == Supersampling::None)
        return frame;
    FrameSetup out = frame;
    out.pointSampling.reset();
    if (ss == Supersampling::Spatial2x) {
        // The same cameras; the raster state and the frame constants take the viewport
        // from the profile.
        out.profile.viewWidth *= 2;
        out.profile.viewHeight *= 2;
        return out;
    }
    // Angular: two cameras per view interval, one in each half, at random positions.
    const uint32_t n = frame.profile.viewCount;
    out.profile.viewCount = 2 * n;
    out.cameras.clear();
    out.clipFromScene.clear();
    out.eyeScene.clear();
    uint64_t timeBits = 0;
    std::memcpy(&timeBits, &frame.time, sizeof(timeBits));
    const uint64_t frameHash = mix64(seed ^ mix64(timeBits));
    const glm::dmat4 sceneFromDisplay = glm::inverse(frame.displayFromScene);
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t s = 0; s < 2; ++s) {
            const double u = unitFromHash(mix64(frameHash + 2 * uint64_t(i) + s));
            const double position = (double(i) + (double(s) + u) / 2.0) / double(n);
            const ViewCamera camera = makeViewCameraAt(frame.profile, frame.framing, std::min(position, 1.0));
            out.cameras.push_back(camera);
            out.clipFromScene.push_back(glm::mat4(camera.clipFromDisplay * frame.displayFromScene));
            out.eyeScene.push_back(glm::vec3(sceneFromDisplay * glm::dvec4(camera.eye, 1.0)));
        }
    out.pointSampling = std::make_shared<const FrameSetup>(frame);
    return out;
}

FramePipeline::FramePipeline(const DisplayProfile& profile, Scene scene, double turntablePeriod,
                             const GpuSceneOptions& sceneOptions)
    : profile_(profile), turntablePeriod_(turntablePeriod)
{
    const double fill = scene.settings.framingFill > 0.0f ? double(scene.settings.framingFill) : 1.0;
    framing_ = fitSceneToDisplay(profile_, scene.bounds, fill);
    scene_ = std::make_unique<GpuScene>(std::move(scene), sceneOptions);
    targets_ = std::make_unique<ViewTargets>(profile_.viewCount, profile_.viewWidth, profile_.viewHeight);
    eia_ = std::make_unique<EiaBuilder>(profile_);
}

void FramePipeline::animate(double time)
{
    scene_->update(time);
    frame_ = frameAt(profile_, time);
}

FrameSetup FramePipeline::frameAt(const DisplayProfile& profile, double time) const
{
    FrameSetup frame = makeFrameSetup(profile, framing_, time, turntablePeriod_, controls_);
    frame.textureAnisotropy = scene_->maxAnisotropy();
    frame.lighting = lighting_;
    frame.lighting.environment = environment_.get();
    frame.lighting.lights = sceneLights(scene_->cpu(), scene_->sceneFromNode());
    return frame;
}

void FramePipeline::setLighting(const FrameLighting& lighting, std::shared_ptr<const GpuEnvironment> environment)
{
    lighting_ = lighting;
    lighting_.lights.clear();
    environment_ = std::move(environment);
}

void FramePipeline::poseScene(GpuTimer& timer)
{
    if (!scene_->deforms())
        return; // static scenes have no pose stage
    timer.begin(stage::kPose);
    scene_->pose();
    timer.end();
}

void FramePipeline::buildEia(GpuTimer& timer, Reconstruction reconstruction)
{
    eia_->build(*targets_, reconstruction, timer);
}

FramePipeline::~FramePipeline() = default; // here, where the members' types are complete

void FramePipeline::setSupersampling(Supersampling ss, uint64_t seed)
{
    ssSeed_ = seed;
    if (ss == ss_)
        return;
    ss_ = ss;
    ssTargets_.reset();
    if (ss == Supersampling::None)
        return;
    const uint32_t n = profile_.viewCount, w = profile_.viewWidth, h = profile_.viewHeight;
    ssTargets_ = ss == Supersampling::Spatial2x ? std::make_unique<ViewTargets>(n, 2 * w, 2 * h)
                                                : std::make_unique<ViewTargets>(2 * n, w, h);
    if (!downsample_)
        downsample_.reset(gl::buildProgram({{GL_COMPUTE_SHADER, "view_downsample.comp"}}));
}

void FramePipeline::renderFrame(Renderer& renderer, double time, GpuTimer& timer, Reconstruction reconstruction)
{
    animate(time);
    timer.begin(stage::kTotal);
    poseScene(timer);
    if (ss_ == Supersampling::None) {
        renderer.render(*scene_, frame_, *targets_, timer);
    } else {
        // Supersampled views, then their linear-light mean into the display's views.
        const FrameSetup frame = supersampledFrame(frame_, ss_, ssSeed_);
        renderer.render(*scene_, frame, *ssTargets_, timer);
        timer.begin(stage::kDownsample);
        namespace db = downsample_bindings;
        glUseProgram(downsample_);
        glUniform3ui(db::kLocTargetSize, targets_->width(), targets_->height(), targets_->viewCount());
        glUniform1ui(db::kLocMode, ss_ == Supersampling::Spatial2x ? db::kSpatial : db::kAngular);
        glBindTextureUnit(db::kUnitSource, ssTargets_->colorArray());
        glBindImageTexture(db::kImageTarget, targets_->colorArray(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glDispatchCompute((targets_->width() + db::kLocalSize - 1) / db::kLocalSize,
                          (targets_->height() + db::kLocalSize - 1) / db::kLocalSize, targets_->viewCount());
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        glBindImageTexture(db::kImageTarget, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glBindTextureUnit(db::kUnitSource, 0);
        glUseProgram(0);
        timer.end();
    }
    // gstd's panel model writes the panel image itself (the reconstruction does not apply).
    if (!renderer.writePanelImage(eia_->texture(), timer))
        buildEia(timer, reconstruction);
    timer.end();
}

uint32_t FramePipeline::renderCompleteFrame(Renderer& renderer, double time, GpuTimer& timer,
                                           Reconstruction reconstruction)
{
    renderFrame(renderer, time, timer, reconstruction);
    return completeFrame(renderer, time, reconstruction);
}

uint32_t FramePipeline::completeFrame(Renderer& renderer, double time, Reconstruction reconstruction, bool preview)
{
    // note: a renderer grows its buffers to 1.25x what the overflowing frame needed, so one
    // more render is enough unless it hit its cap; the bound only guards against a renderer
    // that can never settle.
    uint32_t again = 0;
    for (; again < 4 && !renderer.settle(); ++again) {
        GpuTimer untimed;
        if (preview)
            renderPreviewFrame(renderer, time, untimed, reconstruction);
        else
            renderFrame(renderer, time, untimed, reconstruction);
        untimed.finish();
    }
    return again;
}

uint64_t FramePipeline::frameGpuBytes(const Renderer& renderer) const
{
    // The depth arrays count only for a renderer that draws with them: in lfd-bench an
    // earlier mvr run has allocated them, but an lfdpr-only frame never does.
    const bool depth = renderer.drawsWithDepthTargets();
    uint64_t bytes = targets_->colourBytes() + (depth ? targets_->depthBytes() : 0) + eia_->bytes() +
                     renderer.frameGpuBytes();
    if (ssTargets_)
        bytes += ssTargets_->colourBytes() + (depth ? ssTargets_->depthBytes() : 0);
    return bytes;
}

DisplayProfile previewProfile(const DisplayProfile& full, const PreviewShape& shape)
{
    const uint32_t step = std::max(shape.viewStep, 1u), divisor = std::max(shape.sizeDivisor, 1u);
    return withViews(full, (full.viewCount + step - 1) / step, std::max(full.viewWidth / divisor, 1u),
                     std::max(full.viewHeight / divisor, 1u));
}

void FramePipeline::setPreviewShape(const PreviewShape& shape)
{
    previewShape_ = shape;
    previewTargets_.reset();
    previewEia_.reset();
}

void FramePipeline::renderPreviewFrame(Renderer& renderer, double time, GpuTimer& timer, Reconstruction reconstruction)
{
    if (!previewTargets_) {
        previewProfile_ = previewProfile(profile_, previewShape_);
        previewTargets_ = std::make_unique<ViewTargets>(previewProfile_.viewCount, previewProfile_.viewWidth,
                                                        previewProfile_.viewHeight);
        previewEia_ = std::make_unique<EiaBuilder>(previewProfile_);
    }
    scene_->update(time);
    frame_ = frameAt(previewProfile_, time);
    timer.begin(stage::kTotal);
    poseScene(timer);
    renderer.render(*scene_, frame_, *previewTargets_, timer);
    if (!renderer.writePanelImage(previewEia_->texture(), timer))
        previewEia_->build(*previewTargets_, reconstruction, timer);
    timer.end();
}

FrameOutputs FramePipeline::read(uint32_t frameIndex) const
{
    FrameOutputs out;
    out.frame = frameIndex;
    out.views.reserve(targets_->viewCount());
    for (uint32_t i = 0; i < targets_->viewCount(); ++i)
        out.views.push_back(targets_->readView(i));
    out.eia = eia_->read();
    return out;
}

} // namespace lfd::player
