// Strict glTF 2.0 schema validation for the import stage (internal to the baker).
//
// tinygltf is a lenient loader: a property of the wrong JSON type, a negative index or an
// unknown enum value is silently dropped or defaulted, so a broken file would bake into
// something other than what its author wrote. The validator walks the raw JSON of every
// property the baker reads (glTF 2.0 specification, section 5 "Properties Reference" and
// the JSON schema) and reports each violation with its JSON path, for example
// `materials[0].pbrMetallicRoughness: expected an object, got an array`.
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

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

struct SchemaIssue {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    std::string path;    // JSON path, e.g. "materials[0].pbrMetallicRoughness"
    std::string message; // e.g. "expected an object, got an array"

    std::string text() const { return path + ": " + message; }
};

// The severities the validation stages report with, by short name.
inline constexpr SchemaIssue::Severity kError = SchemaIssue::Severity::Error;
inline constexpr SchemaIssue::Severity kWarn = SchemaIssue::Severity::Warning;

// Every violation in `document` (the glTF JSON), in document order.
std::vector<SchemaIssue> validateGltfSchema(const nlohmann::json& document);

// The accessors (by index) that a mesh (attributes, indices, morph targets) or an animation
// sampler reads: a defect in one of them refuses the file, in any other it is a warning.
std::set<int64_t> accessorsReadByMeshesAndAnimations(const nlohmann::json& document);

} // namespace lfd::bake::gltf
