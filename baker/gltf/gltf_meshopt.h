// Buffer views compressed with EXT_meshopt_compression (or KHR_meshopt_compression, the
// same JSON), decoded with Debian 12's meshoptimizer 0.18 (internal to the baker;
// gltf_decompress.h calls it). Specification: the extension's README, "JSON schema
// updates" (the layout), Appendix A (the bitstreams) and Appendix B (the filters).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// The two names of the extension; a buffer view carries at most one of them.
inline constexpr const char* kExtMeshopt = "EXT_meshopt_compression";
inline constexpr const char* kKhrMeshopt = "KHR_meshopt_compression";

// A compressed view's extension object, as the schema validation accepted it.
struct MeshoptView {
    std::string extension; // kExtMeshopt or kKhrMeshopt
    size_t buffer = 0;     // the buffer holding the compressed bytes
    size_t byteOffset = 0;
    size_t byteLength = 0;
    size_t byteStride = 0; // of the decoded elements
    size_t count = 0;      // decoded elements
    std::string mode;      // ATTRIBUTES, TRIANGLES or INDICES
    std::string filter;    // NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL or COLOR
};

// The extension of buffer view `view` (its JSON), or nullopt when it has none or the
// schema check reported it.
std::optional<MeshoptView> meshoptView(const nlohmann::json& view);

// Decodes `compressed` into byteStride * count bytes. Returns "" on success, otherwise
// why the stream cannot be decoded (one line: corrupt, truncated, or a codec version or
// filter meshoptimizer 0.18 does not have).
std::string decodeMeshoptView(const MeshoptView& view, std::span<const uint8_t> compressed, std::vector<uint8_t>& out);

} // namespace lfd::bake::gltf
