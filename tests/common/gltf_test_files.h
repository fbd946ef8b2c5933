// Writing glTF test files byte by byte: little-endian values appended to a buffer, and
// base64 for data URIs. Shared by the glTF validation and conformance tests.
#pragma once

#include <cstdint>
#include <cstring>
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

} // namespace lfd::test
