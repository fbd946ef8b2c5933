// Primitives compressed with KHR_draco_mesh_compression, decoded with Debian 12's Draco
// 1.5.5 (internal to the baker; gltf_decompress.h calls it). Specification: the
// extension's README - the decoded geometry fills the accessors of the primitive's
// `attributes` named in the extension and its `indices`, and those accessors "must match
// the decompressed data" (count, type, componentType).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

inline constexpr const char* kDraco = "KHR_draco_mesh_compression";

// An accessor the decoded geometry fills, as its JSON declares it.
struct DracoTarget {
    size_t accessor = 0;
    std::string use;        // for messages: "attributes.POSITION" or "indices"
    int dracoId = -1;       // the attribute's unique id in the stream (-1: the indices)
    int componentType = 0;  // glTF componentType (5120 ... 5126)
    int components = 0;     // 1 (SCALAR) ... 4 (VEC4)
    size_t count = 0;
};

// The decoded data of one target: `count` elements, each `components` values of its
// componentType, tightly packed.
struct DracoDecoded {
    size_t accessor = 0;
    std::vector<uint8_t> bytes;
};

// Decodes one primitive's Draco stream into the data of `targets` (the attributes and,
// when given, the indices), in their order. Without an indices target the primitive has
// none in the file: `generatedIndices` receives the decoded triangles (UNSIGNED_INT).
// Returns "" on success, otherwise one line saying why the stream cannot fill the
// accessors (corrupt or truncated stream, a missing attribute id, a count, type or
// componentType that differs from the accessor's).
std::string decodeDracoPrimitive(std::span<const uint8_t> stream, const std::vector<DracoTarget>& targets,
                                 std::vector<DracoDecoded>& out, std::optional<DracoDecoded>& generatedIndices);

} // namespace lfd::bake::gltf
