// Strict glTF 2.0 validation for the import stage (internal to the baker), in two phases
// over the same objects: the JSON schema (before tinygltf parses the file) and the rules
// beyond it (after, on tinygltf's model).
//
// tinygltf is a lenient loader: a property of the wrong JSON type, a negative index or an
// unknown enum value is silently dropped or defaulted, so a broken file would bake into
// something other than what its author wrote. The schema phase walks the raw JSON of every
// property the baker reads (glTF 2.0 specification, section 5 "Properties Reference" and
// the JSON schema) and reports each violation with its JSON path, for example
// `materials[0].pbrMetallicRoughness: expected an object, got an array`. The semantic
// phase checks links between objects (scene roots, shared buffer views and their strides,
// animation targets, morph-target counts) and the contents of accessors (bounds within
// their views, index ranges, unit normals and tangents, animation key times).
//
// The checks live in validation/, one file per glTF object with both phases of it; every
// finding carries a code of the catalogue (gltf_issue_codes.h, docs/baker/gltf-issues.md).
//
// Severity (docs/baker/lfd-bake.md "Validation"):
//   Error   - the baker cannot know what the author meant: a wrong type, a missing
//             required property, a reference to something that does not exist, an enum
//             value it cannot interpret in a property it reads. The file is refused.
//   Warning - a sensible bake is still possible and the message says what the baker
//             does: out-of-range factors (clamped), non-unit rotations (normalised), wrong
//             types or values in properties the baker never reads (names, samplers,
//             cameras, skins, optional extensions). `lfd-bake --strict` refuses these too.
#pragma once

#include "gltf_issue_codes.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lfd::bake::gltf {

struct SchemaIssue {
    using Severity = IssueSeverity;
    IssueCode code = IssueCode::TYPE_MISMATCH;
    Severity severity = Severity::Error;
    std::string path;    // JSON path, e.g. "materials[0].pbrMetallicRoughness"
    std::string message; // e.g. "expected an object, got an array"

    std::string text() const { return path + ": " + message; }
};

// A finding of kind `code` at `path`, with the code's severity (a Warning where `use` is
// kIgnored: gltf_issue_codes.h).
SchemaIssue makeIssue(IssueCode code, std::string path, std::string message, Use use = kRead);

// Every schema violation in `document` (the glTF JSON), in document order.
std::vector<SchemaIssue> validateGltfSchema(const nlohmann::json& document);

// Appends every semantic finding to `issues`, storage (buffer views, accessors) before its
// users. `model` is tinygltf's parse of `document` (with accessors without a bufferView
// given one over zeros, appended after the document's own buffers and views; indices of the
// document's objects are unchanged). Data checks skip accessors whose bytes lie in
// `buffersWithoutData` (buffers the file holds no bytes for).
void validateGltfSemantics(const tinygltf::Model& model, const nlohmann::json& document,
                           const std::set<size_t>& buffersWithoutData, std::vector<SchemaIssue>& issues);

// The accessors (by index) that a mesh (attributes, indices, morph targets) or an animation
// sampler reads: a defect in one of them refuses the file, in any other it is a warning.
std::set<int64_t> accessorsReadByMeshesAndAnimations(const nlohmann::json& document);

} // namespace lfd::bake::gltf
