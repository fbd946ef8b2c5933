// lfdpr, the visibility pipeline (LfdprOptions::Pipeline::Visibility, the default): owns
// its buffers and runs, per frame,
//   1. "point_generation": compute point generation (lfdpr_visibility_points) into 8-byte
//      points and 16-byte triangle records; as it reserves points it keeps the splat's
//      indirect dispatch covering them (GPU side, no pass of its own);
//   2. "view_generation": visibility splatting of depth and the point's triangle record
//      into every view (lfdpr_visibility_shading, camera-line coherence);
//   3. "resolve": one shading per visible view pixel, as mvr shades a fragment.
// No step waits for the GPU (docs/player/lfdpr.md "Frames that never wait"): the counters are
// copied into a read-back slot behind a fence and read frames later (gl::GpuReadback). A frame
// whose points overflowed the buffer is known then: the buffer grows for the next frames (stat
// overflow_frames), and settle() tells a caller that reads the frame's outputs to render it again.
#include "renderer_lfdpr.h"

#include "frame_stages.h"
#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "gpu_readback.h"
#include "gpu_timer.h"
#include "lfdpr_camera_line.h"
#include "lfdpr_visibility_points.h"
#include "lfdpr_constants.h"
#include "lfdpr_counters.h"
#include "lfdpr_direct_panel.h"
#include "lfdpr_paper_point_generation.h" // makeLfdprFrame, LfdprFrameGpu
#include "lfdpr_visibility_shading.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::player {

namespace {

using lfdpr_bindings::LfdprVisibilityDrawGpu; // generated from shaders/lfdpr_bindings.glsl, checked by the layout test

// A frame's read-back slot: its counters, then (32-bit path) the pixels it repaired and the
// points it queued at a depth tie.
struct CountsSlot {
    LfdprVisibilityCountersGpu counters;
    uint32_t repairs;
    uint32_t tiePoints;
};
constexpr size_t kRepairsOffset = offsetof(CountsSlot, repairs);
constexpr size_t kTiePointsOffset = offsetof(CountsSlot, tiePoints);

class LfdprVisibilityRenderer final : public LfdprRenderer {
public:
    explicit LfdprVisibilityRenderer(const LfdprOptions& options)
        : options_(options), k_(LfdprConstants::get()), gpuWork_(lfdprGpuWorkShape(options.workShape)),
          pointGeneration_(options.pixelCentreCulling, options.trimSamplingMargin, options.cellScale, gpuWork_),
          shading_(lfdprUseInt64(options.atomics), gpuWork_, lfdprHardwareAniso(options.anisoFilter),
                   options.testIndexRaces, options.countWork, options.direct != LfdprOptions::Direct::Off)
    {
        shading_.setTestTieCapacity(options.testTieCapacity);
        if (options.direct != LfdprOptions::Direct::Off)
            direct_ = std::make_unique<LfdprDirectPanel>(shading_.programDefines(), shading_.int64(),
                                                         shading_.hardwareAniso(),
                                                         options.direct == LfdprOptions::Direct::ExactRay);
        GLint64 maxBlockBytes = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlockBytes);
        maxPointCapacity_ = uint32_t(std::min<uint64_t>(
            std::max<uint32_t>(options.maxPointCapacity, 1),
            std::max<uint64_t>(uint64_t(std::max<GLint64>(maxBlockBytes, 0)) / k_.compactPointBytes, 1)));
        // 0: sized by the first frame of each scene (sizeForScene); until then a small buffer.
        pointCapacity_ = std::clamp<uint32_t>(options.initialPointCapacity ? options.initialPointCapacity : 1024u, 1,
                                              maxPointCapacity_);
        points_ = gl::createBuffer(size_t(pointCapacity_) * k_.compactPointBytes);
        counters_ = gl::createBuffer(k_.visCounterBytes, GL_DYNAMIC_STORAGE_BIT);
        frameUbo_ = gl::createBuffer(sizeof(LfdprFrameGpu), GL_DYNAMIC_STORAGE_BIT);
        lineUbo_ = gl::createBuffer(sizeof(LfdprCameraLineGpu), GL_DYNAMIC_STORAGE_BIT);
        dummy_ = gl::createBuffer(16);
        for (gl::Texture& t : texels_)
            t = gl::createTexture(GL_TEXTURE_BUFFER);
        info_.int64Atomics = shading_.int64();
        info_.hardwareAniso = shading_.hardwareAniso();
        info_.bytesPerPoint = k_.compactPointBytes;
    }

    std::string name() const override { return "lfdpr"; }
    const LfdprOptions& options() const override { return options_; }
    const LfdprFrameInfo& lastFrame() const override { return info_; }

    std::vector<uint32_t> pointsPerTriangle() const override
    {
        // A point's record sits at its triangle's drawn index (lfdpr_visibility_points.comp
        // writeRecord); the record's (draw, primitive) must name that same triangle.
        std::vector<uint32_t> counts(size_t(triangleCapacity_), 0);
        std::vector<glm::uvec2> points(size_t(info_.pointsStored));
        std::vector<glm::uvec4> records(static_cast<size_t>(triangleCapacity_));
        if (!points.empty())
            glGetNamedBufferSubData(points_, 0, GLsizeiptr(points.size() * sizeof(points[0])), points.data());
        glGetNamedBufferSubData(records_, 0, GLsizeiptr(records.size() * sizeof(records[0])), records.data());
        for (const glm::uvec2& point : points) {
            if (point.x >= records.size() || records[point.x].x >= drawFirstTriangle_.size())
                continue;
            const uint64_t triangle = uint64_t(drawFirstTriangle_[records[point.x].x]) + records[point.x].y;
            if (triangle == point.x)
                ++counts[size_t(triangle)];
        }
        return counts;
    }

    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                GpuTimer& timer) override
    {
        // Step 1: buffers for this scene and these views (grown after an overflow the
        // read-back has reported); frame constants.
        if (targets.viewCount() != frame.profile.viewCount || targets.width() != frame.profile.viewWidth ||
            targets.height() != frame.profile.viewHeight)
            throw std::invalid_argument("lfdpr: view targets do not match the frame's profile");
        prepareScene(scene);
        if (direct_)
            direct_->resize(frame.profile); // the panel's words and inverse map replace the views'
        else
            shading_.resize(targets.viewCount(), targets.width(), targets.height());
        readback_.poll([this](uint64_t tag, const uint8_t* bytes) { applyCounts(tag, bytes); });
        // note: points are sampled for frame.samplingFrame() (the display's views under
        // angular supersampling, so the cloud does not grow) and splatted into frame's.
        const FrameSetup& sampling = frame.samplingFrame();
        uniforms_.upload(sampling);
        uploadCameraLine(frame);
        const uint32_t options = (options_.lfdBiasedSampling ? k_.optionLfdSampling : 0u) |
                                 (options_.textureSplatting ? k_.optionTextureSplatting : 0u);
        sizeForScene(scene, sampling, options); // before the constants: they carry the capacity
        // Point generation sizes the splat's dispatch, for the views the points go into.
        const LfdprFrameGpu constants = makeLfdprFrame(sampling, pointCapacity_, options, frame.profile.viewCount);
        glNamedBufferSubData(frameUbo_, 0, sizeof(constants), &constants);

        // Step 2: every clear of the frame, behind one barrier; point generation, which also
        // sizes the splat's dispatch (GPU side); the counters go to a read-back slot.
        const uint64_t tag = ++frameSerial_;
        capacities_.submitted(tag, pointCapacity_);
        timer.begin(stage::kPointGeneration);
        bindBuffers(scene);
        const GLuint zero = 0, one = 1;
        glClearNamedBufferData(counters_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glClearNamedBufferSubData(counters_, GL_R32UI, offsetof(LfdprVisibilityCountersGpu, splatGroupsZ), sizeof(GLuint),
                                  GL_RED_INTEGER, GL_UNSIGNED_INT, &one);
        pointGeneration_.clearQueues();
        if (direct_)
            direct_->beginFrame(scene, texturedMaterials_);
        else
            shading_.beginFrame(scene, texturedMaterials_, targets);
        // The clears' writes (a shader's, on the GPU work shape) before every later access.
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        pointGeneration_.run(scene);
        timer.end();
        if (frame.pointSampling) {
            uniforms_.upload(frame);
            const LfdprFrameGpu splatConstants = makeLfdprFrame(frame, pointCapacity_, options);
            glNamedBufferSubData(frameUbo_, 0, sizeof(splatConstants), &splatConstants);
        }

        // Step 3: visibility, then shading once per visible pixel (or subpixel).
        splatAndShade(scene, targets, timer, tag);

        // Step 4: what is known without the GPU's counts (the counts of a frame, and the
        // capacity it ran with, come with them: applyCounts).
        info_.triangleCapacity = uint32_t(triangleCapacity_);
        info_.pointBufferBytes = uint64_t(pointCapacity_) * k_.compactPointBytes;
        info_.triangleBufferBytes = triangleCapacity_ * k_.recordBytes + pointGeneration_.bufferBytes();
        info_.viewBufferBytes = shading_.viewBufferBytes();
        // Work counters known on the CPU: what this frame's clears wrote (the counters, the
        // large-triangle queues' dispatch words and shading's clears).
        workBytesCleared_ = k_.visCounterBytes + pointGeneration_.clearedBytes() +
                            (direct_ ? direct_->clearedBytes() : shading_.clearedBytes());
        splatViews_ = frame.profile.viewCount;
    }

    // Step 3 of render(): the splat, the shading (into the views, or with LfdprOptions::Direct
    // into the panel's channel planes), and the counters to the frame's read-back slot.
    void splatAndShade(const GpuScene& scene, ViewTargets& targets, GpuTimer& timer, uint64_t tag)
    {
        bindBuffers(scene);
        bindSceneTexels(scene);
        timer.begin(stage::kViewGeneration);
        if (direct_)
            direct_->bindForSplat();
        shading_.splat(counters_);
        timer.end();
        timer.begin(stage::kResolve);
        if (direct_)
            direct_->shade(scene);
        else
            shading_.shade(scene, targets);
        timer.end();
        // The counters once the splat and the shading have added their work (countWork).
        readback_.begin(tag);
        readback_.copy(counters_, 0, 0, sizeof(LfdprVisibilityCountersGpu));
        if (!shading_.int64()) {
            readback_.copy(shading_.repairBuffer(), LfdprVisibilityShading::repairCountOffset(), kRepairsOffset,
                           sizeof(uint32_t));
            if (shading_.tiePass())
                readback_.copy(shading_.shadeWorkBuffer(), LfdprVisibilityShading::tiePointsOffset(),
                               kTiePointsOffset, sizeof(uint32_t));
        }
        readback_.end();
    }

    // The direct splat's panel (LfdprOptions::Direct): its channel planes packed into the EIA.
    bool writePanelImage(unsigned eiaTexture, GpuTimer& timer) override
    {
        if (!direct_)
            return false;
        timer.begin(stage::kEia);
        direct_->writePanel(eiaTexture);
        timer.end();
        return true;
    }

    bool settle() override
    {
        readback_.waitAll([this](uint64_t tag, const uint8_t* bytes) { applyCounts(tag, bytes); });
        // The last frame was whole unless it overflowed and the buffer has room now.
        return !(info_.overflowed && lastCountedTag_ == frameSerial_ && pointCapacity_ > info_.pointCapacity);
    }

    uint64_t frameGpuBytes() const override
    {
        return uint64_t(pointCapacity_) * k_.compactPointBytes + triangleCapacity_ * k_.recordBytes +
               pointGeneration_.bufferBytes() + shading_.viewBufferBytes() + shading_.shadeWorkBytes() +
               (direct_ ? direct_->bufferBytes() : 0);
    }

    std::vector<std::pair<std::string, double>> extraStats() const override
    {
        std::vector<std::pair<std::string, double>> stats = baseStats();
        if (options_.countWork)
            appendWorkStats(stats);
        return stats;
    }

private:
    std::vector<std::pair<std::string, double>> baseStats() const
    {
        return {
            {"points", double(info_.points)},
            {"bytes_per_point", double(info_.bytesPerPoint)},
            {"point_buffer_bytes", double(info_.pointBufferBytes)},
            {"triangle_buffer_bytes", double(info_.triangleBufferBytes)},
            {"view_buffer_bytes", double(info_.viewBufferBytes)},
            {"frame_gpu_bytes", double(info_.pointBufferBytes + info_.triangleBufferBytes + info_.viewBufferBytes +
                                       shading_.shadeWorkBytes() + (direct_ ? direct_->bufferBytes() : 0))},
            {"shade_work_bytes", double(shading_.shadeWorkBytes())},
            {"point_capacity", double(info_.pointCapacity)},
            {"overflow_frames", double(info_.overflowFrames)},
            {"point_buffer_growths", double(info_.bufferGrowths)},
            {"points_sized_at_load", double(info_.sizedPoints)},
            // Work counters of the last counted frame: points splatted, point x view pairs
            // the splat considers (every stored point in every view), bytes cleared.
            {"work_points", double(info_.pointsStored)},
            {"work_point_views", double(info_.pointsStored) * double(splatViews_)},
            {"work_bytes_cleared", double(workBytesCleared_)},
            {"index_repairs", double(info_.repairs)},
            {"tie_points", double(info_.tiePoints)},
            {"atomics", info_.int64Atomics ? 1.0 : 0.0},
            {"triangles_emitting", double(info_.triangles)},
            {"triangles_oversized", double(info_.trianglesOversized)},
            {"triangles_coarsened", double(trianglesCoarsened_)},
            {"triangles_large", double(info_.trianglesLarge)},
            {"shading_passes", double(direct_ ? direct_->lastShadingDispatches() : shading_.lastShadingDispatches())},
            {"direct_panel_bytes", double(direct_ ? direct_->bufferBytes() : 0)},
            {"lfd_sampling", options_.lfdBiasedSampling ? 1.0 : 0.0},
            {"texture_splatting", options_.textureSplatting ? 1.0 : 0.0},
            {"pixel_centre_culling", options_.pixelCentreCulling ? 1.0 : 0.0},
            {"trim_sampling_margin", options_.trimSamplingMargin ? 1.0 : 0.0},
            {"cell_scale", double(options_.cellScale)},
            {"work_shape_gpu", gpuWork_ ? 1.0 : 0.0},
            {"aniso_hardware", shading_.hardwareAniso() ? 1.0 : 0.0},
            {"pipeline_paper", 0.0},
        };
    }

    // The GPU's work counters of the last counted frame (LfdprOptions::countWork;
    // docs/player/8k-panels.md "Work counters").
    void appendWorkStats(std::vector<std::pair<std::string, double>>& stats) const
    {
        const double pointViews = double(info_.pointsStored) * double(splatViews_);
        stats.insert(stats.end(), {{"work_point_views_culled", double(info_.workCulled)},
                                   {"work_point_views_culled_by_centres", double(info_.workCulledCentres)},
                                   {"work_point_view_setups", pointViews - double(info_.workCulled)},
                                   {"work_samples", double(info_.workSamples)},
                                   {"work_atomics", double(info_.workAtomics)},
                                   {"work_words_lowered", double(info_.workLowered)},
                                   {"work_shadings", double(info_.workShadings)}});
    }

    // The point buffer sized for a scene's first frame (LfdprOptions::initialPointCapacity
    // 0): point generation runs once with capacity 0 - it stores nothing but counts every
    // point, by the same rule as a frame - and the count is read back, waiting: the one
    // wait of a scene, at its first frame, never in a steady frame. The count depends on the
    // views (pixel footprints reverse-projected at each triangle) and on the pose, so it is
    // exact for this frame only: the buffer takes kSizingHeadroom x the count, and later
    // frames that need more still grow it (applyCounts).
    void sizeForScene(const GpuScene& scene, const FrameSetup& sampling, uint32_t options)
    {
        if (options_.initialPointCapacity != 0 || sizedSerial_ == scene.serial())
            return;
        sizedSerial_ = scene.serial();
        const LfdprFrameGpu counting = makeLfdprFrame(sampling, 0, options, sampling.profile.viewCount);
        glNamedBufferSubData(frameUbo_, 0, sizeof(counting), &counting);
        bindBuffers(scene);
        const GLuint zero = 0;
        glClearNamedBufferData(counters_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        pointGeneration_.clearQueues();
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        pointGeneration_.run(scene);
        LfdprVisibilityCountersGpu c{};
        glGetNamedBufferSubData(counters_, 0, sizeof(c), &c); // waits (once per scene)
        info_.sizedPoints = c.pointCount;
        const uint32_t wanted = uint32_t(std::clamp<double>(std::ceil(double(c.pointCount) * kSizingHeadroom),
                                                            double(kMinPointCapacity), double(maxPointCapacity_)));
        if (wanted != pointCapacity_) {
            pointCapacity_ = wanted;
            points_ = gl::createBuffer(size_t(pointCapacity_) * k_.compactPointBytes);
        }
    }
    static constexpr double kSizingHeadroom = 1.5;
    static constexpr uint32_t kMinPointCapacity = 1024;

    // A frame's counters, come back from the GPU: the stats of that frame, and after an
    // overflow a point buffer grown to 1.25 x the count (never dropping points silently:
    // overflow_frames counts every frame that lost some, and settle() has the caller
    // render the last frame again).
    void applyCounts(uint64_t tag, const uint8_t* bytes)
    {
        CountsSlot slot;
        std::memcpy(&slot, bytes, sizeof(slot));
        const uint32_t capacity = capacities_.counted(tag, pointCapacity_);
        const LfdprVisibilityCountersGpu& c = slot.counters;
        lastCountedTag_ = tag;
        info_.points = c.pointCount;
        info_.pointsStored = std::min(c.pointCount, capacity);
        info_.triangles = c.recordCount;
        info_.trianglesOversized = c.oversizedCount;
        trianglesCoarsened_ = c.coarsenedCount;
        info_.trianglesLarge = c.largeCount;
        info_.repairs = shading_.int64() ? 0 : slot.repairs;
        info_.tiePoints = shading_.tiePass() ? slot.tiePoints : 0;
        info_.workCulled = c.workCulled;
        info_.workCulledCentres = c.workCulledCentres;
        info_.workSamples = c.workSamples;
        info_.workAtomics = c.workAtomics;
        info_.workLowered = c.workLowered;
        info_.workShadings = c.workShadings;
        info_.pointCapacity = capacity;
        info_.overflowed = c.pointCount > capacity;
        if (!info_.overflowed)
            return;
        ++info_.overflowFrames;
        const uint32_t wanted =
            uint32_t(std::min<double>(std::ceil(double(c.pointCount) * 1.25), double(maxPointCapacity_)));
        if (wanted > pointCapacity_) {
            pointCapacity_ = wanted;
            points_ = gl::createBuffer(size_t(pointCapacity_) * k_.compactPointBytes);
            ++info_.bufferGrowths;
        }
    }

    // Per-scene tables: draws, records, point generation's workgroups; the materials that
    // need a shading pass of their own (textured, drawn).
    void prepareScene(const GpuScene& scene)
    {
        if (scene.serial() == sceneSerial_)
            return;
        sceneSerial_ = scene.serial();
        std::vector<LfdprVisibilityDrawGpu> draws;
        drawFirstTriangle_.clear();
        texturedMaterials_.clear();
        uint64_t triangles = 0;
        const bool hasUv = (scene.cpu().vertices.mask() & kStreamUv) != 0;
        for (const DrawItem& d : scene.draws()) {
            const bool textured =
                hasUv && d.material != kNone && hasTextures(scene.cpu().materials[size_t(d.material)]);
            if (textured &&
                std::find(texturedMaterials_.begin(), texturedMaterials_.end(), d.material) == texturedMaterials_.end())
                texturedMaterials_.push_back(d.material);
        }
        const std::vector<uint32_t> groups = lfdprMaterialGroups(scene, texturedMaterials_);
        for (const DrawItem& d : scene.draws()) {
            const uint32_t material = scene.gpuMaterialIndex(d.material);
            draws.push_back({d.node, material, d.firstIndex / 3, groups[material]});
            drawFirstTriangle_.push_back(uint32_t(triangles));
            triangles += d.indexCount / 3;
        }
        if (triangles > 0xFFFFFFFFull)
            throw std::invalid_argument("lfdpr: more than 2^32 drawn triangles");
        triangleCapacity_ = std::max<uint64_t>(triangles, 1);
        records_ = gl::createBuffer(triangleCapacity_ * k_.recordBytes);
        draws_ = gl::createBuffer(draws.size() * sizeof(LfdprVisibilityDrawGpu), 0, draws.empty() ? nullptr : draws.data());
        pointGeneration_.prepare(scene, drawFirstTriangle_);
    }

    static bool hasTextures(const Material& m)
    {
        return m.baseColorTexture != kNone || m.metallicRoughnessTexture != kNone || m.normalTexture != kNone ||
               m.occlusionTexture != kNone || m.emissiveTexture != kNone;
    }

    void uploadCameraLine(const FrameSetup& frame)
    {
        const LfdprCameraLine line = makeLfdprCameraLine(frame);
        glNamedBufferSubData(lineUbo_, 0, sizeof(line.gpu), &line.gpu);
    }

    unsigned streamOrDummy(const GpuScene& scene, unsigned location) const
    {
        const unsigned b = scene.streamBuffer(location);
        return b ? b : dummy_.get();
    }

    void bindBuffers(const GpuScene& scene) const
    {
        auto ssbo = [](unsigned binding, unsigned buffer) { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer); };
        auto stream = [&](unsigned location) { return streamOrDummy(scene, location); };
        ssbo(bindings::kSsboMaterials, scene.materialBuffer());
        ssbo(bindings::kSsboNodes, scene.nodeTransformBuffer());
        ssbo(bindings::kSsboTriangleStats, scene.triangleStatsBuffer());
        ssbo(k_.ssboIndices, scene.indexBuffer());
        ssbo(k_.ssboPositions, stream(bindings::kAttribPosition));
        ssbo(k_.ssboNormals, stream(bindings::kAttribNormal));
        ssbo(k_.ssboTangents, stream(bindings::kAttribTangent));
        ssbo(k_.ssboUvs, stream(bindings::kAttribUv));
        ssbo(k_.ssboDraws, draws_);
        ssbo(k_.ssboPoints, points_);
        ssbo(k_.ssboRecords, records_);
        ssbo(k_.ssboVisCounters, counters_);
        glBindBufferBase(GL_UNIFORM_BUFFER, k_.uboFrame, frameUbo_);
        glBindBufferBase(GL_UNIFORM_BUFFER, k_.uboCameraLine, lineUbo_);
    }

    // The shading pass reads the same buffers as buffer textures (lfdpr_scene_access.glsl,
    // LFDPR_SCENE_TEXELS); attached once a frame, after point generation, since the point
    // buffer is reallocated when it grows.
    void bindSceneTexels(const GpuScene& scene) const
    {
        auto stream = [&](unsigned location) { return streamOrDummy(scene, location); };
        size_t slot = 0;
        auto texel = [&](unsigned unit, GLenum format, unsigned buffer) {
            const gl::Texture& texture = texels_[slot++];
            glTextureBuffer(texture, format, buffer);
            glBindTextureUnit(unit, texture);
        };
        texel(k_.unitIndices, GL_RGB32UI, scene.indexBuffer());
        texel(k_.unitPositions, GL_RGB32F, stream(bindings::kAttribPosition));
        texel(k_.unitNormals, GL_RGB32F, stream(bindings::kAttribNormal));
        texel(k_.unitTangents, GL_RGBA32F, stream(bindings::kAttribTangent));
        texel(k_.unitUvs, GL_RG32F, stream(bindings::kAttribUv));
        texel(k_.unitRecords, GL_RGBA32UI, records_);
        texel(k_.unitDraws, GL_RGBA32UI, draws_);
        texel(k_.unitNodes, GL_RGBA32F, scene.nodeTransformBuffer());
        texel(k_.unitMaterials, GL_RGBA32F, scene.materialBuffer());
    }

    LfdprOptions options_;
    const LfdprConstants& k_;
    bool gpuWork_; // LFDPR_WORK_GPU for every program (lfdpr_work_shape.glsl)
    LfdprFrameInfo info_;
    FrameUniforms uniforms_;
    LfdprVisibilityPointGeneration pointGeneration_;
    LfdprVisibilityShading shading_;
    std::unique_ptr<LfdprDirectPanel> direct_; // LfdprOptions::Direct on: replaces the views
    uint64_t sceneSerial_ = 0; // GpuScene::serial() of the scene the tables are for
    uint64_t sizedSerial_ = 0; // ... and of the scene the point buffer was sized for
    std::vector<uint32_t> drawFirstTriangle_;
    std::vector<int32_t> texturedMaterials_;
    gl::Buffer points_, counters_, frameUbo_, lineUbo_, dummy_, records_, draws_;
    gl::GpuReadback readback_{sizeof(CountsSlot)};
    LfdprFrameCapacities capacities_;
    uint64_t frameSerial_ = 0, lastCountedTag_ = 0;
    std::array<gl::Texture, 9> texels_; // buffer textures over the buffers above (bindSceneTexels)
    uint32_t pointCapacity_ = 0, maxPointCapacity_ = 0;
    uint64_t triangleCapacity_ = 0, trianglesCoarsened_ = 0;
    uint64_t workBytesCleared_ = 0;
    uint32_t splatViews_ = 0;
};

} // namespace

std::unique_ptr<LfdprRenderer> createLfdprVisibilityRenderer(const LfdprOptions& options)
{
    return std::make_unique<LfdprVisibilityRenderer>(options);
}

} // namespace lfd::player
