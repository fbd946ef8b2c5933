// Memory-mapped pack reading, for streaming large packs to the GPU (docs/player/streaming.md).
//
// readPack copies the whole file into memory, so a pack with a 16K texture needs its
// full size in host memory before the first frame. MappedPack maps the file read-only,
// runs the same structural validation and decoding as readPack on every section except
// the texel payload (TEXL), and returns the Scene with textures carrying metadata only
// (size, sRGB, mip chain; texels empty). The texels stay in the file: mipBytes() points
// into the mapping, releasePages() drops pages once they are uploaded, and the TEXL
// checksum is computed as the texels are read (noteTexelsRead) and compared at the end
// (finishTexelVerification). Errors are lfd::PackError, one line naming the file.
#pragma once

#include "lfd/pack.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace lfd {

// Decompresses one zstd-stored texture level (kTextureZstdLevels) piece by piece, so a
// streamer holds one chunk of it, not the whole level. Throws PackError (one line naming
// `name` and `what`) on a corrupt, truncated or over-long frame; the last read() checks
// that the frame ends exactly where the level does.
class LevelInflater {
public:
    LevelInflater(std::span<const uint8_t> frame, uint64_t size, std::string name, std::string what);
    ~LevelInflater();
    LevelInflater(const LevelInflater&) = delete;
    LevelInflater& operator=(const LevelInflater&) = delete;

    // The next n bytes of the level.
    void read(uint8_t* out, size_t n);
    // Decodes (and checks) the rest without keeping it.
    void skipAll();
    uint64_t remaining() const { return size_ - produced_; }

private:
    void consumeTail();
    struct State;
    std::span<const uint8_t> frame_;
    uint64_t size_ = 0, produced_ = 0;
    size_t consumed_ = 0;
    std::string name_, what_;
    std::unique_ptr<State> state_;
};

class MappedPack {
public:
    // Maps `path` and validates everything but the texel checksum. Counts and sizes are
    // checked against the file size before anything is allocated, as in readPack.
    explicit MappedPack(const std::filesystem::path& path);
    ~MappedPack();
    MappedPack(const MappedPack&) = delete;
    MappedPack& operator=(const MappedPack&) = delete;

    const std::string& name() const { return name_; }
    uint64_t fileSize() const { return size_; }
    const PackInfo& info() const { return info_; }
    // Textures carry metadata and mips only; every other field as readPack returns it.
    // Empty after takeScene().
    const Scene& scene() const { return scene_; }
    // Moves the scene out (the player's GpuScene keeps it), so the decoded geometry is
    // not held twice; textures() and the texel accessors keep working.
    Scene takeScene() { return std::move(scene_); }
    // Texture metadata (mip chains), kept for the texel accessors.
    const std::vector<Texture>& textures() const { return textures_; }

    // The content of section `tag` (pack_layout.h kTag*): the mapping for raw sections,
    // the inflated copy for zstd ones; empty when absent. Every payload but TEXL has been
    // checksummed.
    std::span<const uint8_t> section(uint32_t tag) const;
    // Mip `level` of texture `texture` in the mapping as stored, not yet verified: pass
    // what is read to noteTexelsRead before releasing its pages. The level's texels as
    // the GPU takes them (rows of texels or of 4x4 blocks, textures()[t].format) when
    // levelsZstd(texture) is false; a zstd frame of them (LevelInflater) when it is true.
    std::span<const uint8_t> mipBytes(uint32_t texture, uint32_t level) const;
    bool levelsZstd(uint32_t texture) const { return levelsZstd_.at(texture); }
    // Byte offset of mipBytes(texture, level) within the TEXL payload.
    uint64_t mipTexelOffset(uint32_t texture, uint32_t level) const;

    // Hashes the TEXL bytes [offset, offset + size) that were just read. XXH3 is
    // sequential, so a range past the verified prefix first hashes the gap (from the
    // mapping, releasing it again); a range inside the prefix is already counted.
    void noteTexelsRead(uint64_t offset, uint64_t size);
    // Hashes the rest of TEXL and compares with the section checksum; throws PackError
    // "<file>: section 'TEXL' checksum mismatch (corrupt texels)" on a mismatch.
    void finishTexelVerification();
    bool texelsVerified() const { return verified_; }
    uint64_t texelBytesVerified() const { return hashedUpTo_; }

    // Drops this process's pages of [data, data + size) (whole pages inside the range;
    // madvise MADV_DONTNEED): the mapping stays valid and a later read faults the page
    // in again from the page cache, so resident memory stays bounded by what is in use.
    void releasePages(const void* data, size_t size) const;
    // Drops every page of the mapping.
    void releaseAll() const;

private:
    struct HashState;
    void hashRange(uint64_t offset, uint64_t size);

    std::string name_;
    const uint8_t* data_ = nullptr;
    uint64_t size_ = 0;
    bool mapped_ = false;
    PackInfo info_;
    Scene scene_;
    std::vector<Texture> textures_; // scene_.textures (metadata only), outlives takeScene()
    uint64_t texlOffset_ = 0, texlSize_ = 0, texlChecksum_ = 0;
    std::vector<bool> levelsZstd_;
    std::vector<std::vector<std::pair<uint64_t, uint64_t>>> storedLevels_; // (offset in TEXL, bytes)
    std::vector<std::pair<uint32_t, std::span<const uint8_t>>> sections_;
    std::vector<std::pair<uint32_t, std::vector<uint8_t>>> inflated_; // zstd sections' content
    std::unique_ptr<HashState> hash_;
    uint64_t hashedUpTo_ = 0;
    bool verified_ = false;
};

} // namespace lfd
