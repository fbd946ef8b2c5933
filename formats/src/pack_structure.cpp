// Structural pass over untrusted pack bytes: magic, version, header and table checksums,
// section bounds, alignment, overlaps, zero padding, trailing bytes, payload checksums
// and the count/stride/version rules of every known section. Nothing is decoded here,
// and nothing is allocated from a count that has not been checked against the bytes.
#include "pack_internal.h"

#include <algorithm>
#include <cstring>

namespace lfd::pack {

namespace {

struct KnownSection {
    uint32_t tag;
    uint32_t stride;
    bool required;
    bool single; // exactly one element
};

constexpr KnownSection kKnownSections[] = {
    {kTagBakeSettings, sizeof(BakeSettingsRecord), true, true},
    {kTagBounds, sizeof(BoundsRecord), true, true},
    {kTagStrings, 1, true, false},
    {kTagPositions, 12, true, false},
    {kTagNormals, 12, false, false},
    {kTagTangents, 16, false, false},
    {kTagUvs, 8, false, false},
    {kTagIndices, 4, true, false},
    {kTagTriangleStats, sizeof(TriangleStats), true, false},
    {kTagPrimitives, sizeof(PrimitiveRecord), true, false},
    {kTagMeshes, sizeof(MeshRecord), true, false},
    {kTagMaterials, sizeof(MaterialRecord), true, false},
    {kTagTextures, sizeof(TextureRecord), true, false},
    {kTagMipLevels, sizeof(MipRecord), true, false},
    {kTagTexels, 1, true, false},
    {kTagNodes, sizeof(NodeRecord), true, false},
    {kTagAnimations, sizeof(AnimationRecord), true, false},
    {kTagChannels, sizeof(ChannelRecord), true, false},
    {kTagKeyTimes, 4, true, false},
    {kTagKeyValues, 16, true, false},
    {kTagJoints, 16, false, false},
    {kTagWeights, 16, false, false},
    {kTagMorphPositions, 12, false, false},
    {kTagMorphNormals, 12, false, false},
    {kTagMorphTangents, 12, false, false},
    {kTagSkins, sizeof(SkinRecord), false, false},
    {kTagSkinJoints, sizeof(SkinJointRecord), false, false},
    {kTagDeformers, sizeof(DeformerRecord), false, false},
    {kTagDeformerWeights, 4, false, false},
    {kTagMaterialExtensions, sizeof(MaterialExtensionRecord), false, false},
    {kTagLights, sizeof(LightRecord), false, false},
};

// The newest layout version of a known section (ACHN's version 2 adds Weights channels).
uint32_t newestVersion(uint32_t tag) { return tag == kTagChannels ? kChannelsWeightsVersion : kSectionVersion; }

const KnownSection* knownSection(uint32_t tag)
{
    for (const KnownSection& k : kKnownSections)
        if (k.tag == tag)
            return &k;
    return nullptr;
}

std::string quoted(uint32_t tag) { return "section '" + tagName(tag) + "'"; }

bool allZero(const uint8_t* p, uint64_t n)
{
    return std::all_of(p, p + n, [](uint8_t b) { return b == 0; });
}

class StructureChecker {
public:
    StructureChecker(const uint8_t* data, size_t size, const std::string& name, uint32_t deferredChecksumTag)
        : data_(data), size_(size), name_(name), deferredChecksumTag_(deferredChecksumTag)
    {
    }

    SectionTable run()
    {
        checkHeader();
        readTable();
        checkLayout();
        checkPayloads();
        checkKnownSections();
        return std::move(table_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { pack::fail(name_, problem); }

    void checkHeader()
    {
        // Magic and version are checked on whatever prefix exists, so a foreign or newer
        // file is named as such rather than as "truncated".
        const size_t magicBytes = std::min(size_, sizeof kMagic);
        if (std::memcmp(data_, kMagic, magicBytes) != 0)
            fail("not an .lfdpack file (bad magic)");
        if (size_ >= offsetof(FileHeader, formatVersion) + 4) {
            uint32_t version;
            std::memcpy(&version, data_ + offsetof(FileHeader, formatVersion), 4);
            if (version < kOldestFormatVersion || version > kFormatVersion)
                fail("unsupported format version " + std::to_string(version) + " (this reader supports " +
                     std::to_string(kOldestFormatVersion) + " to " + std::to_string(kFormatVersion) + ")");
        }
        if (size_ < sizeof(FileHeader))
            fail("truncated: file has " + std::to_string(size_) + " bytes, the header needs " +
                 std::to_string(sizeof(FileHeader)));
        std::memcpy(&header_, data_, sizeof header_);
        if (checksum(data_, kHeaderChecksummedBytes) != header_.headerChecksum)
            fail("header checksum mismatch (corrupt header)");
        if (header_.headerSize != sizeof(FileHeader) || header_.sectionEntrySize != sizeof(SectionEntry) ||
            header_.tableOffset != sizeof(FileHeader) || header_.reserved != 0)
            fail("malformed header (header size " + std::to_string(header_.headerSize) + ", entry size " +
                 std::to_string(header_.sectionEntrySize) + ", table offset " + std::to_string(header_.tableOffset) +
                 ")");
    }

    void readTable()
    {
        const uint64_t available = size_ - sizeof(FileHeader);
        const uint64_t tableBytes = uint64_t(header_.sectionCount) * sizeof(SectionEntry);
        if (tableBytes > available)
            fail("truncated: section table of " + std::to_string(header_.sectionCount) + " entries ends at byte " +
                 std::to_string(sizeof(FileHeader) + tableBytes) + " but file has " + std::to_string(size_) +
                 " bytes");
        tableEnd_ = sizeof(FileHeader) + tableBytes;
        if (checksum(data_ + sizeof(FileHeader), size_t(tableBytes)) != header_.tableChecksum)
            fail("section table checksum mismatch (corrupt table)");
        if (header_.fileSize != size_) {
            if (header_.fileSize > size_)
                fail("truncated: header says the file has " + std::to_string(header_.fileSize) + " bytes but it has " +
                     std::to_string(size_));
            fail("trailing bytes: header says the file has " + std::to_string(header_.fileSize) +
                 " bytes but it has " + std::to_string(size_));
        }
        table_.entries.resize(header_.sectionCount); // bounded by the bytes present
        if (tableBytes > 0) // an empty table has no storage: memcpy from/to null is undefined
            std::memcpy(table_.entries.data(), data_ + sizeof(FileHeader), size_t(tableBytes));
    }

    void checkLayout()
    {
        std::vector<const SectionEntry*> byOffset;
        byOffset.reserve(table_.entries.size());
        for (const SectionEntry& e : table_.entries) {
            if (e.offset > size_ || e.size > size_ - e.offset)
                fail("truncated: " + quoted(e.tag) + " ends at byte " + endString(e) + " but file has " +
                     std::to_string(size_) + " bytes");
            if (e.offset % kAlignment != 0)
                fail(quoted(e.tag) + " offset " + std::to_string(e.offset) + " is not a multiple of " +
                     std::to_string(kAlignment));
            if (e.offset < tableEnd_)
                fail(quoted(e.tag) + " at byte " + std::to_string(e.offset) +
                     " overlaps the header and section table (which end at byte " + std::to_string(tableEnd_) + ")");
            if (header_.formatVersion == 1 && e.encoding != 0)
                fail(quoted(e.tag) + " has a non-zero reserved field");
            if (e.encoding > kEncodingZstd)
                fail(quoted(e.tag) + " has unknown encoding " + std::to_string(e.encoding));
            byOffset.push_back(&e);
        }
        // Empty sections sort first among equal offsets: one may share its offset with the
        // section that follows it, but may not lie inside another.
        std::stable_sort(byOffset.begin(), byOffset.end(), [](const SectionEntry* a, const SectionEntry* b) {
            return a->offset != b->offset ? a->offset < b->offset : a->size < b->size;
        });

        // Everything between the table and the sections, and between sections, is
        // alignment padding: it must be zero so that no byte of the file is unchecked.
        uint64_t cursor = tableEnd_;
        const SectionEntry* previous = nullptr;
        for (const SectionEntry* e : byOffset) {
            if (e->offset < cursor)
                fail(quoted(e->tag) + " [" + std::to_string(e->offset) + ", " + endString(*e) + ") overlaps " +
                     quoted(previous->tag) + " [" + std::to_string(previous->offset) + ", " + endString(*previous) +
                     ")");
            if (!allZero(data_ + cursor, e->offset - cursor))
                fail("non-zero padding bytes before " + quoted(e->tag));
            cursor = e->offset + e->size;
            previous = e;
        }
        if (cursor != size_)
            fail("trailing bytes: the last section ends at byte " + std::to_string(cursor) + " but file has " +
                 std::to_string(size_) + " bytes");
    }

    void checkPayloads() const
    {
        for (const SectionEntry& e : table_.entries)
            if (e.tag != deferredChecksumTag_ && checksum(data_ + e.offset, size_t(e.size)) != e.checksum)
                fail(quoted(e.tag) + " checksum mismatch (corrupt payload)");
    }

    void checkKnownSections()
    {
        table_.info.formatVersion = header_.formatVersion;
        table_.info.fileSize = size_;
        for (const SectionEntry& e : table_.entries) {
            table_.info.sections.push_back(
                PackSectionInfo{tagName(e.tag), e.version, e.offset, e.size, e.checksum, e.count, e.encoding});
            const KnownSection* known = knownSection(e.tag);
            if (!known)
                continue; // forward compatibility: unknown sections are skipped
            if (table_.find(e.tag) != &e)
                fail("duplicate " + quoted(e.tag));
            if (e.version < kSectionVersion || e.version > newestVersion(e.tag))
                fail(quoted(e.tag) + " has unsupported version " + std::to_string(e.version));
            if (e.stride != known->stride)
                fail(quoted(e.tag) + " has element size " + std::to_string(e.stride) + ", expected " +
                     std::to_string(known->stride));
            if (e.encoding == kEncodingZstd)
                checkZstdSection(e, *known);
            else if (e.count != e.size / known->stride || e.size % known->stride != 0)
                fail(quoted(e.tag) + " count " + std::to_string(e.count) + " is inconsistent with its " +
                     std::to_string(e.size) + " bytes");
            if (known->single && e.count != 1)
                fail(quoted(e.tag) + " must hold exactly one element, has " + std::to_string(e.count));
        }
        for (const KnownSection& k : kKnownSections)
            if (k.required && !table_.find(k.tag))
                fail("missing required " + quoted(k.tag));
    }

    // A zstd section's count is checked against what its stored bytes may expand to
    // (kZstdMaxRatio), so inflating it allocates no more than that; the frame itself is
    // checked to hold exactly count * stride bytes when it is inflated.
    void checkZstdSection(const SectionEntry& e, const KnownSection& known) const
    {
        if (e.tag == kTagTexels)
            fail(quoted(e.tag) + " cannot be zstd-compressed as a whole (its levels carry their own encoding)");
        if (e.count > maxInflatedBytes(e.size) / known.stride)
            fail(quoted(e.tag) + " count " + std::to_string(e.count) + " is more than its " + std::to_string(e.size) +
                 " compressed bytes may hold");
    }

    static std::string endString(const SectionEntry& e)
    {
        // offset + size may exceed 64 bits in a corrupt table: print it without wrapping.
        if (e.size > UINT64_MAX - e.offset)
            return std::to_string(e.offset) + "+" + std::to_string(e.size);
        return std::to_string(e.offset + e.size);
    }

    const uint8_t* data_;
    size_t size_;
    const std::string& name_;
    uint32_t deferredChecksumTag_; // its payload is verified by the caller as it is read
    FileHeader header_{};
    uint64_t tableEnd_ = 0;
    SectionTable table_;
};

} // namespace

const SectionEntry* SectionTable::find(uint32_t tag) const
{
    for (const SectionEntry& e : entries)
        if (e.tag == tag)
            return &e;
    return nullptr;
}

const uint8_t* SectionTable::payload(const uint8_t* file, const SectionEntry& entry) const
{
    if (entry.encoding != kEncodingZstd)
        return file + entry.offset;
    for (const auto& [tag, bytes] : inflated)
        if (tag == entry.tag)
            return bytes.data();
    return nullptr; // unknown zstd sections are not inflated
}

void inflateSections(const uint8_t* data, SectionTable& table, const std::string& name)
{
    for (const SectionEntry& e : table.entries) {
        if (e.encoding != kEncodingZstd || !knownSection(e.tag))
            continue;
        table.inflated.emplace_back(e.tag, inflate(data + e.offset, size_t(e.size), e.count * e.stride, name,
                                                   "section '" + tagName(e.tag) + "'"));
    }
}

SectionTable validateStructure(const uint8_t* data, size_t size, const std::string& name,
                               uint32_t deferredChecksumTag)
{
    SectionTable table = StructureChecker(data, size, name, deferredChecksumTag).run();
    inflateSections(data, table, name);
    return table;
}

} // namespace lfd::pack
