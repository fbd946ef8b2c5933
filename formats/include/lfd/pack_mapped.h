// Memory-mapped pack reading, for streaming large packs to the GPU (README "Streaming").
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

    // The payload of section `tag` (pack_layout.h kTag*) in the mapping; empty when absent.
    // Every payload but TEXL has been checksummed.
    std::span<const uint8_t> section(uint32_t tag) const;
    // Mip `level` of texture `texture` in the mapping (RGBA8 rows, top to bottom), not yet
    // verified: pass what is read to noteTexelsRead before releasing its pages.
    std::span<const uint8_t> mipBytes(uint32_t texture, uint32_t level) const;
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
    std::vector<uint64_t> textureTexelStart_; // offset of each texture's level 0 in TEXL
    std::vector<std::pair<uint32_t, std::span<const uint8_t>>> sections_;
    std::unique_ptr<HashState> hash_;
    uint64_t hashedUpTo_ = 0;
    bool verified_ = false;
};

} // namespace lfd
