#include "texture_streamer.h"

#include "gpu_texture_format.h"
#include "scene_bindings.h"

#include "lfd/pack_layout.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace lfd::player {

TextureStreamer::TextureStreamer(GpuScene& scene, std::shared_ptr<MappedPack> pack, size_t chunkBytes)
    : scene_(scene), pack_(std::move(pack)), chunkBytes_(std::max<size_t>(chunkBytes, 4096))
{
    // Step 1: geometry, every buffer whole before any texel (nothing draws without it).
    auto addBuffer = [&](uint32_t tag, unsigned buffer) {
        const std::span<const uint8_t> bytes = pack_->section(tag);
        if (!bytes.empty() && buffer != 0)
            jobs_.push_back(Job{bytes, buffer});
    };
    addBuffer(pack::kTagPositions, scene_.streamBuffer(bindings::kAttribPosition));
    addBuffer(pack::kTagNormals, scene_.streamBuffer(bindings::kAttribNormal));
    addBuffer(pack::kTagTangents, scene_.streamBuffer(bindings::kAttribTangent));
    addBuffer(pack::kTagUvs, scene_.streamBuffer(bindings::kAttribUv));
    addBuffer(pack::kTagIndices, scene_.indexBuffer());
    addBuffer(pack::kTagTriangleStats, scene_.triangleStatsBuffer());

    // Step 2: texture levels, smallest first across all textures: within a texture each
    // level is smaller than the one above it, so this is coarsest-first per texture too,
    // and every texture's coarsest level comes before any texture's second level.
    const std::vector<Texture>& textures = pack_->textures();
    resident_.assign(textures.size(), 0);
    std::vector<Job> levels;
    for (size_t t = 0; t < textures.size(); ++t) {
        const GpuTextureLayout& layout = scene_.textureLayout(t);
        for (uint32_t l = 0; l < layout.levels; ++l) {
            const uint32_t packLevel = layout.firstPackLevel + l;
            const MipLevel& mip = textures[t].mips[packLevel];
            levels.push_back(Job{pack_->mipBytes(uint32_t(t), packLevel), 0, t, l, mip.width, mip.height,
                                 pack_->mipTexelOffset(uint32_t(t), packLevel), mip.size});
        }
    }
    std::stable_sort(levels.begin(), levels.end(), [](const Job& a, const Job& b) {
        return a.texelBytes != b.texelBytes ? a.texelBytes < b.texelBytes : a.texture < b.texture;
    });
    firstFinerJob_ = jobs_.size();
    jobs_.insert(jobs_.end(), levels.begin(), levels.end());
    std::vector<bool> seen(textures.size(), false);
    size_t coarsestSeen = 0;
    // The renderable point: after the job that completes the last texture's first level.
    const size_t geometryJobs = firstFinerJob_;
    for (size_t j = geometryJobs; j < jobs_.size() && coarsestSeen < textures.size(); ++j) {
        if (!seen[jobs_[j].texture]) {
            seen[jobs_[j].texture] = true;
            ++coarsestSeen;
        }
        firstFinerJob_ = j + 1;
    }
    for (const Job& job : jobs_)
        total_ += job.texture == SIZE_MAX ? job.bytes.size() : job.texelBytes;
    if (textures.empty()) {
        pack_->finishTexelVerification(); // TEXL is empty: its checksum is still checked
        verified_ = true;
    }
}

void TextureStreamer::uploadGeometryChunk(Job& job)
{
    // GL copies the client bytes before glNamedBufferSubData returns (GL 4.5 section
    // 6.2), so the chunk's pages can be dropped right after the call.
    const uint64_t n = std::min<uint64_t>(chunkBytes_, job.bytes.size() - doneInJob_);
    const uint8_t* src = job.bytes.data() + doneInJob_;
    glNamedBufferSubData(job.buffer, GLintptr(doneInJob_), GLsizeiptr(n), src);
    pack_->releasePages(src, size_t(n));
    doneInJob_ += n;
    uploaded_ += n;
}

bool TextureStreamer::uploadTextureChunk(Job& job)
{
    // Whole row units per chunk (texel rows, or rows of 4x4 blocks), at least one: a
    // 65536-wide RGBA8 level has 256 KiB rows.
    const Texture& texture = pack_->textures()[job.texture];
    const TextureFormat format = texture.format;
    const GlTextureFormat gl = glTextureFormat(format, texture.srgb);
    const uint64_t unitBytes = unitRowBytes(format, job.width);
    const uint64_t unitCount = (job.height + rowsPerUnit(format) - 1) / rowsPerUnit(format);
    const uint64_t units = std::clamp<uint64_t>(chunkBytes_ / unitBytes, 1, unitCount - doneInJob_);
    const uint64_t offset = doneInJob_ * unitBytes;
    const unsigned name = scene_.texture(int32_t(job.texture));
    if (pack_->levelsZstd(uint32_t(job.texture))) {
        if (!inflater_)
            inflater_ = std::make_unique<LevelInflater>(job.bytes, job.texelBytes, pack_->name(),
                                                        "texture " + std::to_string(job.texture) + " level " +
                                                            std::to_string(job.glLevel));
        staging_.resize(size_t(units * unitBytes));
        inflater_->read(staging_.data(), staging_.size());
        uploadLevelRows(name, GLint(job.glLevel), format, gl, job.width, job.height, uint32_t(doneInJob_),
                        uint32_t(units), staging_.data());
    } else {
        const uint8_t* src = job.bytes.data() + offset;
        uploadLevelRows(name, GLint(job.glLevel), format, gl, job.width, job.height, uint32_t(doneInJob_),
                        uint32_t(units), src);
        pack_->noteTexelsRead(job.texelOffset + offset, units * unitBytes);
        pack_->releasePages(src, size_t(units * unitBytes));
    }
    doneInJob_ += units;
    uploaded_ += units * unitBytes;
    if (doneInJob_ < unitCount)
        return false;
    if (inflater_) {
        // The whole frame has been read (LevelInflater checked it ends with the level).
        pack_->noteTexelsRead(job.texelOffset, job.bytes.size());
        pack_->releasePages(job.bytes.data(), job.bytes.size());
        inflater_.reset();
    }
    // Levels arrive finest-last per texture, so this one is the finest resident.
    resident_[job.texture] += 1;
    glTextureParameteri(name, GL_TEXTURE_BASE_LEVEL, GLint(job.glLevel));
    return true;
}

void TextureStreamer::uploadChunk()
{
    Job& job = jobs_[next_];
    bool jobDone = false;
    if (job.texture == SIZE_MAX) {
        uploadGeometryChunk(job);
        jobDone = doneInJob_ == job.bytes.size();
    } else {
        jobDone = uploadTextureChunk(job);
    }
    if (jobDone) {
        ++next_;
        doneInJob_ = 0;
        if (next_ == jobs_.size() && !verified_) {
            pack_->finishTexelVerification(); // throws PackError on corrupt texels
            verified_ = true;
        }
    }
}

bool TextureStreamer::step(uint64_t bytes)
{
    const uint64_t start = uploaded_;
    do {
        if (next_ == jobs_.size()) {
            if (!verified_) {
                pack_->finishTexelVerification();
                verified_ = true;
            }
            break;
        }
        uploadChunk();
    } while (uploaded_ - start < bytes);
    return resident();
}

void TextureStreamer::untilRenderable()
{
    while (!renderable())
        uploadChunk();
}

void TextureStreamer::untilResident()
{
    while (!resident())
        step(UINT64_MAX);
}

} // namespace lfd::player
