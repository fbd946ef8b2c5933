// lfdpr, the visibility pipeline (LfdprOptions::Pipeline::Visibility, the default): owns
// its buffers and runs, per frame,
//   1. "point_generation": compute point generation (lfdpr_compute_points) into 8-byte
//      points and 16-byte triangle records; the point count is read back, and after an
//      overflow the buffer grows and generation is redone in the same frame;
//   2. "view_generation": visibility splatting of depth and the point's triangle record
//      into every view (lfdpr_visibility_shading, camera-line coherence);
//   3. "resolve": one shading per visible view pixel, as mvr shades a fragment.
#include "renderer_lfdpr.h"

#include "frame_stages.h"
#include "frame_uniforms.h"
#include "gpu_scene.h"
#include "gpu_timer.h"
#include "lfdpr_camera_line.h"
#include "lfdpr_compute_points.h"
#include "lfdpr_constants.h"
#include "lfdpr_counters.h"
#include "lfdpr_point_generation.h" // makeLfdprFrame, LfdprFrameGpu
#include "lfdpr_visibility_shading.h"
#include "scene_bindings.h"
#include "shader_library.h"
#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace lfd::player {

namespace {

using lfdpr_bindings::LfdprDrawGpu; // generated from shaders/lfdpr_bindings.glsl, checked by the layout test

class LfdprVisibilityRenderer final : public LfdprRenderer {
public:
    explicit LfdprVisibilityRenderer(const LfdprOptions& options)
        : options_(options), k_(LfdprConstants::get()), pointGeneration_(options.pixelCentreCulling, options.cellScale),
          shading_(lfdprUseInt64(options.atomics), options.testIndexRaces)
    {
        GLint64 maxBlockBytes = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlockBytes);
        maxPointCapacity_ = uint32_t(std::min<uint64_t>(
            std::max<uint32_t>(options.maxPointCapacity, 1),
            std::max<uint64_t>(uint64_t(std::max<GLint64>(maxBlockBytes, 0)) / k_.compactPointBytes, 1)));
        pointCapacity_ = std::clamp<uint32_t>(options.initialPointCapacity, 1, maxPointCapacity_);
        points_ = gl::createBuffer(size_t(pointCapacity_) * k_.compactPointBytes);
        counters_ = gl::createBuffer(k_.visCounterBytes, GL_DYNAMIC_STORAGE_BIT);
        frameUbo_ = gl::createBuffer(sizeof(LfdprFrameGpu), GL_DYNAMIC_STORAGE_BIT);
        lineUbo_ = gl::createBuffer(sizeof(LfdprCameraLineGpu), GL_DYNAMIC_STORAGE_BIT);
        dummy_ = gl::createBuffer(16);
        for (gl::Texture& t : texels_)
            t = gl::createTexture(GL_TEXTURE_BUFFER);
        info_.int64Atomics = shading_.int64();
        info_.bytesPerPoint = k_.compactPointBytes;
    }

    std::string name() const override { return "lfdpr"; }
    const LfdprOptions& options() const override { return options_; }
    const LfdprFrameInfo& lastFrame() const override { return info_; }

    std::vector<uint32_t> pointsPerTriangle() const override
    {
        // A point's record names (draw, primitive); largeBase_ holds each draw's first
        // drawn triangle.
        std::vector<uint32_t> counts(size_t(triangleCapacity_), 0);
        std::vector<glm::uvec2> points(size_t(info_.pointsStored));
        std::vector<glm::uvec4> records(size_t(info_.triangles));
        if (!points.empty())
            glGetNamedBufferSubData(points_, 0, GLsizeiptr(points.size() * sizeof(points[0])), points.data());
        if (!records.empty())
            glGetNamedBufferSubData(records_, 0, GLsizeiptr(records.size() * sizeof(records[0])), records.data());
        for (const glm::uvec2& point : points) {
            if (point.x >= records.size() || records[point.x].x >= largeBase_.size())
                continue;
            const uint64_t triangle = uint64_t(largeBase_[records[point.x].x]) + records[point.x].y;
            if (triangle < counts.size())
                ++counts[size_t(triangle)];
        }
        return counts;
    }

    void render(const GpuScene& scene, const FrameSetup& frame, ViewTargets& targets,
                GpuTimer& timer) override
    {
        // Step 1: buffers for this scene and these views; frame constants.
        if (targets.viewCount() != frame.profile.viewCount || targets.width() != frame.profile.viewWidth ||
            targets.height() != frame.profile.viewHeight)
            throw std::invalid_argument("lfdpr: view targets do not match the frame's profile");
        prepareScene(scene);
        shading_.resize(targets.viewCount(), targets.width(), targets.height());
        // note: points are sampled for frame.samplingFrame() (the display's views under
        // angular supersampling, so the cloud does not grow) and splatted into frame's.
        const FrameSetup& sampling = frame.samplingFrame();
        uniforms_.upload(sampling);
        uploadCameraLine(frame);

        // Step 2: point generation; grown and redone while the buffer overflows.
        LfdprVisCountersGpu c{};
        timer.begin(stage::kPointGeneration);
        for (;;) {
            const uint32_t options = (options_.lfdBiasedSampling ? k_.optionLfdSampling : 0u) |
                                     (options_.textureSplatting ? k_.optionTextureSplatting : 0u);
            const LfdprFrameGpu constants = makeLfdprFrame(sampling, pointCapacity_, options);
            glNamedBufferSubData(frameUbo_, 0, sizeof(constants), &constants);
            bindBuffers(scene);
            const GLuint zero = 0;
            glClearNamedBufferData(counters_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            const GLuint noGroups[4] = {0, 1, 1, 0};
            glClearNamedBufferData(largeDispatch_, GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, noGroups);
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            pointGeneration_.run(scene, largeBase_, largeDispatch_);
            c = readLfdprVisCounters(counters_);
            if (c.pointCount <= pointCapacity_ || pointCapacity_ >= maxPointCapacity_)
                break;
            // note: never drop points silently: grow to the needed count * 1.25 and redo.
            pointCapacity_ = uint32_t(std::min<double>(std::ceil(double(c.pointCount) * 1.25), double(maxPointCapacity_)));
            points_ = gl::createBuffer(size_t(pointCapacity_) * k_.compactPointBytes);
            ++info_.regenerations;
        }
        timer.end();
        const uint32_t stored = std::min(c.pointCount, pointCapacity_);
        if (frame.pointSampling) {
            uniforms_.upload(frame);
            const uint32_t options = (options_.lfdBiasedSampling ? k_.optionLfdSampling : 0u) |
                                     (options_.textureSplatting ? k_.optionTextureSplatting : 0u);
            const LfdprFrameGpu constants = makeLfdprFrame(frame, pointCapacity_, options);
            glNamedBufferSubData(frameUbo_, 0, sizeof(constants), &constants);
        }

        // Step 3: visibility, then shading once per visible pixel.
        bindBuffers(scene);
        bindSceneTexels(scene);
        timer.begin(stage::kViewGeneration);
        shading_.splat(scene, texturedMaterials_, stored);
        timer.end();
        timer.begin(stage::kResolve);
        info_.repairs = shading_.shade(scene, targets, stored);
        timer.end();

        // Step 4: what happened.
        info_.points = c.pointCount;
        info_.pointsStored = stored;
        info_.triangles = c.recordCount;
        info_.trianglesOversized = c.oversizedCount;
        trianglesCoarsened_ = c.coarsenedCount;
        info_.trianglesLarge = c.largeCount;
        info_.pointCapacity = pointCapacity_;
        info_.triangleCapacity = uint32_t(triangleCapacity_);
        info_.overflowed = c.pointCount > pointCapacity_;
        if (info_.overflowed)
            ++info_.overflowFrames;
        info_.pointBufferBytes = uint64_t(pointCapacity_) * k_.compactPointBytes;
        info_.triangleBufferBytes = triangleCapacity_ * (k_.recordBytes + sizeof(uint32_t));
        info_.viewBufferBytes = shading_.viewBufferBytes();
    }

    std::vector<std::pair<std::string, double>> extraStats() const override
    {
        return {
            {"points", double(info_.points)},
            {"bytes_per_point", double(info_.bytesPerPoint)},
            {"point_buffer_bytes", double(info_.pointBufferBytes)},
            {"triangle_buffer_bytes", double(info_.triangleBufferBytes)},
            {"view_buffer_bytes", double(info_.viewBufferBytes)},
            {"frame_gpu_bytes", double(info_.pointBufferBytes + info_.triangleBufferBytes + info_.viewBufferBytes +
                                       shading_.shadeWorkBytes())},
            {"shade_work_bytes", double(shading_.shadeWorkBytes())},
            {"point_capacity", double(info_.pointCapacity)},
            {"overflow_frames", double(info_.overflowFrames)},
            {"point_regenerations", double(info_.regenerations)},
            {"index_repairs", double(info_.repairs)},
            {"atomics", info_.int64Atomics ? 1.0 : 0.0},
            {"triangles_emitting", double(info_.triangles)},
            {"triangles_oversized", double(info_.trianglesOversized)},
            {"triangles_coarsened", double(trianglesCoarsened_)},
            {"triangles_large", double(info_.trianglesLarge)},
            {"shading_passes", double(shading_.lastShadingDispatches())},
            {"lfd_sampling", options_.lfdBiasedSampling ? 1.0 : 0.0},
            {"texture_splatting", options_.textureSplatting ? 1.0 : 0.0},
            {"pixel_centre_culling", options_.pixelCentreCulling ? 1.0 : 0.0},
            {"cell_scale", double(options_.cellScale)},
            {"pipeline_paper", 0.0},
        };
    }

private:
    // Per-scene tables: draws, the large-triangle list segments, records; the materials
    // that need a shading pass of their own (textured, drawn).
    void prepareScene(const GpuScene& scene)
    {
        if (&scene == scene_ && scene.draws().size() == drawCount_)
            return;
        scene_ = &scene;
        drawCount_ = scene.draws().size();
        std::vector<LfdprDrawGpu> draws;
        largeBase_.clear();
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
            largeBase_.push_back(uint32_t(triangles));
            triangles += d.indexCount / 3;
        }
        if (triangles > 0xFFFFFFFFull)
            throw std::invalid_argument("lfdpr: more than 2^32 drawn triangles");
        triangleCapacity_ = std::max<uint64_t>(triangles, 1);
        records_ = gl::createBuffer(triangleCapacity_ * k_.recordBytes);
        large_ = gl::createBuffer(triangleCapacity_ * sizeof(uint32_t));
        largeDispatch_ = gl::createBuffer(std::max<size_t>(draws.size(), 1) * k_.largeDispatchBytes);
        draws_ = gl::createBuffer(draws.size() * sizeof(LfdprDrawGpu), 0, draws.empty() ? nullptr : draws.data());
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
        ssbo(k_.ssboLarge, large_);
        ssbo(k_.ssboLargeDispatch, largeDispatch_);
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
    LfdprFrameInfo info_;
    FrameUniforms uniforms_;
    LfdprComputePointGeneration pointGeneration_;
    LfdprVisibilityShading shading_;
    const GpuScene* scene_ = nullptr;
    size_t drawCount_ = 0;
    std::vector<uint32_t> largeBase_;
    std::vector<int32_t> texturedMaterials_;
    gl::Buffer points_, counters_, frameUbo_, lineUbo_, dummy_, records_, large_, largeDispatch_, draws_;
    std::array<gl::Texture, 9> texels_; // buffer textures over the buffers above (bindSceneTexels)
    uint32_t pointCapacity_ = 0, maxPointCapacity_ = 0;
    uint64_t triangleCapacity_ = 0, trianglesCoarsened_ = 0;
};

} // namespace

std::unique_ptr<LfdprRenderer> createLfdprVisibilityRenderer(const LfdprOptions& options)
{
    return std::make_unique<LfdprVisibilityRenderer>(options);
}

} // namespace lfd::player
