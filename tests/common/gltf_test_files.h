// Writing glTF test files: little-endian values appended to a buffer, base64 for data
// URIs, GLB files (written, and read back into their JSON and BIN chunks), and a fixture
// that writes each case to a file of its own in a temporary folder. Shared by the glTF
// validation, conformance and compression tests.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <vector>

namespace lfd::test {

inline std::string base64(const std::vector<uint8_t>& bytes)
{
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
        out += kAlphabet[n >> 18 & 63];
        out += kAlphabet[n >> 12 & 63];
        out += i + 1 < bytes.size() ? kAlphabet[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
    }
    return out;
}

// Appends `values` in the machine's byte order (little-endian on every supported target,
// as glTF requires).
template <class T>
void append(std::vector<uint8_t>& bin, std::initializer_list<T> values)
{
    for (T v : values) {
        uint8_t bytes[sizeof(T)];
        std::memcpy(bytes, &v, sizeof(T));
        bin.insert(bin.end(), bytes, bytes + sizeof(T));
    }
}

// A GLB (glTF 2.0 section 4.4): the header, then `chunks` as given (type, payload padded
// with `pad` unless `alignChunks` is false).
struct Chunk {
    uint32_t type;
    std::vector<uint8_t> payload;
    uint8_t pad;
};
inline constexpr uint32_t kJson = 0x4E4F534Au, kBin = 0x004E4942u;

inline Chunk jsonChunk(const nlohmann::json& doc)
{
    std::string text = doc.dump();
    while (text.size() % 4)
        text += ' ';
    return {kJson, std::vector<uint8_t>(text.begin(), text.end()), ' '};
}

inline std::vector<uint8_t> glb(const std::vector<Chunk>& chunks, bool alignChunks = true)
{
    std::vector<uint8_t> body;
    for (const Chunk& c : chunks) {
        std::vector<uint8_t> payload = c.payload;
        while (alignChunks && payload.size() % 4)
            payload.push_back(c.pad);
        append<uint32_t>(body, {uint32_t(payload.size()), c.type});
        body.insert(body.end(), payload.begin(), payload.end());
    }
    std::vector<uint8_t> out;
    append<uint32_t>(out, {0x46546C67u, 2u, uint32_t(12 + body.size())});
    out.insert(out.end(), body.begin(), body.end());
    return out;
}

// A well-formed GLB file's JSON and BIN chunk (empty when it has none), for tests that
// change a fixture in one place and write it back with glbOf().
struct GlbParts {
    nlohmann::json doc;
    std::vector<uint8_t> bin;
};

inline GlbParts readGlb(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    GlbParts parts;
    for (size_t at = 12; at + 8 <= file.size();) {
        uint32_t length = 0, type = 0;
        std::memcpy(&length, &file[at], 4);
        std::memcpy(&type, &file[at + 4], 4);
        const auto begin = file.begin() + std::ptrdiff_t(at + 8), end = begin + std::ptrdiff_t(length);
        if (type == kJson)
            parts.doc = nlohmann::json::parse(begin, end);
        else if (type == kBin)
            parts.bin.assign(begin, end);
        at += 8 + length;
    }
    return parts;
}

inline std::vector<uint8_t> glbOf(const GlbParts& parts)
{
    return glb({jsonChunk(parts.doc), {kBin, parts.bin, 0}});
}

// A test whose cases are files: write() and writeBytes() give each its own name
// ("case<N>.gltf") in a folder that lives as long as the test.
class GltfCaseFiles : public ::testing::Test {
protected:
    explicit GltfCaseFiles(const std::string& folder)
        : dir_(std::filesystem::temp_directory_path() / (folder + "_" + std::to_string(::getpid())))
    {
        std::filesystem::create_directories(dir_);
    }
    ~GltfCaseFiles() override { std::filesystem::remove_all(dir_); }

    std::filesystem::path write(const nlohmann::json& doc)
    {
        const std::filesystem::path path = next(".gltf");
        std::ofstream(path) << doc.dump();
        return path;
    }
    std::filesystem::path writeBytes(const std::vector<uint8_t>& bytes, const char* extension)
    {
        const std::filesystem::path path = next(extension);
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return path;
    }

    std::filesystem::path dir_;

private:
    std::filesystem::path next(const char* extension) { return dir_ / ("case" + std::to_string(++files_) + extension); }
    int files_ = 0;
};

} // namespace lfd::test
