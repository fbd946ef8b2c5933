// Private glue between the pack writer, the structural checks, the decoder and the
// scene checks. Not installed; nothing outside formats/src includes it.
#pragma once

#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lfd::pack {

// Throws PackError("<name>: <problem>") with any line breaks flattened, so every error
// stays one line whatever a file name or a nested exception contained.
[[noreturn]] void fail(const std::string& name, const std::string& problem);

// Mip levels of a full chain: floor(log2(max(width, height))) + 1.
uint32_t fullMipCount(uint32_t width, uint32_t height);

// Section payloads stored with zstd (format 2). compressSection returns the frame, or
// nothing when the data should stay raw (zstd would not shrink it). inflate checks that the frame holds exactly `expectedSize` bytes.
std::vector<uint8_t> compressSection(const void* data, size_t size);
// Writes a zstd frame of `size` bytes to `write` piece by piece and returns its size,
// even when it does not shrink (a texture's levels are all zstd or all raw). Data that
// would expand past kZstdMaxRatio (a uniform 16384² level) gets a zstd skippable frame
// appended, enough to keep the stored size within the bound.
using ByteSink = std::function<void(const void*, size_t)>;
uint64_t compressLevel(const void* data, size_t size, const ByteSink& write);
std::vector<uint8_t> inflate(const uint8_t* frame, size_t frameSize, uint64_t expectedSize,
                             const std::string& name, const std::string& what);
// The largest content a zstd payload of `storedSize` bytes may declare.
uint64_t maxInflatedBytes(uint64_t storedSize);

// What validateScene expects of Texture::texels / Texture::mips.
enum class TexelPolicy {
    Required,     // texels present, mips equal the full chain
    MetadataOnly, // texels ignored; mips empty or equal to the full chain
};

// Every semantic rule of the format that can be stated on a Scene (index ranges,
// references, enum values, finite floats, key times...). Shared by the writer (refuses
// to write what the reader would reject) and the reader (after decoding).
void validateScene(const Scene& scene, const std::string& name, TexelPolicy texels);
// Whether every component of a stored float (scalar, vector or quaternion) is finite: the
// validators' one test for NaN and infinity.
inline bool finite(float v) { return std::isfinite(v); }
template <glm::length_t N, typename T, glm::qualifier Q>
bool finite(const glm::vec<N, T, Q>& v)
{
    for (glm::length_t i = 0; i < N; ++i)
        if (!std::isfinite(v[i]))
            return false;
    return true;
}
inline bool finite(const glm::quat& q) { return finite(q.x) && finite(q.y) && finite(q.z) && finite(q.w); }

// The rules of skins, morph deltas, deformers and weight channels (part of validateScene).
void validateDeformation(const Scene& scene, const std::string& name);
// The rules of lights (part of validateScene).
void validateLights(const Scene& scene, const std::string& name);

// The header and section table after the structural pass: bounds, alignment, overlaps,
// padding, checksums and per-section count/stride/version rules all hold.
struct SectionTable {
    PackInfo info;
    std::vector<SectionEntry> entries; // file order
    // Decompressed payloads of the zstd sections (inflateSections), in entry order.
    std::vector<std::pair<uint32_t, std::vector<uint8_t>>> inflated;

    // The known section with this tag, or nullptr when absent (optional streams).
    const SectionEntry* find(uint32_t tag) const;
    // The section's content: the stored bytes of a raw section, the inflated bytes of a
    // zstd one (count * stride bytes either way).
    const uint8_t* payload(const uint8_t* file, const SectionEntry& entry) const;
};

// Decompresses every zstd section of a structurally valid table into table.inflated.
void inflateSections(const uint8_t* data, SectionTable& table, const std::string& name);

// Where the writer's bytes go: a memory buffer or a temporary file. Writes are
// sequential except for the final seek back to the header and table.
class Sink {
public:
    virtual ~Sink() = default;
    virtual void write(const void* data, size_t size) = 0;
    virtual void writeAt(uint64_t offset, const void* data, size_t size) = 0;
};

// Validates `scene` and writes the whole pack to `sink`, which starts empty. Throws
// PackError naming `name`.
void emitPack(Sink& sink, const Scene& scene, const TextureProducer& produce, const PackWriteOptions& options,
              const std::string& name);

// deferredChecksumTag: a section whose payload checksum is not checked here because the
// caller verifies it while reading the payload (the mapped reader's texels, which are
// hashed as they stream to the GPU instead of being read twice); 0 checks every payload.
SectionTable validateStructure(const uint8_t* data, size_t size, const std::string& name,
                               uint32_t deferredChecksumTag = 0);

// What the decoder does with the texels.
enum class TexelMode {
    Copy,   // Texture::texels hold every level as the GPU takes it (zstd levels inflated)
    Verify, // texels left empty, but every zstd level is inflated and checked (verifyPack)
    Skip,   // texels left empty and not looked at (the mapped reader streams them later)
};

// Where a texture's levels lie in TEXL as stored (format 2: zstd levels differ in size
// from the decoded levels of Texture::mips).
struct StoredTexture {
    bool zstd = false;
    std::vector<std::pair<uint64_t, uint64_t>> levels; // (offset in TEXL, stored bytes)
};

// Builds the Scene from structurally valid (and inflated) sections, checking the
// cross-section ranges (strings, channel/key runs, mip chains, texel runs) before any
// allocation they drive, then runs validateScene. `stored`, if given, receives each
// texture's stored level ranges.
Scene decodeScene(const uint8_t* data, const SectionTable& table, const std::string& name, TexelMode texels,
                  std::vector<StoredTexture>* stored = nullptr);

} // namespace lfd::pack
