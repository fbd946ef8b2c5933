// gstd: the gold standard (renderer_gstd.h; the views model is the paper's section 5
// "GStd"). View i's interval [i, i+1) / N of the cone holds S sub-views at its exact
// angles (i + (s + 0.5) / S) / N, cameras S i + s of makeViewCamera with S N views. Each
// sub-view is drawn by mvr's programs (mvr.vert + mvr.frag, the same PBR shading) at
// `factor` times the resolution with anisotropic texture filtering, then
//  - reduced to the view resolution by the Gaussian reconstruction of
//    shaders/gstd_reconstruct.comp, averaged over the view's S sub-views (both models);
//  - in the panel model, integrated into every subpixel it lights (gstd_panel.h).
// One high-resolution framebuffer is reused for every sub-view, so memory does not grow
// with the view count.
#include "renderer_gstd.h"

#include "frame_stages.h"
#include "gstd_bindings_gpu.h"
#include "gstd_panel.h"
#include "gl_context.h"
#include "gl_handles.h"
#include "gpu_environment.h"
#include "gpu_timer.h"
#include "raster_draw.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace lfd::player {

namespace {

namespace gb = gstd_bindings;

// splitmix64 (Steele, Lea & Flood 2014): a tiny, fully specified generator, so a seed
// gives the same offsets with every compiler and standard library.
struct SplitMix64 {
    uint64_t state;
    uint64_t next()
    {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in (0, 1]: 53 random bits, never 0 (Box-Muller takes its logarithm).
    double uniform() { return (double(next() >> 11) + 1.0) * 0x1.0p-53; }
};

// The frame gstd draws: the same scene placement and time, 2N cameras at the exact
// sub-view angles, and a profile of the high-resolution size (the raster state and the
// frame constants take the viewport from it).
FrameSetup subViewFrame(const FrameSetup& frame, uint32_t factor, uint32_t subViews)
{
    FrameSetup sub = frame;
    const uint32_t n = frame.profile.viewCount * subViews;
    sub.profile.viewCount = n;
    sub.profile.viewWidth = frame.profile.viewWidth * factor;
    sub.profile.viewHeight = frame.profile.viewHeight * factor;
    sub.cameras.clear();
    sub.clipFromScene.clear();
    sub.eyeScene.clear();
    const glm::dmat4 sceneFromDisplay = glm::inverse(frame.displayFromScene);
    for (uint32_t j = 0; j < n; ++j) {
        // Camera j of S N sits at (j + 0.5) / S N of the cone: (i + (s + 0.5) / S) / N for
        // j = S i + s (formats/include/lfd/framing.h).
        const ViewCamera camera = makeViewCamera(frame.profile, frame.framing, j, n);
        sub.cameras.push_back(camera);
        sub.clipFromScene.push_back(glm::mat4(camera.clipFromDisplay * frame.displayFromScene));
        sub.eyeScene.push_back(glm::vec3(sceneFromDisplay * glm::dvec4(camera.eye, 1.0)));
    }
    return sub;
}

// A value for an error message: "-1", "0.25", "nan".
std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

bool anisotropySupported()
{
    return epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
           epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic");
}

class GstdRenderer final : public Renderer {
public:
    explicit GstdRenderer(const GstdOptions& options)
        : options_(options), offsets_(gstdSampleOffsets(options)), draw_("mvr.vert"),
          reconstruct_(gl::buildProgram({{GL_COMPUTE_SHADER, "gstd_reconstruct.comp"}})),
          sampler_(gl::createSampler())
    {
        // The scene textures' sampling for this renderer only: a sampler object bound to
        // the material units overrides the textures' own state (GpuScene's trilinear
        // REPEAT) while gstd draws, adding anisotropic filtering (paper section 5).
        glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_REPEAT);
        if (anisotropySupported()) {
            GLfloat maxSupported = 1.0f;
            glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &maxSupported);
            anisotropy_ = std::min(options_.maxAnisotropy, maxSupported);
            glSamplerParameterf(sampler_, GL_TEXTURE_MAX_ANISOTROPY, anisotropy_);
        } else {
            std::fprintf(stderr, "gstd: warning: no anisotropic filtering in this driver "
                                 "(GL_EXT_texture_filter_anisotropic); textures are trilinear\n");
        }
    }

    std::string name() const override { return "gstd"; }

    std::vector<std::pair<std::string, double>> extraStats() const override
    {
        return {{"gstd_factor", double(options_.factor)},
                {"gstd_samples", double(options_.samples)},
                {"gstd_filter_diameter", options_.filterDiameter},
                {"gstd_sub_views", double(options_.subViewCount())},
                {"gstd_model_panel", options_.model == GstdModel::Panel ? 1.0 : 0.0},
                {"anisotropy", double(anisotropy_)}};
    }

    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                GpuTimer& timer) override
    {
        timer.begin(stage::kViewGeneration);
        const uint32_t width = targets.width(), height = targets.height(), views = targets.viewCount();
        const uint32_t subViews = options_.subViewCount();
        const bool panel = options_.model == GstdModel::Panel;
        // The views model needs one interval's sub-views at a time; the panel model draws a
        // batch of intervals before integrating them (fewer passes over the panel).
        const uint32_t batch = panel ? panelBatchViews(width, height, subViews, views) : 1;
        ensureTargets(width, height, batch * subViews);
        FrameSetup sub = subViewFrame(frame, options_.factor, subViews);
        sub.lighting.environment = referenceEnvironment(frame.lighting.environment);
        if (panel) {
            if (!panel_)
                panel_ = std::make_unique<GstdPanelAccumulator>();
            panel_->begin(frame.profile, views, subViews);
        }
        panelReady_ = panel;

        GstdProgress progress{0, views * subViews, 0, (views + batch - 1) / batch, width * options_.factor,
                              height * options_.factor, panel};
        if (options_.progress)
            options_.progress(progress); // the plan, before any drawing
        for (uint32_t first = 0; first < views; first += batch) {
            const uint32_t count = std::min(batch, views - first);
            for (uint32_t view = first; view < first + count; ++view)
                for (uint32_t s = 0; s < subViews; ++s) {
                    const uint32_t layer = (view - first) * subViews + s;
                    drawSubView(scene, sub, view * subViews + s, layer); // step 1
                    reconstructView(targets, view, s, layer);           // step 2
                }
            // Step 3 (panel model): the batch's sub-views into every subpixel they reach.
            if (panel)
                panel_->add(highRes_, width * options_.factor, height * options_.factor, first, count);
            if (options_.progress) {
                glFinish(); // the report says what the GPU has finished, not what is queued
                progress.done += count * subViews;
                ++progress.batchesDone;
                options_.progress(progress);
            }
        }
        glBindTextureUnit(gb::kUnitHighRes, 0);
        glBindImageTexture(gb::kImageAccum, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(gb::kImageView, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glUseProgram(0);
        // The views are read next by the EIA pass, readbacks and blits.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        timer.end();
    }

    bool writePanelImage(unsigned eiaTexture, GpuTimer& timer) override
    {
        if (!panelReady_)
            return false;
        timer.begin(stage::kEia);
        panel_->resolve(eiaTexture);
        timer.end();
        return true;
    }

    uint64_t frameGpuBytes() const override { return panel_ ? panel_->bytes() : 0; }

private:
    // The gold standard's environment: the frame's source prefiltered with the reference
    // preset (larger faces, more levels and samples; lighting::PrefilterSettings), made once
    // per source and kept. Null without an environment.
    const GpuEnvironment* referenceEnvironment(const GpuEnvironment* environment)
    {
        if (!environment)
            return nullptr;
        if (!reference_ || reference_->key() != environment->key() || reference_->source() != environment->source())
            reference_ = withSettings(*environment, lighting::PrefilterSettings::reference());
        return reference_.get();
    }

    // Step 1: sub-view `index` (camera index of the sub-view frame) at high resolution into
    // layer `layer`, as mvr draws a view. beginFrame runs per sub-view because step 2
    // switches to the compute program (it re-uploads S N view matrices: negligible next to
    // the draw).
    void drawSubView(const GpuScene& scene, const FrameSetup& sub, uint32_t index, uint32_t layer)
    {
        GLuint samplers[5];
        std::fill(std::begin(samplers), std::end(samplers), sampler_);
        const float depthOne = 1.0f;
        glNamedFramebufferTextureLayer(highResFbo_, GL_COLOR_ATTACHMENT0, highRes_, 0, GLint(layer));
        glBindFramebuffer(GL_FRAMEBUFFER, highResFbo_);
        draw_.beginFrame(scene, sub);
        glClearNamedFramebufferfv(highResFbo_, GL_COLOR, 0, kBackground);
        glClearNamedFramebufferfv(highResFbo_, GL_DEPTH, 0, &depthOne);
        glBindSamplers(bindings::kUnitBaseColor, 5, samplers);
        glProgramUniform1i(draw_.program(), bindings::kLocView, GLint(index));
        draw_.drawScene(scene, 1);
        glBindSamplers(bindings::kUnitBaseColor, 5, nullptr);
        draw_.endFrame();
    }

    // Step 2: sub-view s of `view` (in layer `layer`) through the Gaussian reconstruction at
    // view resolution, averaged over the view's sub-views into its ViewTargets layer.
    void reconstructView(ViewTargets& targets, uint32_t view, uint32_t s, uint32_t layer)
    {
        const uint32_t width = targets.width(), height = targets.height();
        glUseProgram(reconstruct_);
        glBindTextureUnit(gb::kUnitHighRes, highRes_);
        glBindImageTexture(gb::kImageAccum, accum_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(gb::kImageView, targets.colorArray(), 0, GL_FALSE, GLint(view), GL_WRITE_ONLY, GL_RGBA8);
        glUniform2ui(gb::kLocSize, width, height);
        glUniform1ui(gb::kLocSampleCount, options_.samples);
        glUniform1ui(gb::kLocSubView, s);
        glUniform1ui(gb::kLocSubViewCount, options_.subViewCount());
        glUniform1ui(gb::kLocLayer, layer);
        glUniform2fv(gb::kLocOffsets, GLsizei(options_.samples), &offsets_[size_t(s) * options_.samples].x);
        glDispatchCompute((width + gb::kLocalSize - 1) / gb::kLocalSize, // one invocation per view pixel
                          (height + gb::kLocalSize - 1) / gb::kLocalSize, 1);
        // The accumulator is read by the next dispatch; the high-res texture is drawn into
        // again later (ordered by GL for framebuffer writes).
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // View intervals per panel batch: as many as fit 256 MiB of sub-views (and the layer
    // limits), at least one.
    uint32_t panelBatchViews(uint32_t width, uint32_t height, uint32_t subViews, uint32_t views) const
    {
        GLint maxLayers = 256;
        glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
        const uint64_t layerBytes = uint64_t(width) * height * options_.factor * options_.factor * 4;
        const uint64_t byMemory = (uint64_t(256) << 20) / std::max<uint64_t>(layerBytes * subViews, 1);
        const uint64_t byLayers = uint64_t(std::min<GLint>(maxLayers, gb::kMaxBatchLayers)) / subViews;
        return uint32_t(std::clamp<uint64_t>(std::min(byMemory, byLayers), 1, views));
    }

    // One high-resolution colour target (a layer per sub-view of a batch) + depth and
    // one view-size accumulator, made for the first frame and remade only when the view
    // size or the sub-view count changes.
    void ensureTargets(uint32_t width, uint32_t height, uint32_t layers)
    {
        if (highRes_ && width == width_ && height == height_ && layers == layers_)
            return;
        releaseTargets();
        GLint maxSize = 0, maxViewport[2] = {0, 0};
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
        const uint64_t highW = uint64_t(width) * options_.factor, highH = uint64_t(height) * options_.factor;
        const uint64_t limit = uint64_t(std::min({maxSize, maxViewport[0], maxViewport[1]}));
        if (highW > limit || highH > limit)
            throw gl::GlError("gstd: " + std::to_string(highW) + "x" + std::to_string(highH) +
                              " sub-views (factor " + std::to_string(options_.factor) +
                              ") exceed the driver's limit of " + std::to_string(limit) +
                              " pixels; use a smaller factor");
        width_ = width;
        height_ = height;

        // sRGB storage: mvr.frag writes sRGB-encoded values (GL_FRAMEBUFFER_SRGB stays
        // off, so they are stored as written), and the reconstruction's bilinear fetches
        // decode to linear light before filtering.
        layers_ = layers;
        highRes_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(highRes_, 1, GL_SRGB8_ALPHA8, GLsizei(highW), GLsizei(highH), GLsizei(layers));
        glTextureParameteri(highRes_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(highRes_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(highRes_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(highRes_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        highResDepth_ = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(highResDepth_, 1, GL_DEPTH_COMPONENT32F, GLsizei(highW), GLsizei(highH));
        highResFbo_ = gl::createFramebuffer();
        glNamedFramebufferTextureLayer(highResFbo_, GL_COLOR_ATTACHMENT0, highRes_, 0, 0);
        glNamedFramebufferTexture(highResFbo_, GL_DEPTH_ATTACHMENT, highResDepth_, 0);
        if (const GLenum status = glCheckNamedFramebufferStatus(highResFbo_, GL_FRAMEBUFFER);
            status != GL_FRAMEBUFFER_COMPLETE) {
            char hex[16];
            std::snprintf(hex, sizeof(hex), "0x%04x", unsigned(status));
            throw gl::GlError("gstd: the " + std::to_string(highW) + "x" + std::to_string(highH) + "x" +
                              std::to_string(layers) + " sub-view framebuffer (factor " +
                              std::to_string(options_.factor) + ") is incomplete: status " + hex +
                              "; try a smaller --gstd-factor");
        }
        accum_ = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(accum_, 1, GL_RGBA32F, GLsizei(width), GLsizei(height));
    }

    void releaseTargets()
    {
        highResFbo_.reset();
        highRes_.reset();
        highResDepth_.reset();
        accum_.reset();
    }

    GstdOptions options_;
    std::vector<glm::vec2> offsets_;
    RasterDraw draw_;
    gl::Program reconstruct_;
    gl::Sampler sampler_;
    gl::Texture highRes_, highResDepth_, accum_; // the high-resolution sub-views (2D array), the accumulator
    gl::Framebuffer highResFbo_;
    uint32_t width_ = 0, height_ = 0, layers_ = 0;
    float anisotropy_ = 1.0f;
    std::unique_ptr<GstdPanelAccumulator> panel_; // the panel model's, made on first use
    std::shared_ptr<const GpuEnvironment> reference_; // referenceEnvironment's
    bool panelReady_ = false;                     // the last render() filled it
};

} // namespace

void validateGstdOptions(const GstdOptions& options)
{
    if (options.factor == 0 || options.factor > 16)
        throw std::invalid_argument("gstd: factor must be 1..16, got " + std::to_string(options.factor));
    if (options.samples == 0 || options.samples > uint32_t(gb::kMaxSamples))
        throw std::invalid_argument("gstd: samples must be 1.." + std::to_string(gb::kMaxSamples) + ", got " +
                                    std::to_string(options.samples));
    if (options.subViews > 16)
        throw std::invalid_argument("gstd: sub-views per view must be 1..16 (0 = the model's default), got " +
                                    std::to_string(options.subViews));
    if (!(options.filterDiameter > 0.0) || !std::isfinite(options.filterDiameter))
        throw std::invalid_argument("gstd: the filter diameter must be positive, got " +
                                    numberText(options.filterDiameter));
    if (!(options.maxAnisotropy >= 1.0f) || !std::isfinite(options.maxAnisotropy))
        throw std::invalid_argument("gstd: the anisotropy must be at least 1, got " +
                                    numberText(options.maxAnisotropy));
}

std::vector<glm::vec2> gstdSampleOffsets(const GstdOptions& options)
{
    validateGstdOptions(options);
    // 2D Gaussian by Box-Muller, truncated at its 3-sigma support radius (resampled
    // outside it: about 1.1% of draws), so the filter is the truncated Gaussian exactly.
    const double radius = 0.5 * options.filterDiameter;
    const double sigma = radius / 3.0;
    SplitMix64 rng{options.seed};
    std::vector<glm::vec2> offsets;
    const size_t count = size_t(options.samples) * options.subViewCount();
    offsets.reserve(count);
    while (offsets.size() < count) {
        const double r = sigma * std::sqrt(-2.0 * std::log(rng.uniform()));
        const double phi = 2.0 * std::numbers::pi * rng.uniform();
        if (r <= radius)
            offsets.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)));
    }
    return offsets;
}

std::string gstdSettingsKey(const GstdOptions& options)
{
    char key[240];
    std::snprintf(key, sizeof(key), "gstd/v1 factor=%u samples=%u seed=%llu diameter=%a anisotropy=%a subviews=%u",
                  options.factor, options.samples, static_cast<unsigned long long>(options.seed),
                  options.filterDiameter, double(options.maxAnisotropy), options.subViewCount());
    std::string text = key;
    // The views model keeps its original key, so existing cache entries stay valid.
    if (options.model != GstdModel::Views)
        text += " model=" + gstdModelName(options.model);
    return text;
}

GstdModel parseGstdModel(const std::string& name)
{
    if (name == "panel")
        return GstdModel::Panel;
    if (name == "views")
        return GstdModel::Views;
    throw std::invalid_argument("unknown gstd model '" + name + "' (expected panel or views)");
}

std::string gstdModelName(GstdModel model)
{
    return model == GstdModel::Panel ? "panel" : "views";
}

std::unique_ptr<Renderer> createGstdRenderer(const GstdOptions& options)
{
    validateGstdOptions(options);
    return std::make_unique<GstdRenderer>(options);
}

} // namespace lfd::player
