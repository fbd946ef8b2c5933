// .lfdpack (format version 2, kFormatVersion; version 1 packs stay readable): write,
// verify and read. The on-disk layout is documented field by field in formats/README.md;
// the constants live in pack_layout.h.
//
// Every pack is untrusted input: readPack/verifyPack check magic, version, section table
// bounds, alignment, checksums, counts, index ranges, references and finite floats
// before anything is returned. Errors are reported as lfd::PackError whose what() is one
// line naming the file and the problem.
#pragma once

#include "lfd/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd {

class PackError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Produces texture `index` (texels + mips filled) just before it is written, so the
// writer never holds more than one baked texture at a time. The Texture passed to
// writePack in Scene::textures may then carry metadata only (texels empty).
using TextureProducer = std::function<Texture(uint32_t index)>;

struct PackSectionInfo {
    std::string tag; // four characters, e.g. "VPOS"
    uint32_t version = 0;
    uint64_t offset = 0;
    uint64_t size = 0;
    uint64_t checksum = 0; // XXH3-64 of the payload
    uint64_t count = 0;    // elements in the section
    uint32_t encoding = 0; // pack::SectionEncoding: 0 raw, 1 zstd (size is then the stored bytes)
};

struct PackInfo {
    uint32_t formatVersion = 0;
    uint64_t fileSize = 0;
    std::vector<PackSectionInfo> sections;
};

// How payloads are stored (formats/README.md "Compression").
struct PackWriteOptions {
    // zstd for the geometry and key sections and for every texture's levels (RGBA8 or
    // blocks), wherever it makes them smaller. Off: every byte stored raw (as format 1 did).
    bool compress = true;
};

// Writes `scene` to `path` atomically: a temporary file next to `path` is written,
// flushed and renamed over `path`; on any failure the temporary is removed and `path`
// is left untouched. If `produce` is set, texture i's texels come from produce(i).
// Throws PackError.
void writePack(const std::filesystem::path& path, const Scene& scene,
               const TextureProducer& produce = {}, const PackWriteOptions& options = {});

// Reads and fully validates a pack. Throws PackError (one line: "<file>: <problem>").
// `info`, if given, receives the section table (what verifyPack returns) from the same read.
Scene readPack(const std::filesystem::path& path, PackInfo* info = nullptr);

// Validates without keeping the scene; returns the section table for reports.
PackInfo verifyPack(const std::filesystem::path& path);

// In-memory variants (used by tests and fuzzing). `name` is used in error messages.
std::vector<uint8_t> writePackToMemory(const Scene& scene, const TextureProducer& produce = {},
                                       const PackWriteOptions& options = {});
Scene readPackFromMemory(const uint8_t* data, size_t size, const std::string& name);

} // namespace lfd
