// Shared pack helpers: the checksum, tag printing, mip chain arithmetic, one-line
// errors and the test-only resealing of a patched pack.
#include "pack_internal.h"

#include <xxhash.h>

#include <algorithm>
#include <cstring>

namespace lfd::pack {

uint64_t checksum(const void* data, size_t size) { return XXH3_64bits(data, size); }

std::string tagName(uint32_t tag)
{
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    for (int i = 0; i < 4; ++i) {
        const auto c = uint8_t(tag >> (8 * i));
        if (c >= 0x20 && c < 0x7f && c != '\\' && c != '\'') {
            out += char(c);
        } else {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    return out;
}

void fail(const std::string& name, const std::string& problem)
{
    std::string message = name + ": " + problem;
    std::replace_if(
        message.begin(), message.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw PackError(message);
}

uint32_t fullMipCount(uint32_t width, uint32_t height)
{
    // floor(log2(max(w, h))) + 1 levels end at 1x1.
    const uint32_t largest = std::max({width, height, 1u});
    return uint32_t(std::bit_width(largest));
}

void resealPack(std::vector<uint8_t>& bytes)
{
    if (bytes.size() < sizeof(FileHeader))
        return;
    FileHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    const uint64_t tableBytes = uint64_t(header.sectionCount) * sizeof(SectionEntry);
    if (tableBytes > bytes.size() - sizeof header) {
        // No table to reseal: still seal the header, so a test can claim a huge table.
        header.headerChecksum = checksum(bytes.data(), kHeaderChecksummedBytes);
        std::memcpy(bytes.data(), &header, sizeof header);
        return;
    }

    // Payload checksums first: they live in the table the table checksum covers.
    uint8_t* table = bytes.data() + sizeof header;
    for (uint32_t i = 0; i < header.sectionCount; ++i) {
        SectionEntry entry;
        std::memcpy(&entry, table + i * sizeof entry, sizeof entry);
        if (entry.offset > bytes.size() || entry.size > bytes.size() - entry.offset)
            continue;
        entry.checksum = checksum(bytes.data() + entry.offset, size_t(entry.size));
        std::memcpy(table + i * sizeof entry, &entry, sizeof entry);
    }
    header.tableChecksum = checksum(table, size_t(tableBytes));
    std::memcpy(bytes.data(), &header, sizeof header);
    header.headerChecksum = checksum(bytes.data(), kHeaderChecksummedBytes);
    std::memcpy(bytes.data(), &header, sizeof header);
}

} // namespace lfd::pack
