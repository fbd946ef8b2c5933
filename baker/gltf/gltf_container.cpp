// glTF 2.0 containers: the JSON text of a .gltf, and the header and chunks of a .glb
// (section 4.4 "Binary glTF Layout"). Each rule below cites the specification's MUST
// (an error) or its client rules (unknown chunks are ignored: a warning).
#include "gltf_container.h"

#include "gltf_accessors.h" // fail

#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

namespace lfd::bake::gltf {
namespace {

constexpr uint32_t kMagic = 0x46546C67u;     // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534Au; // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942u;  // "BIN\0"

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset)
{
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v; // little-endian file on a little-endian host (x86-64, the only target)
}

std::string hex(uint32_t v)
{
    char text[16];
    std::snprintf(text, sizeof(text), "0x%08X", v);
    return text;
}

// Section 3.3 "JSON encoding": UTF-8 without a byte-order mark.
bool startsWithBom(const std::string& text)
{
    return text.size() >= 3 && uint8_t(text[0]) == 0xEF && uint8_t(text[1]) == 0xBB && uint8_t(text[2]) == 0xBF;
}

class GlbReader {
public:
    GlbReader(const std::vector<uint8_t>& bytes, std::vector<SchemaIssue>& issues) : bytes_(bytes), issues_(issues) {}

    GltfContainer read()
    {
        GltfContainer out;
        out.binary = true;
        const std::optional<size_t> end = readHeader();
        if (!end)
            return out;
        // Step 2: the chunks: JSON first, BIN (at most one) second, unknown ones skipped.
        size_t offset = 12;
        bool sawBin = false;
        for (size_t index = 0; offset < *end; ++index)
            if (!readChunk(index, *end, offset, sawBin, out))
                return out;
        if (out.json.empty() && !hasError())
            report(IssueCode::GLB_CHUNK_INVALID, "GLB", "has no JSON chunk");
        return out;
    }

    // Step 1: the 12-byte header: magic, version 2, total length. Returns where the GLB
    // ends (its declared length), or nothing after an error.
    std::optional<size_t> readHeader()
    {
        if (bytes_.size() < 12) {
            report(IssueCode::GLB_HEADER_INVALID, "GLB header", "the file ends after " + std::to_string(bytes_.size()) + " bytes, inside the 12-byte header");
            return std::nullopt;
        }
        const uint32_t version = readU32(bytes_, 4), length = readU32(bytes_, 8);
        if (version != 2) {
            report(IssueCode::GLB_HEADER_INVALID, "GLB header.version", std::to_string(version) + " is not 2" +
                                            (version == 1 ? " (GLB version 1 is glTF 1.0, which this baker does not read)" : ""));
            return std::nullopt;
        }
        size_t end = bytes_.size();
        if (length < 12) {
            report(IssueCode::GLB_HEADER_INVALID, "GLB header.length", std::to_string(length) + " is smaller than the header");
            return std::nullopt;
        }
        if (length > bytes_.size()) {
            report(IssueCode::GLB_HEADER_INVALID, "GLB header.length", std::to_string(length) + " exceeds the file's " + std::to_string(bytes_.size()) +
                                           " bytes (truncated file)");
            return std::nullopt;
        }
        if (length < bytes_.size()) {
            report(IssueCode::GLB_TRAILING_BYTES, "GLB header.length", std::to_string(bytes_.size() - length) +
                                          " bytes of extra data after the declared length: ignored");
            end = length;
        }
        return end;
    }

    // Chunk `index` at `offset` into `out`, and `offset` past it; false after an error that
    // ends the reading.
    bool readChunk(size_t index, size_t end, size_t& offset, bool& sawBin, GltfContainer& out)
    {
        const std::string where = "GLB chunk " + std::to_string(index);
        if (end - offset < 8) {
            report(IssueCode::GLB_CHUNK_INVALID, where, "the file ends inside the chunk's 8-byte header");
            return false;
        }
        const uint32_t chunkLength = readU32(bytes_, offset), type = readU32(bytes_, offset + 4);
        const std::string named = where + (type == kChunkJson ? " (JSON)" : type == kChunkBin ? " (BIN)" : "");
        if (chunkLength > end - offset - 8) {
            report(IssueCode::GLB_CHUNK_INVALID, named, "chunkLength " + std::to_string(chunkLength) + " runs past the end of the GLB (" +
                             std::to_string(end - offset - 8) + " bytes left)");
            return false;
        }
        // Section 4.4.3.1: "The start and the end of each chunk MUST be aligned to a
        // 4-byte boundary".
        if (chunkLength % 4 != 0)
            report(IssueCode::GLB_CHUNK_INVALID, named, "chunkLength " + std::to_string(chunkLength) + " is not a multiple of 4");
        const auto data = bytes_.begin() + std::ptrdiff_t(offset + 8);
        if (index == 0 && type != kChunkJson) {
            report(IssueCode::GLB_CHUNK_INVALID, where, "the first chunk is of type " + hex(type) + ", not JSON");
            return false;
        }
        if (type == kChunkJson) {
            if (index != 0) {
                report(IssueCode::GLB_CHUNK_INVALID, named, "a second JSON chunk");
            } else if (chunkLength == 0) {
                report(IssueCode::GLB_CHUNK_INVALID, named, "empty JSON chunk");
                return false;
            } else {
                out.json.assign(data, data + std::ptrdiff_t(chunkLength));
            }
        } else if (type == kChunkBin) {
            if (sawBin)
                report(IssueCode::GLB_CHUNK_INVALID, named, "a second BIN chunk (a GLB has at most one)");
            else if (index != 1)
                report(IssueCode::GLB_CHUNK_INVALID, named, "the BIN chunk is not the second chunk");
            else if (chunkLength == 0)
                report(IssueCode::GLB_CHUNK_INVALID, named, "empty BIN chunk");
            else
                out.bin.emplace(data, data + std::ptrdiff_t(chunkLength));
            sawBin = true;
        } else {
            report(IssueCode::GLB_UNKNOWN_CHUNK, where, "unknown chunk type " + hex(type) + ": ignored");
        }
        offset += 8 + size_t(chunkLength);
        return true;
    }

private:
    void report(IssueCode code, const std::string& where, const std::string& what)
    {
        issues_.push_back(makeIssue(code, where, what));
    }
    bool hasError() const
    {
        for (const SchemaIssue& i : issues_)
            if (i.severity == SchemaIssue::Severity::Error)
                return true;
        return false;
    }

    const std::vector<uint8_t>& bytes_;
    std::vector<SchemaIssue>& issues_;
};

} // namespace

GltfContainer readGltfContainer(const std::filesystem::path& path, const std::string& file,
                                std::vector<SchemaIssue>& issues)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        fail(file, "cannot open the file for reading");
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        fail(file, "read error");

    GltfContainer out;
    if (bytes.size() >= 4 && readU32(bytes, 0) == kMagic) {
        out = GlbReader(bytes, issues).read();
    } else {
        out.json.assign(bytes.begin(), bytes.end());
    }
    // Section 3.3 "JSON encoding": "JSON MUST use UTF-8 encoding without BOM".
    if (startsWithBom(out.json)) {
        issues.push_back(makeIssue(IssueCode::JSON_BYTE_ORDER_MARK, out.binary ? "GLB chunk 0 (JSON)" : "(top level)",
                                   "starts with a UTF-8 byte-order mark, which glTF JSON must not have"));
        out.json.erase(0, 3);
    }
    return out;
}

} // namespace lfd::bake::gltf
