// Compressed geometry decoded at load time (see gltf_decompress.h).
#include "gltf_decompress.h"

#include "gltf_accessors.h" // componentSize
#include "gltf_draco.h"
#include "gltf_meshopt.h"
#include "parallel.h"
#include "validation/context.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <map>
#include <optional>
#include <span>

namespace lfd::bake::gltf {
namespace {

// A non-negative integer member (the schema check has reported any other), or `fallback`.
size_t sizeOf(const json& o, const char* key, size_t fallback = 0)
{
    const auto it = o.find(key);
    const double d = it != o.end() && it->is_number() ? it->get<double>() : -1.0;
    return d >= 0 && d < 9.0e15 ? size_t(d) : fallback;
}

// Components of one element of an accessor `type` (0 for matrices, which Draco does not fill).
int componentsOf(const std::string& type)
{
    return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 0;
}

// The bytes, buffers and document being rewritten, shared by the two decoders.
class Decoder {
public:
    Decoder(json& document, std::vector<std::vector<uint8_t>>& buffers, const std::set<size_t>& withoutData,
            unsigned threads, std::vector<SchemaIssue>& issues)
        : doc_(document), buffers_(buffers), withoutData_(withoutData), threads_(threads), issues_(issues)
    {
    }

    void run()
    {
        // Views first: a Draco stream may itself lie in a meshopt-compressed view.
        meshoptViews();
        dracoPrimitives();
    }

private:
    // Bytes [offset, offset + length) of buffer b; nullopt when the file does not hold
    // them (no uri, or a problem the resources step reports) or `what` overruns it
    // (reported here, at `path`).
    std::optional<std::span<const uint8_t>> range(size_t b, size_t offset, size_t length, const std::string& path,
                                                  const std::string& what)
    {
        if (b >= buffers_.size() || withoutData_.count(b))
            return std::nullopt;
        const size_t size = buffers_[b].size();
        if (offset > size || length > size - offset) {
            issues_.push_back(makeIssue(IssueCode::COMPRESSED_DATA_OUT_OF_BOUNDS, path,
                               what + " (byteOffset " + std::to_string(offset) + ", byteLength " + std::to_string(length) +
                                   ") does not fit buffers[" + std::to_string(b) + "] (" + std::to_string(size) + " bytes)"));
            return std::nullopt;
        }
        return std::span<const uint8_t>(buffers_[b].data() + offset, length);
    }

    // Appends `bytes` as a new buffer; returns its index. Its JSON has no uri: the bytes
    // are handed to tinygltf from memory, as every buffer's are (gltf_load.cpp).
    size_t appendBuffer(std::vector<uint8_t> bytes)
    {
        if (!doc_.contains("buffers") || !doc_["buffers"].is_array())
            doc_["buffers"] = json::array();
        doc_["buffers"].push_back({{"byteLength", bytes.size()}});
        buffers_.push_back(std::move(bytes));
        return buffers_.size() - 1;
    }

    // Appends `bytes` as a new buffer with one view over all of it; returns the view index.
    size_t appendView(std::vector<uint8_t> bytes, size_t stride, int target)
    {
        if (!doc_.contains("bufferViews") || !doc_["bufferViews"].is_array())
            doc_["bufferViews"] = json::array();
        json view = {{"byteLength", bytes.size()}};
        view["buffer"] = appendBuffer(std::move(bytes));
        if (stride != 0)
            view["byteStride"] = stride;
        if (target != 0)
            view["target"] = target;
        doc_["bufferViews"].push_back(std::move(view));
        return doc_["bufferViews"].size() - 1;
    }

    void meshoptViews();
    void dracoPrimitives();
    std::optional<std::vector<DracoTarget>> dracoTargets(const json& primitive, const json& extension,
                                                         const std::string& path);
    void applyDraco(const json::json_pointer& primitivePointer, size_t view, std::vector<DracoDecoded>& decoded,
                    std::optional<DracoDecoded>& generatedIndices, const std::string& path);

    json& doc_;
    std::vector<std::vector<uint8_t>>& buffers_;
    const std::set<size_t>& withoutData_;
    ThreadBudget threads_;
    std::vector<SchemaIssue>& issues_;
    std::map<size_t, size_t> dracoFilled_; // accessor -> the Draco bufferView that filled it
};

// ---- EXT_meshopt_compression / KHR_meshopt_compression ------------------------------

void Decoder::meshoptViews()
{
    struct Item {
        size_t view;
        MeshoptView ext;
        std::span<const uint8_t> compressed;
        std::vector<uint8_t> decoded;
        std::string why;
    };
    std::vector<Item> items;
    const json& views = arrayOf(doc_, "bufferViews");
    for (size_t v = 0; v < views.size(); ++v) {
        const std::optional<MeshoptView> ext = meshoptView(views[v]);
        if (!ext)
            continue;
        const std::string path = at("bufferViews", v);
        // "Fallback buffers": the parent view's buffer must be large enough to hold the
        // decoded data, which bounds what the decoder allocates by bytes the file declares.
        const size_t parent = sizeOf(views[v], "buffer", SIZE_MAX);
        const size_t parentLength = parent < buffers_.size() ? buffers_[parent].size() : 0;
        if (sizeOf(views[v], "byteOffset") + ext->byteStride * ext->count > parentLength) {
            issues_.push_back(makeIssue(IssueCode::MESHOPT_DECODED_TOO_LONG, path, "decodes to " + std::to_string(ext->byteStride * ext->count) +
                                                 " bytes, more than its buffers[" + std::to_string(parent) + "] holds (" +
                                                 std::to_string(parentLength) + " bytes)"));
            continue;
        }
        const std::string extPath = path + ".extensions." + ext->extension;
        if (auto bytes = range(ext->buffer, ext->byteOffset, ext->byteLength, extPath, "the compressed data"))
            items.push_back({v, *ext, *bytes, {}, {}});
    }
    parallelFor(items.size(), threads_,
                [&](size_t i) { items[i].why = decodeMeshoptView(items[i].ext, items[i].compressed, items[i].decoded); });
    for (Item& item : items) {
        json& view = doc_["bufferViews"][item.view];
        if (!item.why.empty()) {
            issues_.push_back(makeIssue(IssueCode::MESHOPT_DECODE_FAILED,
                                        at("bufferViews", item.view) + ".extensions." + item.ext.extension, item.why));
            continue;
        }
        // The view keeps its own layout (byteLength, byteStride, target) over the decoded bytes.
        view["buffer"] = appendBuffer(std::move(item.decoded));
        view.erase("byteOffset");
        view["extensions"].erase(item.ext.extension);
    }
}

// ---- KHR_draco_mesh_compression -------------------------------------------------------

// The accessors a Draco primitive fills (attributes named in the extension, then the
// indices), or nullopt when the primitive cannot be decoded (reported).
std::optional<std::vector<DracoTarget>> Decoder::dracoTargets(const json& primitive, const json& extension,
                                                              const std::string& path)
{
    // The extension: "the mode of primitive must be either TRIANGLES or TRIANGLE_STRIP".
    // The decoder returns triangle lists, whose index count a strip's accessor cannot match.
    if (const size_t mode = sizeOf(primitive, "mode", 4); mode != 4) {
        issues_.push_back(makeIssue(IssueCode::DRACO_MODE_UNSUPPORTED, path + ".mode",
                           std::to_string(mode) + ": only TRIANGLES (4) primitives are decoded from Draco streams, "
                                                  "which hold triangle lists"));
        return std::nullopt;
    }
    const json& accessors = arrayOf(doc_, "accessors");
    std::vector<DracoTarget> targets;
    auto target = [&](size_t a, const std::string& use, int id) {
        const json& acc = accessors[a];
        targets.push_back({a, use, id, int(sizeOf(acc, "componentType")),
                           componentsOf(acc.value("type", std::string())), sizeOf(acc, "count")});
    };
    for (const auto& [name, id] : extension["attributes"].items())
        target(sizeOf(primitive["attributes"], name.c_str()), "attributes." + name, int(id.get<double>()));
    if (primitive.contains("indices"))
        target(sizeOf(primitive, "indices"), "indices", -1);
    return targets;
}

void Decoder::dracoPrimitives()
{
    struct Item {
        json::json_pointer primitive;
        std::string path;
        size_t view;
        std::span<const uint8_t> stream;
        std::vector<DracoTarget> targets;
        std::vector<DracoDecoded> decoded;
        std::optional<DracoDecoded> generatedIndices;
        std::string why;
    };
    std::vector<Item> items;
    const json& meshes = arrayOf(doc_, "meshes");
    const json& views = arrayOf(doc_, "bufferViews");
    for (size_t m = 0; m < meshes.size(); ++m) {
        const json& prims = meshes[m].is_object() ? meshes[m].value("primitives", json::array()) : json::array();
        for (size_t p = 0; p < prims.size(); ++p) {
            const json& prim = prims[p];
            if (!prim.is_object() || !prim.contains("extensions") || !prim["extensions"].contains(kDraco))
                continue;
            const std::string path = at("meshes", m) + "." + at("primitives", p);
            const json& ext = prim["extensions"][kDraco];
            const size_t v = sizeOf(ext, "bufferView");
            std::optional<std::vector<DracoTarget>> targets = dracoTargets(prim, ext, path);
            if (!targets)
                continue;
            const json& view = views[v];
            const std::string extPath = path + ".extensions." + kDraco;
            if (auto bytes = range(sizeOf(view, "buffer"), sizeOf(view, "byteOffset"), sizeOf(view, "byteLength"),
                                   extPath, at("bufferViews", v)))
                items.push_back({json::json_pointer("/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p)),
                                 path, v, *bytes, std::move(*targets), {}, {}, {}});
        }
    }
    parallelFor(items.size(), threads_, [&](size_t i) {
        Item& item = items[i];
        item.why = decodeDracoPrimitive(item.stream, item.targets, item.decoded, item.generatedIndices);
    });
    for (Item& item : items) {
        const std::string extPath = item.path + ".extensions." + kDraco;
        if (!item.why.empty())
            issues_.push_back(makeIssue(IssueCode::DRACO_DECODE_FAILED, extPath,
                               item.why + " (bufferViews[" + std::to_string(item.view) + "], " +
                                   std::to_string(item.stream.size()) + " bytes)"));
        else
            applyDraco(item.primitive, item.view, item.decoded, item.generatedIndices, extPath);
    }
}

// Points the accessors at their decoded data. Vertex data gets a byteStride rounded up to
// 4 bytes (section 3.6.2.4: vertex attribute elements are 4-byte aligned).
void Decoder::applyDraco(const json::json_pointer& primitivePointer, size_t view, std::vector<DracoDecoded>& decoded,
                         std::optional<DracoDecoded>& generatedIndices, const std::string& path)
{
    json& primitive = doc_[primitivePointer];
    const size_t indices = sizeOf(primitive, "indices", SIZE_MAX);
    for (DracoDecoded& d : decoded) {
        const auto [it, fresh] = dracoFilled_.emplace(d.accessor, view);
        if (!fresh) {
            if (it->second != view)
                issues_.push_back(makeIssue(IssueCode::DRACO_ACCESSOR_SHARED, path,
                                   "accessors[" + std::to_string(d.accessor) + "] is also filled by the Draco stream in " +
                                       at("bufferViews", it->second) + ": an accessor holds one decoded stream"));
            continue; // the same stream decoded again (primitives sharing it): the same data
        }
        json& accessor = doc_["accessors"][d.accessor];
        const bool isIndices = d.accessor == indices;
        const size_t element = size_t(componentsOf(accessor.value("type", std::string()))) *
                               size_t(componentSize(int(sizeOf(accessor, "componentType"))));
        const size_t stride = isIndices || element % 4 == 0 ? 0 : (element + 3) / 4 * 4;
        std::vector<uint8_t> bytes = std::move(d.bytes);
        if (stride != 0) {
            std::vector<uint8_t> padded(bytes.size() / element * stride, 0);
            for (size_t e = 0; e < bytes.size() / element; ++e)
                std::memcpy(padded.data() + e * stride, bytes.data() + e * element, element);
            bytes = std::move(padded);
        }
        accessor["bufferView"] = appendView(std::move(bytes), stride, isIndices ? 34963 : 34962);
        accessor.erase("byteOffset");
    }
    if (generatedIndices) {
        const size_t count = generatedIndices->bytes.size() / 4;
        const size_t v = appendView(std::move(generatedIndices->bytes), 0, 34963);
        doc_["accessors"].push_back({{"bufferView", v}, {"componentType", 5125}, {"count", count}, {"type", "SCALAR"}});
        primitive["indices"] = doc_["accessors"].size() - 1;
    }
}

} // namespace

void decodeCompressedGeometry(json& document, std::vector<std::vector<uint8_t>>& buffers,
                              const std::set<size_t>& withoutData, unsigned threads, std::vector<SchemaIssue>& issues)
{
    Decoder(document, buffers, withoutData, threads, issues).run();
}

} // namespace lfd::bake::gltf
