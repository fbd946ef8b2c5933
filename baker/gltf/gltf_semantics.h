// The glTF 2.0 rules beyond the JSON schema that concern data the baker reads: links
// between objects (scene roots, shared buffer views and their strides, animation targets,
// morph-target counts) and the contents of accessors (bounds within their views, index
// ranges and primitive-restart values, unit normals and tangents, animation key times).
// Runs on the whole document, storage (buffer views, accessors) before its users, before the
// importer converts anything, so a defect is named with its JSON path even in a file with
// nothing to render. MUST
// rules of the specification are errors; SHOULD rules and what the baker can work around
// with a stated result are warnings (docs/baker/lfd-bake.md "Validation") (internal to the baker).
#pragma once

#include "gltf_validation.h"

#include <nlohmann/json_fwd.hpp>
#include <tiny_gltf.h>

#include <set>
#include <vector>

namespace lfd::bake::gltf {

// Appends every finding to `issues`. `model` is tinygltf's parse of `document` (with
// accessors without a bufferView given one over zeros, appended after the document's own
// buffers and views; indices of the document's objects are unchanged).
// Data checks skip accessors whose bytes lie in `buffersWithoutData` (buffers the file
// holds no bytes for).
void validateGltfSemantics(const tinygltf::Model& model, const nlohmann::json& document,
                           const std::set<size_t>& buffersWithoutData, std::vector<SchemaIssue>& issues);

} // namespace lfd::bake::gltf
