// Buffers and images of a glTF document, resolved by the baker (see gltf_resources.h).
#include "gltf_resources.h"

#include "gltf_json.h"
#include "gltf_texture_source.h"
#include "validation/context.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>

namespace lfd::bake::gltf {
namespace {


std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// RFC 4648 base64 (standard alphabet, '=' padding optional at the end; whitespace is not
// allowed in a data URI). nullopt for any other character or a truncated quantum.
std::optional<std::vector<uint8_t>> decodeBase64(const std::string& text)
{
    static const std::array<int8_t, 256> table = [] {
        std::array<int8_t, 256> t{};
        t.fill(-1);
        const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        for (int i = 0; i < 64; ++i)
            t[uint8_t(alphabet[i])] = int8_t(i);
        return t;
    }();
    size_t end = text.size();
    while (end > 0 && text[end - 1] == '=' && text.size() - end < 2)
        --end;
    if ((end % 4) == 1)
        return std::nullopt;
    std::vector<uint8_t> out;
    out.reserve(end / 4 * 3 + 2);
    uint32_t acc = 0;
    int bits = 0;
    for (size_t i = 0; i < end; ++i) {
        const int8_t v = table[uint8_t(text[i])];
        if (v < 0)
            return std::nullopt;
        acc = (acc << 6) | uint32_t(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(uint8_t((acc >> bits) & 0xFF));
        }
    }
    return out;
}


// The buffer views a KHR_draco_mesh_compression primitive decodes.
void dracoViews(const json& document, std::set<size_t>& viewsRead)
{
    for (const json& mesh : arrayOf(document, "meshes"))
        if (mesh.is_object() && mesh.contains("primitives") && mesh["primitives"].is_array())
            for (const json& p : mesh["primitives"])
                if (p.is_object() && p.contains("extensions") && p["extensions"].is_object())
                    if (auto v = jsonIndex(p["extensions"].value("KHR_draco_mesh_compression", json()), "bufferView"))
                        viewsRead.insert(*v);
}

// Which buffers some buffer view of an accessor (base or sparse), of an image or of a Draco
// primitive reads, or a meshopt-compressed view decodes, with one such view per buffer for
// messages.
std::map<size_t, size_t> buffersRead(const json& document)
{
    const json& views = arrayOf(document, "bufferViews");
    std::set<size_t> viewsRead;
    dracoViews(document, viewsRead);
    for (const json& a : arrayOf(document, "accessors")) {
        if (auto v = jsonIndex(a, "bufferView"))
            viewsRead.insert(*v);
        if (a.is_object() && a.contains("sparse") && a["sparse"].is_object())
            for (const char* part : {"indices", "values"})
                if (a["sparse"].contains(part))
                    if (auto v = jsonIndex(a["sparse"][part], "bufferView"))
                        viewsRead.insert(*v);
    }
    for (const json& image : arrayOf(document, "images"))
        if (auto v = jsonIndex(image, "bufferView"))
            viewsRead.insert(*v);
    std::map<size_t, size_t> read;
    for (size_t v : viewsRead)
        if (v < views.size())
            if (auto b = jsonIndex(views[v], "buffer"))
                read.emplace(*b, v);
    // EXT_/KHR_meshopt_compression: the extension names the buffer of the compressed bytes.
    for (size_t v = 0; v < views.size(); ++v)
        if (views[v].is_object() && views[v].contains("extensions") && views[v]["extensions"].is_object())
            for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
                if (auto b = jsonIndex(views[v]["extensions"].value(name, json()), "buffer"))
                    read.emplace(*b, v);
    return read;
}

// Which images a material's texture uses: the texture's EXT_texture_webp source when it
// has one (the baker prefers it), its core source otherwise (gltf_texture_source.h).
std::set<size_t> imagesUsed(const json& document)
{
    const json& textures = arrayOf(document, "textures");
    std::set<size_t> used;
    auto texture = [&](const json& info) {
        if (auto t = jsonIndex(info, "index"); t && *t < textures.size())
            if (auto i = textureImage(textures[*t]))
                used.insert(*i);
    };
    for (const json& m : arrayOf(document, "materials")) {
        if (!m.is_object())
            continue;
        for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
            if (m.contains(key))
                texture(m[key]);
        if (m.contains("pbrMetallicRoughness") && m["pbrMetallicRoughness"].is_object())
            for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
                if (m["pbrMetallicRoughness"].contains(key))
                    texture(m["pbrMetallicRoughness"][key]);
    }
    return used;
}

std::optional<std::vector<uint8_t>> readFile(const std::filesystem::path& path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return std::nullopt;
    // One read of the file's size (an istreambuf_iterator copy is a byte at a time).
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec)
        return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!in || size_t(in.gcount()) != bytes.size())
        return std::nullopt;
    return bytes;
}

class Resolver {
public:
    Resolver(const json& document, const GltfContainer& container, const std::filesystem::path& baseDir,
             std::vector<SchemaIssue>& issues)
        : document_(document), container_(container), baseDir_(baseDir), ctx_(document, issues)
    {
    }

    ResolvedResources run()
    {
        ResolvedResources out;
        const std::map<size_t, size_t> read = buffersRead(document_);
        const json& buffers = arrayOf(document_, "buffers");
        for (size_t i = 0; i < buffers.size(); ++i) {
            const auto view = read.find(i);
            bool hasData = true;
            out.buffers.push_back(
                buffer(buffers[i], i, view == read.end() ? std::nullopt : std::optional(view->second), hasData));
            if (!hasData)
                out.withoutData.insert(i);
        }
        const std::set<size_t> used = imagesUsed(document_);
        const json& images = arrayOf(document_, "images");
        for (size_t i = 0; i < images.size(); ++i)
            if (auto bytes = image(images[i], i, used.count(i) != 0))
                out.dataImages.emplace(i, std::move(*bytes));
        out.files = std::move(filesRead_);
        return out;
    }

private:
    // Exactly byteLength bytes for buffer i; `readBy` names a view reading it, if any;
    // `hasData` false for a buffer without a uri (valid; its bytes are not in the file).
    std::vector<uint8_t> buffer(const json& b, size_t i, std::optional<size_t> readBy, bool& hasData)
    {
        const std::string path = at("buffers", i);
        const std::optional<size_t> byteLength = jsonIndex(b, "byteLength");
        // Exactly byteLength bytes: zeros where there is no data, the data cut or padded
        // with zeros otherwise (moved, not copied: buffers can be large).
        const size_t length = byteLength.value_or(0);
        auto zeros = [length] { return std::vector<uint8_t>(length, 0); };
        auto sized = [length](std::vector<uint8_t> data) {
            data.resize(length, 0);
            return data;
        };
        if (!b.is_object() || !byteLength)
            return zeros(); // reported by the schema check
        // A problem with a buffer something reads is an error; with one nothing reads, a
        // warning (the file stays usable).
        const Use use = readBy ? kRead : kIgnored;
        const std::string reader = readBy ? " (bufferViews[" + std::to_string(*readBy) + "] reads it)" : "";
        // A buffer with a problem has no usable data either.
        auto problem = [&](IssueCode code, const std::string& where, const std::string& message) {
            ctx_.report(code, where, message, use);
            hasData = false;
        };
        const auto uriIt = b.find("uri");
        if (uriIt == b.end() || !uriIt->is_string() || uriIt->get_ref<const std::string&>().empty()) {
            // Section 3.6.1.1: without a uri "the buffer's data MUST be provided by other
            // means" (an extension, an application): valid, but not bakeable where the
            // importer needs the bytes (it says so then). In a GLB, buffers[0] is the BIN chunk.
            if (container_.binary && i == 0)
                return binChunk(path, *byteLength, use, reader, hasData);
            hasData = false;
            return zeros();
        }
        const std::string& text = uriIt->get_ref<const std::string&>();
        const std::string uriPath = at(path, "uri");
        const Uri uri = parseUri(text);
        if (uri.kind == Uri::Kind::Remote) {
            problem(IssueCode::URI_NOT_FETCHED, uriPath, "remote URIs are not fetched: " + text.substr(0, 120) + reader);
            return zeros();
        }
        if (uri.kind == Uri::Kind::Data) {
            const std::string media = lower(uri.mediaType);
            if (!media.empty() && media != "application/octet-stream" && media != "application/gltf-buffer")
                problem(IssueCode::DATA_URI_MEDIA_TYPE_INVALID, uriPath, "data URI media type '" + uri.mediaType +
                                       "' is not application/octet-stream or application/gltf-buffer" + reader);
            std::string why;
            std::optional<std::vector<uint8_t>> data = decodeDataUri(uri, why);
            if (!data) {
                problem(IssueCode::DATA_URI_MALFORMED, uriPath, "malformed data URI: " + why + reader);
                return zeros();
            }
            if (data->size() != *byteLength)
                problem(IssueCode::BUFFER_BYTE_LENGTH_MISMATCH, at(path, "byteLength"), std::to_string(*byteLength) + " does not match the " +
                                                      std::to_string(data->size()) + " bytes of its data URI" + reader);
            return sized(std::move(*data));
        }
        const std::filesystem::path file = baseDir_ / uri.payload;
        std::optional<std::vector<uint8_t>> data = readFile(file);
        filesRead_.push_back(file);
        if (!data) {
            problem(IssueCode::RESOURCE_NOT_FOUND, uriPath, "file '" + file.string() + "' not found" + reader);
            return zeros();
        }
        if (data->size() < *byteLength)
            problem(IssueCode::BUFFER_BYTE_LENGTH_MISMATCH, at(path, "byteLength"), std::to_string(*byteLength) + " exceeds the " +
                                                  std::to_string(data->size()) + " bytes of '" + file.string() + "'" +
                                                  reader);
        return sized(std::move(*data));
    }

    // Section 4.4.3.3: a GLB's buffers[0] without uri is its BIN chunk: byteLength bytes of
    // it (zeros, and no data, where the chunk is missing or too short).
    std::vector<uint8_t> binChunk(const std::string& path, size_t byteLength, Use use, const std::string& reader,
                                  bool& hasData)
    {
        if (!container_.bin || container_.bin->size() < byteLength) {
            if (!container_.bin)
                ctx_.report(IssueCode::GLB_BIN_CHUNK_MISSING, path, "refers to the GLB's BIN chunk, but the file has none" + reader,
                            use);
            else
                ctx_.report(IssueCode::BUFFER_BYTE_LENGTH_MISMATCH, at(path, "byteLength"),
                            std::to_string(byteLength) + " exceeds the BIN chunk's " +
                                std::to_string(container_.bin->size()) + " bytes" + reader,
                            use);
            hasData = false;
            return std::vector<uint8_t>(byteLength, 0);
        }
        if (container_.bin->size() - byteLength > 3)
            ctx_.report(IssueCode::GLB_BIN_CHUNK_UNUSED_BYTES, at(path, "byteLength"),
                   std::to_string(byteLength) + " leaves " + std::to_string(container_.bin->size() - byteLength) +
                       " bytes of the BIN chunk unused (at most 3 bytes of padding expected)");
        std::vector<uint8_t> data = *container_.bin;
        data.resize(byteLength, 0);
        return data;
    }

    // The bytes of image i's data URI; remote URIs and malformed data URIs are reported
    // (errors for images a material uses). Relative files are checked when used.
    std::optional<std::vector<uint8_t>> image(const json& im, size_t i, bool used)
    {
        if (!im.is_object() || !im.contains("uri") || !im["uri"].is_string())
            return std::nullopt;
        const std::string& text = im["uri"].get_ref<const std::string&>();
        const std::string path = at(at("images", i), "uri");
        const Use use = used ? kRead : kIgnored;
        const Uri uri = parseUri(text);
        if (uri.kind == Uri::Kind::Remote) {
            ctx_.report(IssueCode::URI_NOT_FETCHED, path, "remote URIs are not fetched: " + text.substr(0, 120), use);
            return std::nullopt;
        }
        if (uri.kind != Uri::Kind::Data)
            return std::nullopt;
        std::string why;
        std::optional<std::vector<uint8_t>> data = decodeDataUri(uri, why);
        if (!data) {
            ctx_.report(IssueCode::DATA_URI_MALFORMED, path, "malformed data URI: " + why, use);
            return data;
        }
        if (data->empty())
            ctx_.report(IssueCode::DATA_URI_EMPTY, path, "empty data URI", use);
        // Section 3.8.4.4: core glTF images are PNG or JPEG, named by their media type
        // (the data URI's, and mimeType when given, must agree); EXT_texture_webp adds
        // image/webp, KHR_texture_basisu image/ktx2, in files that use them.
        const std::string media = lower(uri.mediaType);
        if (!knownMediaType(document_, media))
            ctx_.report(IssueCode::DATA_URI_MEDIA_TYPE_INVALID, path,
                        "data URI media type '" + uri.mediaType + "' is not one of " + describeMediaTypes(document_), use);
        else if (im.contains("mimeType") && im["mimeType"].is_string() && lower(im["mimeType"].get<std::string>()) != media)
            // The baker decodes by content, so a disagreement it can work around is a warning.
            ctx_.report(IssueCode::IMAGE_MIME_TYPE_MISMATCH, at(at("images", i), "mimeType"),
                   "'" + im["mimeType"].get<std::string>() + "' does not match the data URI's media type '" +
                       uri.mediaType + "': decoded by content");
        return data;
    }

    const json& document_;
    const GltfContainer& container_;
    std::filesystem::path baseDir_;
    ValidationContext ctx_;
    std::vector<std::filesystem::path> filesRead_;
};

} // namespace

std::string percentDecode(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(uint8_t(text[i + 1])) &&
            std::isxdigit(uint8_t(text[i + 2]))) {
            out.push_back(char(std::stoi(text.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(text[i]);
        }
    }
    return out;
}

Uri parseUri(const std::string& text)
{
    Uri uri;
    // Section 3.9: data URIs (RFC 2397), or URIs relative to the glTF file.
    if (lower(text.substr(0, 5)) == "data:") {
        uri.kind = Uri::Kind::Data;
        const size_t comma = text.find(',');
        const std::string header = text.substr(5, comma == std::string::npos ? std::string::npos : comma - 5);
        uri.payload = comma == std::string::npos ? std::string() : text.substr(comma + 1);
        const size_t semicolon = header.find(';');
        uri.mediaType = header.substr(0, semicolon);
        if (comma == std::string::npos)
            uri.malformed = "no ',' before the data";
        // RFC 2397: [type/subtype] *(;attribute=value) [;base64]
        std::vector<std::string> params;
        for (size_t start = semicolon; start != std::string::npos;) {
            const size_t next = header.find(';', start + 1);
            params.push_back(header.substr(start + 1, next == std::string::npos ? std::string::npos : next - start - 1));
            start = next;
        }
        uri.base64 = !params.empty() && lower(params.back()) == "base64";
        if (uri.base64)
            params.pop_back();
        if (!uri.mediaType.empty() && uri.mediaType.find('/') == std::string::npos)
            uri.malformed = "media type '" + uri.mediaType + "' is not type/subtype";
        for (const std::string& p : params)
            if (p.find('=') == std::string::npos || p.front() == '=')
                uri.malformed = "parameter '" + p + "' is not attribute=value";
        return uri;
    }
    // A scheme (RFC 3986 section 3.1): a letter, then letters, digits, '+', '-' or '.', then ':'.
    const size_t colon = text.find(':');
    if (colon != std::string::npos && colon > 0 && std::isalpha(uint8_t(text[0])) &&
        std::all_of(text.begin(), text.begin() + std::ptrdiff_t(colon),
                    [](char c) { return std::isalnum(uint8_t(c)) || c == '+' || c == '-' || c == '.'; }) &&
        text.find('/') > colon) {
        uri.kind = Uri::Kind::Remote;
        return uri;
    }
    uri.kind = Uri::Kind::Relative;
    uri.payload = percentDecode(text.substr(0, text.find_first_of("?#")));
    return uri;
}

std::optional<std::vector<uint8_t>> decodeDataUri(const Uri& uri, std::string& why)
{
    if (!uri.malformed.empty()) {
        why = uri.malformed;
        return std::nullopt;
    }
    if (uri.base64) {
        std::optional<std::vector<uint8_t>> bytes = decodeBase64(uri.payload);
        if (!bytes)
            why = "invalid base64";
        return bytes;
    }
    // RFC 2397: without ";base64" the data is percent-encoded octets.
    const std::string decoded = percentDecode(uri.payload);
    return std::vector<uint8_t>(decoded.begin(), decoded.end());
}

ResolvedResources resolveResources(const json& document, const GltfContainer& container,
                                   const std::filesystem::path& baseDir, std::vector<SchemaIssue>& issues)
{
    return Resolver(document, container, baseDir, issues).run();
}

std::string bytesNotInFile(const tinygltf::Model& model, const std::set<size_t>& withoutData, int a)
{
    if (a < 0 || size_t(a) >= model.accessors.size())
        return {};
    const tinygltf::Accessor& acc = model.accessors[size_t(a)];
    for (int v : {acc.bufferView, acc.sparse.isSparse ? acc.sparse.indices.bufferView : -1,
                  acc.sparse.isSparse ? acc.sparse.values.bufferView : -1}) {
        if (v < 0 || size_t(v) >= model.bufferViews.size())
            continue;
        const int b = model.bufferViews[size_t(v)].buffer;
        if (b >= 0 && withoutData.count(size_t(b)))
            return "accessors[" + std::to_string(a) + "] lies in buffers[" + std::to_string(b) +
                   "], which has no uri: its bytes are not in the file";
    }
    return {};
}

} // namespace lfd::bake::gltf
