// Private glue between the pack writer, the structural checks, the decoder and the
// scene checks. Not installed; nothing outside formats/src includes it.
#pragma once

#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::pack {

// Throws PackError("<name>: <problem>") with any line breaks flattened, so every error
// stays one line whatever a file name or a nested exception contained.
[[noreturn]] void fail(const std::string& name, const std::string& problem);

// Full mip chain of a width x height RGBA8 texture: level l is
// max(1, width >> l) x max(1, height >> l), levels back to back from offset 0.
uint32_t fullMipCount(uint32_t width, uint32_t height);
std::vector<MipLevel> mipChain(uint32_t width, uint32_t height);
uint64_t mipChainBytes(uint32_t width, uint32_t height);

// What validateScene expects of Texture::texels / Texture::mips.
enum class TexelPolicy {
    Required,     // texels present, mips equal the full chain
    MetadataOnly, // texels ignored; mips empty or equal to the full chain
};

// Every semantic rule of the format that can be stated on a Scene (index ranges,
// references, enum values, finite floats, key times...). Shared by the writer (refuses
// to write what the reader would reject) and the reader (after decoding).
void validateScene(const Scene& scene, const std::string& name, TexelPolicy texels);

// The header and section table after the structural pass: bounds, alignment, overlaps,
// padding, checksums and per-section count/stride/version rules all hold.
struct SectionTable {
    PackInfo info;
    std::vector<SectionEntry> entries; // file order

    // The known section with this tag, or nullptr when absent (optional streams).
    const SectionEntry* find(uint32_t tag) const;
};

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
void emitPack(Sink& sink, const Scene& scene, const TextureProducer& produce, const std::string& name);

// deferredChecksumTag: a section whose payload checksum is not checked here because the
// caller verifies it while reading the payload (the mapped reader's texels, which are
// hashed as they stream to the GPU instead of being read twice); 0 checks every payload.
SectionTable validateStructure(const uint8_t* data, size_t size, const std::string& name,
                               uint32_t deferredChecksumTag = 0);

// Builds the Scene from structurally valid sections, checking the cross-section ranges
// (strings, channel/key runs, mip chains, texel runs) before any allocation they drive,
// then runs validateScene. Without texels, Texture::texels stay empty (verifyPack).
Scene decodeScene(const uint8_t* data, const SectionTable& table, const std::string& name,
                  bool withTexels);

} // namespace lfd::pack
