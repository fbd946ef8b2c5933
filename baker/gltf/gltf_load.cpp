// Loading a glTF file: the baker's own checks first, then tinygltf on checked JSON with
// the buffers' bytes from memory (see gltf_load.h).
#include "gltf_load.h"

#include "gltf_accessors.h" // fail, firstLine
#include "gltf_container.h"
#include "gltf_decompress.h"
#include "gltf_resources.h"
#include "gltf_validation.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <set>

namespace lfd::bake::gltf {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Names under which the resolved bytes are handed to tinygltf: they are served from
// memory by the file callbacks below, never looked up on disk.
const std::string kBufferName = "lfd-memory-buffer-";
const std::string kImageName = "lfd-memory-image-";

// Shared with tinygltf's callbacks through their user-data pointer.
struct Memory {
    std::vector<std::vector<uint8_t>> buffers;       // moved into tinygltf's model as read
    std::map<size_t, std::vector<uint8_t>> images;    // data-URI images (copied)
};

// The resource index of a memory name ("…/lfd-memory-buffer-3" -> 3), or nullopt.
std::optional<size_t> memoryIndex(const std::string& path, const std::string& prefix)
{
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    if (name.compare(0, prefix.size(), prefix) != 0 || name.size() == prefix.size())
        return std::nullopt;
    size_t index = 0;
    for (size_t i = prefix.size(); i < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9')
            return std::nullopt;
        index = index * 10 + size_t(name[i] - '0');
    }
    return index;
}

bool fileExists(const std::string& path, void* user)
{
    const auto* memory = static_cast<const Memory*>(user);
    if (auto b = memoryIndex(path, kBufferName))
        return *b < memory->buffers.size();
    if (auto i = memoryIndex(path, kImageName))
        return memory->images.count(*i) != 0;
    // Every buffer is served from memory, so any other path is an image file. Its existence
    // is the importer's to check (by JSON path, only where a material uses it), not
    // tinygltf's to warn about.
    return true;
}

// Buffers and data-URI images from memory. For image files at most the first 8 bytes are
// returned (tinygltf reads every external image whole before calling the image loader,
// which decodes nothing here), so a 16K texture is not read at import time; a missing or
// unreadable file reads as one zero byte, and the importer names it where it is used.
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
{
    auto* memory = static_cast<Memory*>(user);
    if (auto b = memoryIndex(path, kBufferName); b && *b < memory->buffers.size()) {
        out->swap(memory->buffers[*b]);
        return true;
    }
    if (auto i = memoryIndex(path, kImageName); i && memory->images.count(*i)) {
        *out = memory->images.at(*i);
        return true;
    }
    (void)err;
    std::ifstream in(path, std::ios::binary);
    std::array<unsigned char, 8> head{};
    in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    const size_t n = size_t(in.gcount());
    if (n == 0)
        out->assign(1, 0);
    else
        out->assign(head.begin(), head.begin() + std::ptrdiff_t(n));
    return true;
}

// Image "loader" that decodes nothing: the texture stage decodes each texture later.
bool captureImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                  void*)
{
    image->as_is = true;
    return true;
}

// Why the baker refuses a required extension it knows of (docs/baker/gltf-extensions.md);
// "" for the rest, which it does not implement.
std::string refusalReason(const std::string& name)
{
    static const std::map<std::string, std::string> reasons = {
        {"KHR_texture_basisu", "KTX2 / Basis Universal textures: Debian 12 packages no KTX2 decoder"},
        {"EXT_mesh_gpu_instancing", "instanced nodes are not read"},
        {"KHR_materials_pbrSpecularGlossiness", "archived; the baker reads metallic-roughness materials"},
        {"KHR_techniques_webgl", "archived; shaders are not read"},
    };
    const auto it = reasons.find(name);
    return it == reasons.end() ? std::string() : " (" + it->second + ")";
}

// The extensionsRequired the baker cannot honour (e.g. KHR_texture_basisu), as
// "extensionsRequired[i]: requires unsupported extension NAME (why)".
std::vector<std::string> unsupportedRequired(const json& document)
{
    std::vector<std::string> found;
    if (document.is_object() && document.contains("extensionsRequired") && document["extensionsRequired"].is_array())
        for (size_t i = 0; i < document["extensionsRequired"].size(); ++i) {
            const json& name = document["extensionsRequired"][i];
            if (name.is_string() && !supportedExtensions().count(name.get<std::string>()))
                found.push_back("extensionsRequired[" + std::to_string(i) + "]: requires unsupported extension " +
                                name.get<std::string>() + refusalReason(name.get<std::string>()));
        }
    return found;
}

// Moves `issues` to `found`, then fails on the first error among them, if any.
void failOnErrors(std::vector<SchemaIssue>& issues, const std::string& file, std::vector<SchemaIssue>& found)
{
    size_t errors = 0;
    std::string first;
    for (const SchemaIssue& issue : issues)
        if (issue.severity == SchemaIssue::Severity::Error && errors++ == 0)
            first = issue.text();
    for (SchemaIssue& issue : issues)
        found.push_back(std::move(issue));
    issues.clear();
    if (errors > 0)
        fail(file, first + (errors > 1 ? " (and " + std::to_string(errors - 1) + " more errors)" : ""));
}

// Bytes of one element of an accessor of `type` and `componentType` (section 3.6.2.4:
// matrix columns start on 4-byte boundaries).
size_t elementBytes(const std::string& type, int64_t componentType)
{
    const size_t component = componentType == 5120 || componentType == 5121   ? 1
                             : componentType == 5122 || componentType == 5123 ? 2
                                                                              : 4;
    const size_t rows = type == "MAT2" ? 2 : type == "MAT3" ? 3 : type == "MAT4" ? 4 : 0;
    if (rows > 0)
        return rows * ((rows * component + 3) / 4 * 4);
    const size_t n = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    return n * component;
}

// Integral numbers written with a fraction ("count": 3.0, valid JSON Schema integers)
// become JSON integers, which tinygltf requires for integer properties; any other number is
// kept (tinygltf reads integers for number properties too).
void integersAsIntegers(json& v)
{
    if (v.is_number_float()) {
        const double d = v.get<double>();
        // note: -0.0 stays a float (a rotation's -0 component keeps its sign bit, so the
        // pack does not change); as an integer property it reads as 0 anyway.
        if (std::isfinite(d) && std::floor(d) == d && std::abs(d) < 9.0e15 && !std::signbit(d))
            v = int64_t(d);
    } else if (v.is_structured()) {
        for (json& child : v)
            integersAsIntegers(child);
    }
}

// JSON numbers beyond double precision's range (1e309) make the JSON parser fail with no
// path; each is replaced by DBL_MAX (the text's byte positions do not matter after this),
// and outOfRangeNumbers finds them again in the parsed document to name their paths.
constexpr double kOutOfRange = std::numeric_limits<double>::max();

std::string clampHugeNumbers(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '"') { // a string: copied as is, escapes included
            const size_t start = i++;
            while (i < text.size() && text[i] != '"')
                i += text[i] == '\\' ? 2 : 1;
            i = std::min(i + 1, text.size());
            out.append(text, start, i - start);
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            const size_t start = i++;
            while (i < text.size() && std::strchr("0123456789.eE+-", text[i]) != nullptr)
                ++i;
            const std::string token = text.substr(start, i - start);
            const double v = std::strtod(token.c_str(), nullptr);
            out += std::isinf(v) ? (v < 0 ? "-1.7976931348623157e308" : "1.7976931348623157e308") : token;
        } else {
            out.push_back(c);
            ++i;
        }
    }
    return out;
}

void outOfRangeNumbers(const json& v, const std::string& path, std::vector<SchemaIssue>& issues)
{
    if (v.is_number_float() && std::abs(v.get<double>()) == kOutOfRange) {
        issues.push_back(makeIssue(IssueCode::NUMBER_OUT_OF_RANGE, path.empty() ? "(top level)" : path,
                                   "a number beyond the range of double precision"));
    } else if (v.is_object()) {
        for (const auto& [key, child] : v.items())
            outOfRangeNumbers(child, path.empty() ? key : path + "." + key, issues);
    } else if (v.is_array()) {
        for (size_t i = 0; i < v.size(); ++i)
            outOfRangeNumbers(v[i], path + "[" + std::to_string(i) + "]", issues);
    }
}

// The document tinygltf parses: every buffer named as memory, data-URI images as memory,
// accessors without a bufferView given one over zeros (section 3.6.2.3: "When
// accessor.bufferView is undefined, the sparse accessor is initialized as an array of
// zeros"), integers as integers. Indices of the original objects are kept (additions go last).
json documentForTinygltf(json document, Memory& memory, const std::string& file)
{
    integersAsIntegers(document);
    if (document.contains("buffers") && document["buffers"].is_array())
        for (size_t i = 0; i < document["buffers"].size(); ++i)
            document["buffers"][i]["uri"] = kBufferName + std::to_string(i);
    // Data-URI images come from memory (one zero byte where a malformed one was reported);
    // what tinygltf need not read (cameras, samplers; skins: readSkins) is left out, so tinygltf's
    // parsing of them cannot fail a file the checks accepted.
    if (document.contains("images") && document["images"].is_array())
        for (size_t i = 0; i < document["images"].size(); ++i) {
            json& image = document["images"][i];
            if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string() ||
                parseUri(image["uri"].get<std::string>()).kind != Uri::Kind::Data)
                continue;
            if (!memory.images.count(i))
                memory.images[i] = {0};
            image["uri"] = kImageName + std::to_string(i);
        }
    for (const char* unread : {"cameras", "skins", "samplers"})
        document.erase(unread);
    if (document.contains("accessors") && document["accessors"].is_array()) {
        for (size_t i = 0; i < document["accessors"].size(); ++i) {
            json& a = document["accessors"][i];
            if (!a.is_object())
                continue;
            // Unknown enum values are reported (warnings: nothing reads the accessor);
            // tinygltf refuses them, so it gets readable ones.
            static const std::set<std::string> types = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
            if (!a.contains("type") || !a["type"].is_string() || !types.count(a["type"].get<std::string>()))
                a["type"] = "SCALAR";
            static const std::set<int64_t> components = {5120, 5121, 5122, 5123, 5125, 5126};
            if (!a.contains("componentType") || !a["componentType"].is_number_integer() ||
                !components.count(a["componentType"].get<int64_t>()))
                a["componentType"] = 5126;
            if (a.contains("bufferView"))
                continue;
            const double count = a.value("count", 0.0);
            const size_t bytes = elementBytes(a.value("type", "SCALAR"), a.value("componentType", int64_t(5126))) *
                                 size_t(std::max(count, 0.0));
            // A bound on what a few bytes of JSON may make the baker allocate.
            if (count > 0 && bytes / size_t(count) != 0 && bytes > (size_t(256) << 20))
                fail(file, "accessors[" + std::to_string(i) + "]: " + std::to_string(int64_t(count)) +
                               " elements without a bufferView would need " + std::to_string(bytes >> 20) +
                               " MiB of zeros (more than 256 MiB)");
            if (!document.contains("buffers") || !document["buffers"].is_array())
                document["buffers"] = json::array();
            if (!document.contains("bufferViews") || !document["bufferViews"].is_array())
                document["bufferViews"] = json::array();
            const size_t buffer = document["buffers"].size(), view = document["bufferViews"].size();
            document["buffers"].push_back({{"uri", kBufferName + std::to_string(buffer)}, {"byteLength", std::max<size_t>(bytes, 4)}});
            document["bufferViews"].push_back({{"buffer", buffer}, {"byteLength", std::max<size_t>(bytes, 4)}});
            memory.buffers.resize(buffer + 1);
            memory.buffers[buffer].assign(std::max<size_t>(bytes, 4), 0);
            a["bufferView"] = view;
            a.erase("byteOffset");
        }
    }
    return document;
}

// tinygltf on the checked document. Its failure here means a check above missed
// something: reported as such, with its own first line.
tinygltf::Model parseWithTinygltf(const json& document, Memory& memory, const fs::path& path, const std::string& file,
                                  std::vector<SchemaIssue>& warnings)
{
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&captureImage, &memory);
    loader.SetFsCallbacks({&fileExists, &tinygltf::ExpandFilePath, &readWholeFile, &tinygltf::WriteWholeFile, &memory});
    tinygltf::Model model;
    std::string err, warn;
    const std::string text = document.dump();
    if (!loader.LoadASCIIFromString(&model, &err, &warn, text.c_str(), unsigned(text.size()),
                                    path.parent_path().string()))
        fail(file, "could not be loaded after its checks passed (tinygltf: " +
                       firstLine(!err.empty() ? err : !warn.empty() ? warn : "no message") + ")");
    // tinygltf only warns about image files it could not read; the importer checks the
    // images it uses itself (and fails on missing ones).
    size_t start = 0;
    while (start < warn.size()) {
        const size_t end = std::min(warn.find('\n', start), warn.size());
        const std::string line = firstLine(warn.substr(start, end - start));
        if (!line.empty())
            warnings.push_back(makeIssue(IssueCode::TINYGLTF_WARNING, "(tinygltf)", line));
        start = end + 1;
    }
    return model;
}

// The document's skins: names, joints that name existing nodes, the matrices' accessor.
std::vector<SkinJson> readSkins(const json& document, size_t nodeCount)
{
    std::vector<SkinJson> skins;
    const auto it = document.find("skins");
    if (it == document.end() || !it->is_array())
        return skins;
    for (const json& skin : *it) {
        SkinJson out;
        if (!skin.is_object()) {
            skins.push_back(out);
            continue;
        }
        if (skin.contains("name") && skin["name"].is_string())
            out.name = skin["name"].get<std::string>();
        if (skin.contains("joints") && skin["joints"].is_array())
            for (const json& j : skin["joints"])
                if (j.is_number_integer() && j.get<int64_t>() >= 0 && size_t(j.get<int64_t>()) < nodeCount)
                    out.joints.push_back(int(j.get<int64_t>()));
        if (skin.contains("inverseBindMatrices") && skin["inverseBindMatrices"].is_number_integer())
            out.inverseBindMatrices = int(skin["inverseBindMatrices"].get<int64_t>());
        skins.push_back(std::move(out));
    }
    return skins;
}

} // namespace

const std::set<std::string>& supportedExtensions()
{
    static const std::set<std::string> names = {"KHR_mesh_quantization",      "KHR_materials_emissive_strength",
                                                "KHR_texture_transform",      "KHR_materials_unlit",
                                                "KHR_lights_punctual",        "KHR_draco_mesh_compression",
                                                "EXT_meshopt_compression",    "KHR_meshopt_compression",
                                                "EXT_texture_webp"};
    return names;
}

LoadedGltf loadGltf(const fs::path& path, const std::string& file, std::vector<SchemaIssue>& warnings, unsigned threads)
{
    std::error_code ec;
    if (!fs::exists(path, ec))
        fail(file, "file not found");
    if (fs::is_directory(path, ec))
        fail(file, "is a directory, not a glTF file");

    // Step 1: the container, then the JSON.
    std::vector<SchemaIssue> issues;
    const GltfContainer container = readGltfContainer(path, file, issues);
    if (container.json.empty())
        failOnErrors(issues, file, warnings);
    json document;
    try {
        document = json::parse(clampHugeNumbers(container.json));
        outOfRangeNumbers(document, "", issues);
    } catch (const json::exception& e) {
        issues.push_back(makeIssue(IssueCode::INVALID_JSON, container.binary ? "GLB chunk 0 (JSON)" : "(top level)",
                                   std::string("not valid JSON: ") + e.what()));
        failOnErrors(issues, file, warnings);
    }

    // Step 2: the schema of what the baker reads and the extensions it must honour, then
    // the bytes the URIs name.
    for (SchemaIssue& issue : validateGltfSchema(document))
        issues.push_back(std::move(issue));
    failOnErrors(issues, file, warnings);
    for (const std::string& line : unsupportedRequired(document))
        fail(file, line);
    // The resources' problems are reported after the semantic checks: a missing .bin says
    // less about a broken file than the defect the checks name.
    std::vector<SchemaIssue> resourceIssues;
    ResolvedResources resources = resolveResources(document, container, path.parent_path(), resourceIssues);

    // Step 3: compressed geometry decoded into buffers of its own, the document rewritten
    // to read them (gltf_decompress.h); a stream that does not decode refuses the file.
    decodeCompressedGeometry(document, resources.buffers, resources.withoutData, threads, issues);
    failOnErrors(issues, file, warnings);

    // Step 4: tinygltf parses the checked document, the bytes from memory.
    Memory memory{std::move(resources.buffers), resources.dataImages};
    const json forTinygltf = documentForTinygltf(document, memory, file);
    LoadedGltf out;
    out.model = parseWithTinygltf(forTinygltf, memory, path, file, warnings);
    out.skins = readSkins(document, out.model.nodes.size());
    out.dataImages = std::move(resources.dataImages);
    out.buffersWithoutData = resources.withoutData;
    out.bufferFiles = std::move(resources.files);
    if (document.contains("accessors") && document["accessors"].is_array())
        for (size_t a = 0; a < document["accessors"].size(); ++a) {
            const json& acc = document["accessors"][a];
            if (acc.is_object() && !acc.contains("bufferView") && !acc.contains("sparse"))
                out.accessorsWithoutData.insert(a);
        }

    // Step 5: the semantics and the data (links between objects, accessor contents; no data
    // check on bytes the file does not hold), then the resources' problems.
    validateGltfSemantics(out.model, document, resources.withoutData, issues);
    for (SchemaIssue& issue : resourceIssues)
        issues.push_back(std::move(issue));
    failOnErrors(issues, file, warnings);
    return out;
}

} // namespace lfd::bake::gltf
