// Loading a glTF file for the import stage (internal to the baker): the baker checks the
// whole document itself, in this order, before anything is converted - the container
// (gltf_container.h), the JSON, the schema of every property the baker reads
// (gltf_validation.h), the buffers and images the URIs name (gltf_resources.h), then the
// document's semantics and data (gltf_validation.h). tinygltf only parses JSON that has
// passed, with every buffer's bytes handed to it from memory, so its own messages never
// reach the user. Compressed geometry (Draco, meshopt) is decoded between the resources and
// the semantics (gltf_decompress.h), so the semantic checks see plain accessors. Every
// finding names the file and a JSON path (docs/baker/lfd-bake.md "Validation").
#pragma once

#include "gltf_validation.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// A skin as the document gives it (section 3.7.3). tinygltf does not parse skins (see
// documentForTinygltf); the importer reads these instead. Joints outside the node list
// are dropped here (the semantic checks warned), -1: no inverse bind matrices.
struct SkinJson {
    std::string name;
    std::vector<int> joints;
    int inverseBindMatrices = -1;
};

struct LoadedGltf {
    tinygltf::Model model;
    std::vector<SkinJson> skins; // the document's "skins", in order
    // Images given by data URIs, decoded (image index -> encoded bytes): tinygltf holds
    // none of them.
    std::map<size_t, std::vector<uint8_t>> dataImages;
    // Buffers whose bytes the file does not hold (no uri: "provided by other means"). The
    // importer skips a primitive that needs them, with a warning naming what needed them.
    std::set<size_t> buffersWithoutData;
    // Accessors without a bufferView and without sparse data: zeros, "unless an extension
    // overrides them" (section 3.6.2.3), so what they stand for is not in the file.
    std::set<size_t> accessorsWithoutData;
    // The buffer files read besides the glTF itself (for the bake's depfile).
    std::vector<std::filesystem::path> bufferFiles;
};

// The extensions the baker honours when a file requires them: KHR_mesh_quantization
// (wider accessor component types, which the accessor reader handles),
// KHR_materials_emissive_strength (folded into emissiveFactor), KHR_texture_transform and
// KHR_materials_unlit (gltf_material_extensions.h), KHR_lights_punctual (gltf_lights.h),
// KHR_draco_mesh_compression and EXT_/KHR_meshopt_compression (decoded at load:
// gltf_decompress.h) and EXT_texture_webp (WebP images, decoded by the texture stage).
const std::set<std::string>& supportedExtensions();

// Loads `path`, appending every finding of its checks to `issues`. When any check finds an
// error, throws BakeError naming `file` and the first error in check order (with the number
// of others; `issues` then holds the findings up to that check, errors included); otherwise
// returns the model (`issues` holds warnings only). Compressed geometry is decoded on up to
// `threads` threads (0: one per hardware thread).
LoadedGltf loadGltf(const std::filesystem::path& path, const std::string& file, std::vector<SchemaIssue>& issues,
                    unsigned threads = 0);

} // namespace lfd::bake::gltf
