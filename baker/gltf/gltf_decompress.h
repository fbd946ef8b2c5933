// Compressed geometry, decoded when the file is loaded (internal to the baker):
// EXT_meshopt_compression / KHR_meshopt_compression buffer views (gltf_meshopt.h), then
// KHR_draco_mesh_compression primitives (gltf_draco.h). It runs after the buffers are
// resolved and before tinygltf and the semantic checks (gltf_load.h): each decoded stream
// becomes a buffer of its own with a buffer view over it, tightly packed, and the
// document is rewritten so that the accessors read them. Everything after - the semantic
// and data checks, the importer - sees plain accessors and checks them as it checks any
// (counts, index ranges and restart values, finite values, unit normals).
#pragma once

#include "gltf_validation.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <set>
#include <vector>

namespace lfd::bake::gltf {

// Decodes every compressed view and primitive of `document` (schema-checked) whose bytes
// the file holds, appending the decoded data to `buffers` (and to the document's buffers
// and bufferViews). Streams in `withoutData` buffers are left alone (the resources step
// reports their problem; the importer skips what needs them). A stream that cannot be
// decoded, or decodes to data that does not match its accessors, is an error in `issues`
// naming the buffer view or the primitive. Streams are decoded on up to `threads` threads
// (0: one per hardware thread, parallel.h); the result does not depend on the count.
void decodeCompressedGeometry(nlohmann::json& document, std::vector<std::vector<uint8_t>>& buffers,
                              const std::set<size_t>& withoutData, unsigned threads, std::vector<SchemaIssue>& issues);

} // namespace lfd::bake::gltf
