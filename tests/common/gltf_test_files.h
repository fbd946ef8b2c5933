// Writing glTF test files: little-endian values appended to a buffer, base64 for data
// URIs, and a fixture that writes each case to a file of its own in a temporary folder.
// Shared by the glTF validation and conformance tests.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
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
