// The bytes of a glTF file as the baker reads them, before any JSON is looked at (glTF 2.0
// section 3.3 "JSON encoding" and section 4.4 "Binary glTF Layout"): the JSON text and,
// for a .glb, its BIN chunk. Every container rule the specification makes MUST-level is
// checked here and reported with the part of the file it concerns ("GLB header",
// "GLB chunk 1 (BIN)", ...), so tinygltf never sees a malformed container and never
// speaks for the baker (internal to the baker).
#pragma once

#include "gltf_validation.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

struct GltfContainer {
    bool binary = false;                    // a .glb (by its magic, not its extension)
    std::string json;                       // the JSON text (UTF-8, without a byte-order mark)
    std::optional<std::vector<uint8_t>> bin; // the GLB's BIN chunk, when it has one
};

// Reads `path` (a .gltf or .glb, told apart by the GLB magic). Container errors and
// warnings go to `issues` in file order; when an error leaves no JSON to read, `json` is
// empty. Throws BakeError naming `file` only when the file cannot be read at all.
GltfContainer readGltfContainer(const std::filesystem::path& path, const std::string& file,
                                std::vector<SchemaIssue>& issues);

} // namespace lfd::bake::gltf
