// Textures, samplers and images (glTF 2.0 sections 3.8, 5.17, 5.18, 5.26, 5.29) with
// EXT_texture_webp and KHR_texture_basisu: their JSON, and an image's buffer view (one
// contiguous range). (The bytes an image's uri names: gltf_resources.cpp.)
#include "validation/checks.h"
#include "validation/model_context.h"

#include "gltf_texture_source.h"

namespace lfd::bake::gltf {

void checkTextureSchema(ValidationContext& ctx, const json& t, const std::string& path)
{
    ctx.indexMember(t, "sampler", path, "samplers", kIgnored);
    ctx.indexMember(t, "source", path, "images", kRead);
    ctx.common(t, path);
    // EXT_texture_webp's image is read (an error), KHR_texture_basisu's never is (a warning).
    if (const json* ext = member(t, "extensions"); ext != nullptr && ext->is_object())
        for (const auto& [name, use] : {std::pair{kWebp, kRead}, std::pair{kBasisu, kIgnored}})
            if (const json* e = ctx.object(*ext, name, at(path, "extensions"), use)) {
                ctx.indexMember(*e, "source", at(at(path, "extensions"), name), "images", use, true);
                ctx.common(*e, at(at(path, "extensions"), name));
            }
}

// Samplers are not stored in the pack (the player samples with its own filters): an
// unknown filter or wrap mode is ignored.
void checkSamplerSchema(ValidationContext& ctx, const json& s, const std::string& path)
{
    ctx.enumInteger(s, "magFilter", path, {9728, 9729}, kIgnored);
    ctx.enumInteger(s, "minFilter", path, {9728, 9729, 9984, 9985, 9986, 9987}, kIgnored);
    ctx.enumInteger(s, "wrapS", path, {33071, 33648, 10497}, kIgnored);
    ctx.enumInteger(s, "wrapT", path, {33071, 33648, 10497}, kIgnored);
    ctx.common(s, path);
}

void checkImageSchema(ValidationContext& ctx, const json& i, const std::string& path)
{
    const json* uri = ctx.string(i, "uri", path, kRead);
    const bool hasView = ctx.indexMember(i, "bufferView", path, "bufferViews", kRead).has_value();
    // Section 5.18.2 "image.mimeType": image/jpeg or image/png, and the types the
    // image-format extensions the file uses add (gltf_texture_source.h).
    if (const json* mime = ctx.string(i, "mimeType", path, kRead);
        mime != nullptr && !knownMediaType(ctx.root(), mime->get<std::string>()))
        ctx.report(IssueCode::IMAGE_MIME_TYPE_UNKNOWN, at(path, "mimeType"),
                   "expected one of " + describeMediaTypes(ctx.root()) + ", got " + describe(*mime) +
                       ": decoded by content");
    // Section 5.17 "image": uri or bufferView (then with mimeType), exactly one.
    if (uri != nullptr && member(i, "bufferView") != nullptr)
        ctx.report(IssueCode::IMAGE_SOURCE_CONFLICT, path, "has both uri and bufferView");
    else if (uri == nullptr && member(i, "uri") == nullptr && member(i, "bufferView") == nullptr)
        ctx.report(IssueCode::IMAGE_SOURCE_MISSING, path, "has neither uri nor bufferView");
    if (hasView && member(i, "mimeType") == nullptr)
        ctx.report(IssueCode::IMAGE_MIME_TYPE_MISSING, at(path, "mimeType"),
                   "required with bufferView, missing: decoded by content");
    ctx.common(i, path);
}

// Section 3.6.1.2: a byteStride is for vertex attributes; image data is one range.
void checkImageViewSemantics(ModelContext& mc)
{
    for (size_t i = 0; i < mc.model.images.size(); ++i) {
        const int v = mc.model.images[i].bufferView;
        if (mc.validView(v) && mc.model.bufferViews[size_t(v)].byteStride != 0)
            mc.report(IssueCode::IMAGE_BUFFER_VIEW_WITH_BYTESTRIDE, at(at("images", i), "bufferView"),
                      viewPath(v) + " has a byteStride (image data must be one contiguous range)");
    }
}

} // namespace lfd::bake::gltf
