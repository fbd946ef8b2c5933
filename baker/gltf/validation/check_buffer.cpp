// Buffers and buffer views (glTF 2.0 sections 3.6.1, 5.10, 5.11), with EXT_/
// KHR_meshopt_compression on buffer views: their JSON; the views' strides and extents in
// their buffers. (The bytes a buffer's uri names: gltf_resources.cpp.)
#include "validation/checks.h"
#include "validation/model_context.h"

#include <cstring>
#include <set>

namespace lfd::bake::gltf {
namespace {

// The stride and layout rules of a meshopt extension object, "for the extension object to
// be valid" (EXT_meshopt_compression / KHR_meshopt_compression, "JSON schema updates").
void meshoptRules(ValidationContext& ctx, const std::string& path, const json& view, int64_t stride, int64_t count,
                  const std::optional<std::string>& mode, const std::string& f)
{
    auto rule = [&](bool holds, const std::string& what) {
        if (!holds)
            ctx.report(IssueCode::MESHOPT_INVALID, path, what);
    };
    const std::string s = std::to_string(stride);
    const json* viewStride = member(view, "byteStride");
    rule(viewStride == nullptr || !viewStride->is_number() || viewStride->get<double>() == double(stride),
         "byteStride " + s + " differs from the buffer view's");
    const json* length = member(view, "byteLength");
    rule(length == nullptr || !length->is_number() || length->get<double>() == double(stride) * double(count),
         "byteStride " + s + " x count " + std::to_string(count) + " differs from the buffer view's byteLength");
    if (mode == "ATTRIBUTES")
        rule(stride % 4 == 0, "byteStride " + s + " is not a multiple of 4 (mode ATTRIBUTES)");
    if (mode == "TRIANGLES")
        rule(count % 3 == 0, "count " + std::to_string(count) + " is not a multiple of 3 (mode TRIANGLES)");
    if (mode == "TRIANGLES" || mode == "INDICES") {
        rule(stride == 2 || stride == 4, "byteStride " + s + " is not 2 or 4 (mode " + *mode + ")");
        rule(f == "NONE", "filter " + f + " on index data (mode " + *mode + ")");
    }
    if (f == "OCTAHEDRAL" || f == "COLOR")
        rule(stride == 4 || stride == 8, "byteStride " + s + " is not 4 or 8 (filter " + f + ")");
    if (f == "QUATERNION")
        rule(stride == 8, "byteStride " + s + " is not 8 (filter QUATERNION)");
    if (f == "EXPONENTIAL")
        rule(stride % 4 == 0, "byteStride " + s + " is not a multiple of 4 (filter EXPONENTIAL)");
}

// EXT_meshopt_compression / KHR_meshopt_compression, "JSON schema updates": the
// compressed range and the decoded layout.
void meshoptExtension(ValidationContext& ctx, const json& m, const std::string& path, const json& view, bool khr)
{
    ctx.indexMember(m, "buffer", path, "buffers", kRead, true);
    ctx.integer(m, "byteOffset", path, kRead, false, 0);
    ctx.integer(m, "byteLength", path, kRead, true, 1);
    const std::optional<int64_t> stride = ctx.integer(m, "byteStride", path, kRead, true, 1, 256);
    const std::optional<int64_t> count = ctx.integer(m, "count", path, kRead, true, 1);
    const std::optional<std::string> mode =
        ctx.enumString(m, "mode", path, {"ATTRIBUTES", "TRIANGLES", "INDICES"}, kRead, true, "");
    // KHR_meshopt_compression adds the COLOR filter.
    const std::optional<std::string> filter =
        khr ? ctx.enumString(m, "filter", path, {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL", "COLOR"}, kRead,
                             false, "")
            : ctx.enumString(m, "filter", path, {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"}, kRead, false, "");
    ctx.common(m, path);
    if (stride && count)
        meshoptRules(ctx, path, view, *stride, *count, mode, filter.value_or("NONE"));
}

// The buffer views a used accessor or a texture's image reads.
std::set<int> viewsRead(const ModelContext& mc)
{
    std::set<int> read;
    for (int a : mc.usedAccessors()) {
        if (!mc.validAccessor(a))
            continue;
        const tinygltf::Accessor& acc = mc.model.accessors[size_t(a)];
        read.insert(acc.bufferView);
        if (acc.sparse.isSparse) {
            read.insert(acc.sparse.indices.bufferView);
            read.insert(acc.sparse.values.bufferView);
        }
    }
    std::set<int> textureImages;
    for (const tinygltf::Texture& t : mc.model.textures)
        textureImages.insert(t.source);
    for (size_t i = 0; i < mc.model.images.size(); ++i)
        if (textureImages.count(int(i)))
            read.insert(mc.model.images[i].bufferView);
    return read;
}

} // namespace

void checkBufferViewSchema(ValidationContext& ctx, const json& v, const std::string& path)
{
    // (The view lying inside its buffer: the semantic phase, an error where it is read.)
    ctx.indexMember(v, "buffer", path, "buffers", kRead, true);
    ctx.integer(v, "byteOffset", path, kRead, false, 0);
    ctx.integer(v, "byteLength", path, kRead, true, 1);
    // Section 5.11.4 "bufferView.byteStride": 4 to 252, a multiple of 4.
    if (auto stride = ctx.integer(v, "byteStride", path, kRead, false, 4, 252); stride && *stride % 4 != 0)
        ctx.report(IssueCode::BUFFER_VIEW_INVALID_BYTE_STRIDE, at(path, "byteStride"),
                   std::to_string(*stride) + " is not a multiple of 4");
    // Section 5.11.4: byteStride is for vertex data; an index buffer view has none.
    if (ctx.enumInteger(v, "target", path, {34962, 34963}, kIgnored) == 34963 && member(v, "byteStride") != nullptr)
        ctx.report(IssueCode::BUFFER_VIEW_STRIDE_ON_INDEX_DATA, at(path, "byteStride"),
                   "defined for a buffer view of index data (target 34963)");
    ctx.common(v, path);
    if (const json* ext = member(v, "extensions"); ext != nullptr && ext->is_object()) {
        // KHR_meshopt_compression, "Exclusions": not on a view that has the EXT one.
        if (ext->contains("EXT_meshopt_compression") && ext->contains("KHR_meshopt_compression"))
            ctx.report(IssueCode::MESHOPT_BOTH_EXTENSIONS, at(path, "extensions"),
                       "has both EXT_meshopt_compression and KHR_meshopt_compression");
        for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
            if (const json* m = ctx.object(*ext, name, at(path, "extensions"), kRead))
                meshoptExtension(ctx, *m, at(at(path, "extensions"), name), v,
                                 std::strcmp(name, "KHR_meshopt_compression") == 0);
    }
}

void checkBufferSchema(ValidationContext& ctx, const json& b, const std::string& path)
{
    ctx.string(b, "uri", path, kRead);
    ctx.integer(b, "byteLength", path, kRead, true, 1);
    ctx.common(b, path);
}

void checkBufferViewSemantics(ModelContext& mc)
{
    const json* views = member(mc.doc, "bufferViews");
    const size_t count = views ? views->size() : 0;
    const std::set<int> read = viewsRead(mc);
    for (size_t v = 0; v < count && v < mc.model.bufferViews.size(); ++v) {
        const tinygltf::BufferView& view = mc.model.bufferViews[v];
        const std::string path = viewPath(int(v));
        if (view.byteStride != 0 && view.byteStride > view.byteLength)
            mc.report(IssueCode::BUFFER_VIEW_STRIDE_EXCEEDS_LENGTH, at(path, "byteStride"),
                      std::to_string(view.byteStride) + " exceeds byteLength " + std::to_string(view.byteLength));
        // Section 3.6.1: the view lies inside its buffer. Reading it would fail; a view
        // nothing reads leaves the file usable.
        if (view.buffer >= 0 && size_t(view.buffer) < mc.model.buffers.size()) {
            const size_t length = mc.model.buffers[size_t(view.buffer)].data.size();
            const bool isRead = read.count(int(v)) != 0;
            if (view.byteOffset > length || view.byteLength > length - view.byteOffset)
                mc.report(IssueCode::BUFFER_VIEW_TOO_LONG, path,
                          "byteOffset " + std::to_string(view.byteOffset) + " + byteLength " +
                              std::to_string(view.byteLength) + " exceeds buffers[" + std::to_string(view.buffer) +
                              "].byteLength " + std::to_string(length) + (isRead ? "" : ": unusable"),
                          isRead ? kRead : kIgnored);
        }
    }
}

} // namespace lfd::bake::gltf
