// meshopt-compressed buffer views (see gltf_meshopt.h).
#include "gltf_meshopt.h"

#include "gltf_json.h"

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

namespace lfd::bake::gltf {
namespace {

using json = nlohmann::json;

// A non-negative integer member ("count": 4.0 is one, as the schema check accepts it), or
// `fallback` when absent.
std::optional<size_t> size(const json& o, const char* key, size_t fallback)
{
    return o.contains(key) ? jsonIndex(o, key) : fallback;
}

// Appendix A: the first byte of each stream is 0xa0 | version (attributes), 0xe0 |
// version (triangles) or 0xd0 | version (indices). meshoptimizer 0.18 decodes attribute
// version 0 and index versions 0 and 1 (EXT_meshopt_compression's); KHR_meshopt_compression
// adds attribute version 1. Named here so the message says why, not just "corrupt".
std::string unsupportedVersion(const MeshoptView& view, std::span<const uint8_t> compressed)
{
    if (view.mode != "ATTRIBUTES" || compressed.empty() || (compressed[0] & 0xf0) != 0xa0 || (compressed[0] & 0x0f) == 0)
        return {};
    return "the stream uses attribute codec version " + std::to_string(compressed[0] & 0x0f) +
           ", which meshoptimizer 0.18 (Debian 12) does not decode (it has version 0, EXT_meshopt_compression's)";
}

// Appendix B, applied in place after the attribute codec.
std::string applyFilter(const MeshoptView& view, std::vector<uint8_t>& data)
{
    const size_t stride = view.byteStride;
    if (view.filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
        meshopt_decodeFilterOct(data.data(), view.count, stride);
    else if (view.filter == "QUATERNION" && stride == 8)
        meshopt_decodeFilterQuat(data.data(), view.count, stride);
    else if (view.filter == "EXPONENTIAL" && stride % 4 == 0)
        meshopt_decodeFilterExp(data.data(), view.count, stride);
    else if (view.filter == "COLOR")
        return "filter COLOR (KHR_meshopt_compression) is not in meshoptimizer 0.18 (Debian 12)";
    else if (view.filter != "NONE")
        return "filter " + view.filter + " does not fit byteStride " + std::to_string(stride);
    return {};
}

} // namespace

std::optional<MeshoptView> meshoptView(const json& view)
{
    if (!view.is_object() || !view.contains("extensions") || !view["extensions"].is_object())
        return std::nullopt;
    const json& extensions = view["extensions"];
    for (const char* name : {kExtMeshopt, kKhrMeshopt}) {
        const auto it = extensions.find(name);
        if (it == extensions.end() || !it->is_object())
            continue;
        const json& e = *it;
        MeshoptView out;
        out.extension = name;
        const auto buffer = size(e, "buffer", SIZE_MAX), offset = size(e, "byteOffset", 0),
                   length = size(e, "byteLength", 0), stride = size(e, "byteStride", 0), count = size(e, "count", 0);
        if (!buffer || *buffer == SIZE_MAX || !offset || !length || !stride || !count || !e.contains("mode") ||
            !e["mode"].is_string())
            return std::nullopt; // reported by the schema check
        out.buffer = *buffer;
        out.byteOffset = *offset;
        out.byteLength = *length;
        out.byteStride = *stride;
        out.count = *count;
        out.mode = e["mode"].get<std::string>();
        out.filter = e.contains("filter") && e["filter"].is_string() ? e["filter"].get<std::string>() : "NONE";
        return out;
    }
    return std::nullopt;
}

std::string decodeMeshoptView(const MeshoptView& view, std::span<const uint8_t> compressed, std::vector<uint8_t>& out)
{
    if (std::string why = unsupportedVersion(view, compressed); !why.empty())
        return why;
    // The schema check keeps byteStride * count within the parent view's byteLength, which
    // lies inside its buffer: no overflow, and no more memory than the file declares.
    out.assign(view.byteStride * view.count, 0);
    int status = -1;
    if (view.mode == "ATTRIBUTES" && view.byteStride % 4 == 0 && view.byteStride <= 256)
        status = meshopt_decodeVertexBuffer(out.data(), view.count, view.byteStride, compressed.data(), compressed.size());
    else if (view.mode == "TRIANGLES" && view.count % 3 == 0 && (view.byteStride == 2 || view.byteStride == 4))
        status = meshopt_decodeIndexBuffer(out.data(), view.count, view.byteStride, compressed.data(), compressed.size());
    else if (view.mode == "INDICES" && (view.byteStride == 2 || view.byteStride == 4))
        status = meshopt_decodeIndexSequence(out.data(), view.count, view.byteStride, compressed.data(), compressed.size());
    else
        return "mode " + view.mode + " does not fit byteStride " + std::to_string(view.byteStride) + " and count " +
               std::to_string(view.count);
    if (status != 0)
        return "the " + std::to_string(compressed.size()) + "-byte " + view.mode + " stream does not decode to " +
               std::to_string(view.count) + " elements of " + std::to_string(view.byteStride) +
               " bytes (corrupt or truncated; meshoptimizer error " + std::to_string(status) + ")";
    return view.mode == "ATTRIBUTES" ? applyFilter(view, out) : std::string();
}

} // namespace lfd::bake::gltf
