// Streams a memory-mapped pack (lfd::MappedPack) into a GpuScene built with
// GpuSceneOptions::streamed: geometry first, then every texture's mip levels coarsest
// (smallest) first, in chunks of at most `chunkBytes` read from the mapping. After each
// chunk its pages are dropped from the mapping, so the host memory streaming needs is
// one chunk (plus the driver's copy of it) whatever the pack's size. Each texture's
// GL_TEXTURE_BASE_LEVEL follows its finest resident level, so rendering can start once
// the geometry and the coarsest levels are in and sharpens as finer levels arrive.
// The texel checksum is computed on the way (MappedPack::noteTexelsRead) and compared
// when the last level is resident: a corrupt pack throws lfd::PackError then.
// Block-compressed levels upload in whole rows of 4x4 blocks; zstd-stored levels (RGBA8
// or blocks) are inflated a chunk at a time (lfd::LevelInflater) into one staging buffer
// of at most `chunkBytes`.
#pragma once

#include "gpu_scene.h"

#include "lfd/pack_mapped.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace lfd::player {

inline constexpr size_t kDefaultStreamChunkBytes = size_t(32) << 20;

class TextureStreamer {
public:
    // `scene` was built from pack->scene() (or takeScene()) with GpuSceneOptions::streamed; both must
    // outlive the streamer. Needs a current GL context for every call.
    TextureStreamer(GpuScene& scene, std::shared_ptr<MappedPack> pack, size_t chunkBytes = kDefaultStreamChunkBytes);

    // Uploads chunks until `bytes` were uploaded (at least one chunk) or all is resident;
    // returns resident().
    bool step(uint64_t bytes);
    // Until the geometry and every texture's coarsest planned level are resident.
    void untilRenderable();
    void untilResident();

    bool renderable() const { return next_ >= firstFinerJob_; }
    bool resident() const { return next_ == jobs_.size() && verified_; }
    uint64_t uploadedBytes() const { return uploaded_; }
    uint64_t totalBytes() const { return total_; }
    // GL levels of texture `index` resident (0..layout.levels); the base level is
    // layout.levels - residentLevels(index) once any is.
    uint32_t residentLevels(size_t index) const { return resident_[index]; }

private:
    struct Job {
        std::span<const uint8_t> bytes; // as stored in the pack (a zstd frame for zstd levels)
        unsigned buffer = 0;       // geometry: destination buffer
        size_t texture = SIZE_MAX; // texture: index, GL level, size, offset in TEXL
        uint32_t glLevel = 0, width = 0, height = 0;
        uint64_t texelOffset = 0;
        uint64_t texelBytes = 0; // the level as the GPU takes it
    };
    void uploadChunk();
    void uploadGeometryChunk(Job& job);
    bool uploadTextureChunk(Job& job); // true when the level is complete

    GpuScene& scene_;
    std::shared_ptr<MappedPack> pack_;
    size_t chunkBytes_;
    std::vector<Job> jobs_;
    size_t next_ = 0, firstFinerJob_ = 0;
    uint64_t doneInJob_ = 0; // bytes (geometry) or row units (texture) of jobs_[next_]
    std::unique_ptr<LevelInflater> inflater_; // the zstd level being streamed
    std::vector<uint8_t> staging_;
    uint64_t uploaded_ = 0, total_ = 0;
    std::vector<uint32_t> resident_;
    bool verified_ = false;
};

} // namespace lfd::player
