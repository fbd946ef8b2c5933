// lfdpr, the paper's pipeline (LfdprOptions::Pipeline::Paper): owns the LFDPR buffers (points, triangle records, counters, per-view
// inverses) and runs point generation, view generation and the resolve each frame; grows
// the point buffer after an overflow and reports what happened (extraStats). The counters
// come back frames later through a fenced read-back slot (gl::GpuReadback), so no frame
// waits for them; an overflowing frame renders what fits and the buffer grows once its
// counts are back (settle() has a caller that reads the outputs render it again).
#include "renderer_lfdpr.h"

#include "frame_stages.h"
#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "gl_handles.h"
#include "gpu_readback.h"
#include "gpu_timer.h"
#include "lfdpr_constants.h"
#include "lfdpr_counters.h"
#include "lfdpr_paper_point_generation.h"
#include "lfdpr_paper_view_generation.h"
#include "scene_bindings.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace lfd::player {

namespace {

class LfdprPaperRenderer final : public LfdprRenderer {
public:
    explicit LfdprPaperRenderer(const LfdprOptions& options)
        : options_(options), k_(LfdprConstants::get()), views_(lfdprUseInt64(options.atomics))
    {
        // The largest point buffer one SSBO binding can address, and the user's cap.
        GLint64 maxBlockBytes = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlockBytes);
        maxPointCapacity_ = uint32_t(std::min<uint64_t>(
            std::max<uint32_t>(options.maxPointCapacity, 1),
            std::max<uint64_t>(uint64_t(std::max<GLint64>(maxBlockBytes, 0)) / k_.pointBytes, 1)));
        pointCapacity_ = std::clamp<uint32_t>(options.initialPointCapacity ? options.initialPointCapacity : (1u << 20), 1,
                                              maxPointCapacity_);
        points_ = gl::createBuffer(size_t(pointCapacity_) * k_.pointBytes);
        counters_ = gl::createBuffer(k_.counterBytes, GL_DYNAMIC_STORAGE_BIT);
        frameUbo_ = gl::createBuffer(sizeof(LfdprFrameGpu), GL_DYNAMIC_STORAGE_BIT);
        info_.int64Atomics = views_.int64();
        info_.bytesPerPoint = k_.pointBytes;
    }

    std::string name() const override { return "lfdpr-paper"; }
    const LfdprOptions& options() const override { return options_; }
    const LfdprFrameInfo& lastFrame() const override { return info_; }

    std::vector<uint32_t> pointsPerTriangle() const override
    {
        // LfdprPaperPointGpu.triangle is the record: draw record base + primitive.
        std::vector<uint32_t> counts(size_t(recordCapacity_), 0);
        std::vector<lfdpr_bindings::LfdprPaperPointGpu> points(size_t(info_.pointsStored));
        if (!points.empty())
            glGetNamedBufferSubData(points_, 0, GLsizeiptr(points.size() * sizeof(points[0])), points.data());
        for (const lfdpr_bindings::LfdprPaperPointGpu& point : points)
            if (point.triangle < counts.size())
                ++counts[point.triangle];
        return counts;
    }

    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                GpuTimer& timer) override
    {
        // Step 1: buffers sized for this scene, these views, and the overflows whose counts
        // have come back.
        readback_.poll([this](uint64_t tag, const uint8_t* bytes) { applyCounts(tag, bytes); });
        prepareBuffers(scene, frame, targets);
        // note: points are sampled for frame.samplingFrame() (the display's views under
        // angular supersampling, so the cloud does not grow) and splatted into frame's.
        const FrameSetup& sampling = frame.samplingFrame();
        uniforms_.upload(sampling);
        const uint32_t options = (options_.lfdBiasedSampling ? k_.optionLfdSampling : 0u) |
                                 (options_.textureSplatting ? k_.optionTextureSplatting : 0u) |
                                 (options_.multiviewMipmapping ? k_.optionMvMipmapping : 0u);
        const LfdprFrameGpu constants = makeLfdprFrame(sampling, pointCapacity_, options, frame.profile.viewCount);
        glNamedBufferSubData(frameUbo_, 0, sizeof(constants), &constants);
        uploadViewInverses(frame);
        bindBuffers(scene);

        // Step 2: point generation (section 3.1).
        timer.begin(stage::kPointGeneration);
        const GLuint zero = 0;
        glClearNamedBufferData(counters_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        pointGeneration_.run(scene);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        timer.end();

        // Step 3: view generation (sections 3.2, 3.3) and the resolve into the targets.
        if (frame.pointSampling) {
            uniforms_.upload(frame);
            const LfdprFrameGpu splatConstants = makeLfdprFrame(frame, pointCapacity_, options);
            glNamedBufferSubData(frameUbo_, 0, sizeof(splatConstants), &splatConstants);
        }
        bindBuffers(scene); // the draw loop changed texture and program state, not buffers
        timer.begin(stage::kViewGeneration);
        views_.splat(counters_);
        timer.end();
        timer.begin(stage::kResolve);
        views_.resolve(targets);
        timer.end();

        // Step 4: the counters to a read-back slot (read frames later: stats, growth).
        const uint64_t tag = ++frameSerial_;
        capacities_.submitted(tag, pointCapacity_);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        readback_.begin(tag);
        readback_.copy(counters_, 0, 0, sizeof(LfdprPaperCountersGpu));
        readback_.end();
        info_.pointCapacity = pointCapacity_;
        info_.triangleCapacity = uint32_t(recordCapacity_);
        info_.pointBufferBytes = uint64_t(pointCapacity_) * k_.pointBytes;
        info_.viewBufferBytes = views_.viewBufferBytes();
    }

    bool settle() override
    {
        readback_.waitAll([this](uint64_t tag, const uint8_t* bytes) { applyCounts(tag, bytes); });
        return !(info_.overflowed && lastCountedTag_ == frameSerial_ && nextCapacity_ > info_.pointCapacity);
    }

    uint64_t frameGpuBytes() const override
    {
        return uint64_t(std::max(pointCapacity_, nextCapacity_)) * k_.pointBytes + triangleBufferBytes() +
               views_.viewBufferBytes();
    }

    std::vector<std::pair<std::string, double>> extraStats() const override
    {
        return {
            {"points", double(info_.points)},
            {"bytes_per_point", double(info_.bytesPerPoint)},
            {"point_buffer_bytes", double(info_.pointBufferBytes)},
            {"triangle_buffer_bytes", double(triangleBufferBytes())},
            {"pipeline_paper", 1.0},
            {"view_buffer_bytes", double(info_.viewBufferBytes)},
            {"point_capacity", double(info_.pointCapacity)},
            {"overflow_frames", double(info_.overflowFrames)},
            {"atomics", info_.int64Atomics ? 1.0 : 0.0},
            {"triangles_emitting", double(info_.triangles)},
            {"triangles_oversized", double(info_.trianglesOversized)},
            {"triangles_coarsened", double(trianglesCoarsened_)},
            {"lfd_sampling", options_.lfdBiasedSampling ? 1.0 : 0.0},
            {"texture_splatting", options_.textureSplatting ? 1.0 : 0.0},
            {"mv_mipmapping", options_.multiviewMipmapping ? 1.0 : 0.0},
        };
    }

private:
    size_t triangleBufferBytes() const
    {
        return size_t(recordCapacity_) * (k_.triangleRecordBytes + k_.triangleSamplingBytes);
    }

    void prepareBuffers(const GpuScene& scene, const FrameSetup& frame, const ViewTargets& targets)
    {
        if (targets.viewCount() != frame.profile.viewCount || targets.width() != frame.profile.viewWidth ||
            targets.height() != frame.profile.viewHeight)
            throw std::invalid_argument("lfdpr: view targets do not match the frame's profile");
        // Points: grow after an overflow, to the needed count * 1.25.
        if (nextCapacity_ > pointCapacity_) {
            pointCapacity_ = nextCapacity_;
            points_ = gl::createBuffer(size_t(pointCapacity_) * k_.pointBytes);
        }
        // Triangle records: one per triangle of every draw (never overflows).
        const uint64_t records = LfdprPaperPointGeneration::recordCount(scene);
        if (records > recordCapacity_ || !records_) {
            recordCapacity_ = std::max<uint64_t>(records, 1);
            records_ = gl::createBuffer(recordCapacity_ * k_.triangleRecordBytes);
            sampling_ = gl::createBuffer(recordCapacity_ * k_.triangleSamplingBytes);
        }
        views_.resize(targets.viewCount(), targets.width(), targets.height());
    }

    void uploadViewInverses(const FrameSetup& frame)
    {
        std::vector<glm::mat4> inverses;
        inverses.reserve(frame.cameras.size());
        for (const ViewCamera& camera : frame.cameras)
            inverses.push_back(glm::mat4(glm::inverse(camera.clipFromDisplay * frame.displayFromScene)));
        if (inverses.size() > viewInverseCapacity_ || !viewInverse_) {
            viewInverseCapacity_ = std::max<size_t>(inverses.size(), 1);
            viewInverse_ = gl::createBuffer(viewInverseCapacity_ * k_.viewInverseBytes, GL_DYNAMIC_STORAGE_BIT);
        }
        if (!inverses.empty())
            glNamedBufferSubData(viewInverse_, 0, GLsizeiptr(inverses.size() * sizeof(glm::mat4)),
                                 inverses.data());
    }

    void bindBuffers(const GpuScene& scene) const
    {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboMaterials, scene.materialBuffer());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboNodes, scene.nodeTransformBuffer());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSsboTriangleStats, scene.triangleStatsBuffer());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k_.ssboPoints, points_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k_.ssboTriangles, records_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k_.ssboSampling, sampling_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k_.ssboCounters, counters_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k_.ssboViewInverse, viewInverse_);
        glBindBufferBase(GL_UNIFORM_BUFFER, k_.uboFrame, frameUbo_);
    }

    // A frame's counters, come back from the GPU: its stats, and after an overflow the
    // capacity the next frames get (1.25 x the count).
    void applyCounts(uint64_t tag, const uint8_t* bytes)
    {
        LfdprPaperCountersGpu c;
        std::memcpy(&c, bytes, sizeof(c));
        const uint32_t capacity = capacities_.counted(tag, pointCapacity_);
        lastCountedTag_ = tag;
        info_.points = c.pointCount;
        info_.pointCapacity = capacity;
        info_.pointsStored = std::min<uint64_t>(c.pointCount, capacity);
        info_.triangles = c.triangleCount;
        info_.trianglesOversized = c.oversizedCount;
        trianglesCoarsened_ = c.coarsenedCount;
        info_.overflowed = c.pointCount > capacity;
        if (info_.overflowed) {
            ++info_.overflowFrames;
            nextCapacity_ = std::max(nextCapacity_, uint32_t(std::min<double>(std::ceil(double(c.pointCount) * 1.25),
                                                                              double(maxPointCapacity_))));
        }
    }

    LfdprOptions options_;
    const LfdprConstants& k_;
    LfdprFrameInfo info_;
    FrameUniforms uniforms_;
    LfdprPaperPointGeneration pointGeneration_;
    LfdprPaperViewGeneration views_;
    gl::Buffer points_, counters_, frameUbo_, records_, sampling_, viewInverse_;
    gl::GpuReadback readback_{sizeof(LfdprPaperCountersGpu)};
    LfdprFrameCapacities capacities_;
    uint64_t frameSerial_ = 0, lastCountedTag_ = 0;
    uint32_t pointCapacity_ = 0, nextCapacity_ = 0, maxPointCapacity_ = 0;
    uint64_t recordCapacity_ = 0, trianglesCoarsened_ = 0;
    size_t viewInverseCapacity_ = 0;
};

} // namespace

std::unique_ptr<LfdprRenderer> createLfdprPaperRenderer(const LfdprOptions& options)
{
    return std::make_unique<LfdprPaperRenderer>(options);
}

} // namespace lfd::player
