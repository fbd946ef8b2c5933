// The bytes a glTF document's buffers and images name (glTF 2.0 section 3.9 "Uniform
// Resource Identifiers", 3.6.1 "Buffers", 3.8.4 "Images"), resolved by the baker itself:
// data URIs (base64 or percent-encoded, any media type), relative files (percent-decoded),
// the GLB's BIN chunk, and buffers without a URI that nothing reads. Remote URIs are
// never fetched. Every problem is a SchemaIssue with the JSON path of the buffer or image
// (internal to the baker).
#pragma once

#include "gltf_container.h"
#include "gltf_validation.h"

#include <nlohmann/json_fwd.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// What a URI names (section 3.9): a data URI, a relative reference resolved against the
// glTF file's folder, or anything with a scheme (remote, not fetched).
struct Uri {
    enum class Kind { Data, Relative, Remote } kind = Kind::Relative;
    std::string mediaType; // data: the media type ("" when omitted)
    bool base64 = false;   // data: ";base64" given
    std::string payload;   // data: after the comma; relative: the percent-decoded path
    std::string malformed; // data: why the header breaks RFC 2397's grammar ("" when it does not)
};
Uri parseUri(const std::string& uri);

// A data URI's bytes: base64-decoded, or percent-decoded text. nullopt when the payload
// is malformed (`why` says how).
std::optional<std::vector<uint8_t>> decodeDataUri(const Uri& uri, std::string& why);

// RFC 3986 percent-decoding ("%20" -> ' '); malformed escapes stay as they are.
std::string percentDecode(const std::string& text);

struct ResolvedResources {
    // Per buffer, exactly byteLength bytes (zeros where nothing supplied them: a buffer
    // nothing reads, or one whose problem was reported).
    std::vector<std::vector<uint8_t>> buffers;
    // Buffers without a uri (and not the GLB's BIN chunk), or with an empty one: valid
    // glTF ("the buffer's data MUST be provided by other means") but no bytes here. Data
    // checks skip what lies in them; the importer skips primitives that need them.
    std::set<size_t> withoutData;
    // Images given by data URIs, decoded (index -> encoded bytes).
    std::map<size_t, std::vector<uint8_t>> dataImages;
    // The buffer files read (relative URIs resolved), for the bake's depfile.
    std::vector<std::filesystem::path> files;
};

// Resolves every buffer of `document` (already schema-checked) and decodes the images' data
// URIs. A problem with the bytes of a buffer some buffer view of an accessor or image reads
// (a missing file, a remote URI, a malformed data URI, too few bytes) is an error; with one
// nothing reads, a warning. A buffer without a uri is recorded in withoutData. Images are
// checked when a material uses them (TextureTable); here only their data URIs are decoded
// (errors for malformed ones a material uses).
// Why accessor `a` of `model` has no bytes in the file - its bufferView or sparse data lies
// in a buffer of `withoutData` - as "accessors[a] lies in buffers[b], which has no uri: its
// bytes are not in the file"; "" when its bytes are there (or `a` is no accessor).
std::string bytesNotInFile(const tinygltf::Model& model, const std::set<size_t>& withoutData, int a);

ResolvedResources resolveResources(const nlohmann::json& document, const GltfContainer& container,
                                   const std::filesystem::path& baseDir, std::vector<SchemaIssue>& issues);

} // namespace lfd::bake::gltf
