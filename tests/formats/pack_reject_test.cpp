// Every pack is untrusted: malformed, truncated, corrupted or semantically broken packs
// are rejected with a one-line PackError naming the file, never a crash.
#include "pack_test_scenes.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <limits>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lfd::test {
namespace {

using namespace lfd::pack;

// Small but complete: every section present, so the byte loops touch all of them.
Scene smallScene()
{
    Scene s = makeFullScene();
    s.textures[0] = makeTexture("a", 3, 2, true, 5);
    s.textures[1] = makeTexture("b", 1, 2, false, 6);
    return s;
}

// Raw sections, so a test can patch records in place (the zstd encoding has tests of
// its own below).
std::vector<uint8_t> smallPack() { return writePackToMemory(smallScene(), {}, PackWriteOptions{false}); }

// Patch, reseal the checksums, expect rejection: the semantic checks must catch it.
template <typename Patch>
void expectPatchRejected(Patch patch, const std::string& needle)
{
    std::vector<uint8_t> bytes = smallPack();
    patch(bytes);
    resealPack(bytes);
    expectPackRejected(bytes, needle);
}

TEST(PackReject, SmallPackIsValid)
{
    const std::vector<uint8_t> bytes = smallPack();
    EXPECT_LT(bytes.size(), 8192u);
    expectSameScene(smallScene(), readPackFromMemory(bytes.data(), bytes.size(), kTestPackName));
    // resealPack on an intact pack changes nothing.
    std::vector<uint8_t> resealed = bytes;
    resealPack(resealed);
    EXPECT_EQ(resealed, bytes);
}

TEST(PackReject, WrongMagic)
{
    std::vector<uint8_t> bytes = smallPack();
    bytes[0] = 'X';
    expectPackRejected(bytes, "not an .lfdpack file (bad magic)");
    expectPackRejected(std::vector<uint8_t>{'g', 'l', 'T', 'F'}, "bad magic");
}

TEST(PackReject, WrongFormatVersion)
{
    std::vector<uint8_t> bytes = smallPack();
    FileHeader h = headerOf(bytes);
    h.formatVersion = 3;
    setHeader(bytes, h);
    resealPack(bytes);
    expectPackRejected(bytes, "unsupported format version 3 (this reader supports 1 to 2)");
    h.formatVersion = 0;
    setHeader(bytes, h);
    expectPackRejected(bytes, "unsupported format version 0");
}

TEST(PackReject, EveryTruncation)
{
    const std::vector<uint8_t> bytes = smallPack();
    for (size_t n = 0; n < bytes.size(); ++n) {
        const std::vector<uint8_t> prefix(bytes.begin(), bytes.begin() + ptrdiff_t(n));
        SCOPED_TRACE("truncated to " + std::to_string(n) + " bytes");
        expectPackRejected(prefix, "truncated");
    }
    EXPECT_THROW(readPackFromMemory(nullptr, 0, kTestPackName), PackError);
}

TEST(PackReject, TruncatedSectionNamesTheSection)
{
    // Truncate inside the last section and make the header agree, so the section bound
    // check (not the file size check) fires.
    std::vector<uint8_t> bytes = smallPack();
    const SectionEntry texels = entryFor(bytes, kTagTexels);
    bytes.resize(size_t(texels.offset + 4));
    FileHeader h = headerOf(bytes);
    h.fileSize = bytes.size();
    setHeader(bytes, h);
    resealPack(bytes);
    expectPackRejected(bytes, "truncated: section 'TEXL' ends at byte " + std::to_string(texels.offset + texels.size) +
                              " but file has " + std::to_string(bytes.size()) + " bytes");
}

TEST(PackReject, EverySingleBitFlip)
{
    const std::vector<uint8_t> bytes = smallPack();
    for (size_t i = 0; i < bytes.size(); ++i) {
        for (int bit : {0, 7}) {
            std::vector<uint8_t> corrupt = bytes;
            corrupt[i] ^= uint8_t(1u << bit);
            SCOPED_TRACE("byte " + std::to_string(i) + " bit " + std::to_string(bit));
            packRejection(corrupt);
        }
    }
}

TEST(PackReject, CorruptPayloadNamesTheSection)
{
    std::vector<uint8_t> bytes = smallPack();
    bytes[size_t(entryFor(bytes, kTagIndices).offset) + 1] ^= 0x10;
    expectPackRejected(bytes, "section 'INDX' checksum mismatch");
    bytes = smallPack();
    bytes[70] ^= 1; // inside the table
    expectPackRejected(bytes, "section table checksum mismatch");
    bytes = smallPack();
    bytes[33] ^= 1; // header fileSize
    expectPackRejected(bytes, "header checksum mismatch");
}

TEST(PackReject, TrailingGarbage)
{
    std::vector<uint8_t> bytes = smallPack();
    bytes.push_back(0);
    expectPackRejected(bytes, "trailing bytes");

    // Even when the header claims the larger size, bytes past the last section are trailing.
    bytes = smallPack();
    bytes.resize(bytes.size() + 64, 0);
    FileHeader h = headerOf(bytes);
    h.fileSize = bytes.size();
    setHeader(bytes, h);
    resealPack(bytes);
    expectPackRejected(bytes, "trailing bytes: the last section ends at byte");
}

TEST(PackReject, OverlappingSections)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagIndices);
            SectionEntry e = entryAt(b, i);
            e.offset = entryFor(b, kTagUvs).offset; // INDX now starts inside VTUV
            setEntry(b, i, e);
        },
        "overlaps section");
}

TEST(PackReject, EmptySectionsMayShareAnOffset)
{
    // An empty section occupies no bytes: it may sit where another payload starts.
    const Scene empty;
    for (const uint32_t host : {kTagBakeSettings, kTagBounds}) {
        std::vector<uint8_t> bytes = writePackToMemory(empty);
        const uint32_t i = *entryIndex(bytes, kTagIndices);
        SectionEntry e = entryAt(bytes, i);
        ASSERT_EQ(e.size, 0u);
        e.offset = entryFor(bytes, host).offset;
        setEntry(bytes, i, e);
        resealPack(bytes);
        EXPECT_NO_THROW(readPackFromMemory(bytes.data(), bytes.size(), kTestPackName)) << tagName(host);
    }
}

TEST(PackReject, SectionOverlappingTheTable)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            SectionEntry e = entryAt(b, 0);
            e.offset = 64;
            setEntry(b, 0, e);
        },
        "overlaps the header and section table");
}

TEST(PackReject, MisalignedSection)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagTexels);
            SectionEntry e = entryAt(b, i);
            e.offset += 4;
            e.size -= 4;
            e.count -= 4;
            setEntry(b, i, e);
        },
        "section 'TEXL' offset");
}

TEST(PackReject, NonZeroPadding)
{
    // Find the first section preceded by alignment padding (some payload ends unaligned).
    const std::vector<uint8_t> bytes = smallPack();
    const FileHeader h = headerOf(bytes);
    std::vector<SectionEntry> sections;
    for (uint32_t i = 0; i < h.sectionCount; ++i)
        sections.push_back(entryAt(bytes, i));
    std::sort(sections.begin(), sections.end(),
              [](const SectionEntry& a, const SectionEntry& b) { return a.offset < b.offset; });
    uint64_t end = sizeof(FileHeader) + h.sectionCount * sizeof(SectionEntry);
    for (const SectionEntry& e : sections) {
        if (e.offset > end) {
            expectPatchRejected([&](std::vector<uint8_t>& b) { b[size_t(e.offset) - 1] = 0xAB; },
                                "non-zero padding bytes before section '" + tagName(e.tag) + "'");
            return;
        }
        end = e.offset + e.size;
    }
    FAIL() << "the small pack has no padding";
}

TEST(PackReject, HugeElementCounts)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagPositions);
            SectionEntry e = entryAt(b, i);
            e.count = uint64_t(1) << 60;
            setEntry(b, i, e);
        },
        "section 'VPOS' count 1152921504606846976 is inconsistent");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagTexels);
            SectionEntry e = entryAt(b, i);
            e.size = std::numeric_limits<uint64_t>::max() - 8;
            e.count = e.size;
            setEntry(b, i, e);
        },
        "truncated: section 'TEXL' ends at byte");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            FileHeader h = headerOf(b);
            h.sectionCount = 0xFFFFFFFFu;
            setHeader(b, h);
        },
        "truncated: section table of 4294967295 entries");
    // A channel claiming 2^40 keys must be caught before anything is allocated.
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            ChannelRecord c = readElement<ChannelRecord>(b, kTagChannels, 0);
            c.keyCount = uint64_t(1) << 40;
            writeElement(b, kTagChannels, 0, c);
        },
        "animation 0 channel 0: keys [0, +1099511627776)");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            AnimationRecord a = readElement<AnimationRecord>(b, kTagAnimations, 1);
            a.channelCount = 0xFFFFFFF0u;
            writeElement(b, kTagAnimations, 1, a);
        },
        "animation 1: channels [3, +4294967280)");
}

// Runs `read` in a child process whose address space is capped 512 MiB above what it
// already uses, so a count that drove an allocation before being checked would end in
// std::bad_alloc instead of the expected PackError. Returns the child's verdict.
// Under AddressSanitizer (which reserves terabytes of shadow memory) the cap cannot be
// set; the child then only checks the error, and ASan's own allocation limits apply.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kCanCapAddressSpace = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kCanCapAddressSpace = false;
#else
constexpr bool kCanCapAddressSpace = true;
#endif
#else
constexpr bool kCanCapAddressSpace = true;
#endif

size_t currentAddressSpaceBytes()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmSize:", 0) == 0)
            return size_t(std::stoull(line.substr(7))) * 1024;
    return 0;
}

std::string rejectedUnderMemoryCap(const std::vector<uint8_t>& bytes, const std::string& needle)
{
    int pipeFds[2];
    if (::pipe(pipeFds) != 0)
        return "pipe failed";
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(pipeFds[0]);
        std::string verdict;
        if (kCanCapAddressSpace) {
            const rlim_t cap = rlim_t(currentAddressSpaceBytes() + (size_t(512) << 20));
            const rlimit limit{cap, cap};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        try {
            readPackFromMemory(bytes.data(), bytes.size(), kTestPackName);
            verdict = "accepted";
        } catch (const PackError& e) {
            verdict = std::string(e.what()).find(needle) != std::string::npos ? "ok" : std::string(e.what());
        } catch (const std::bad_alloc&) {
            verdict = "std::bad_alloc: an allocation was sized before the check";
        }
        [[maybe_unused]] const ssize_t written = ::write(pipeFds[1], verdict.data(), verdict.size());
        ::_exit(0);
    }
    ::close(pipeFds[1]);
    std::string verdict;
    char buffer[512];
    ssize_t n;
    while ((n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0)
        verdict.append(buffer, size_t(n));
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    return verdict.empty() ? "child died (status " + std::to_string(status) + ")" : verdict;
}

// Crafted headers and records whose counts or sizes, if trusted, would allocate
// gigabytes or more: each is rejected, under a 512 MiB address-space cap.
TEST(PackReject, CraftedSizesAreCheckedBeforeAllocation)
{
    struct Case {
        const char* what;
        std::function<void(std::vector<uint8_t>&)> patch;
        const char* needle;
    };
    const Case cases[] = {
        {"section table of 2^32 - 1 entries (192 GiB)",
         [](std::vector<uint8_t>& b) {
             FileHeader h = headerOf(b);
             h.sectionCount = 0xFFFFFFFFu;
             setHeader(b, h);
         },
         "truncated: section table of 4294967295 entries"},
        {"2^60 positions",
         [](std::vector<uint8_t>& b) {
             const uint32_t i = *entryIndex(b, kTagPositions);
             SectionEntry e = entryAt(b, i);
             e.count = uint64_t(1) << 60;
             setEntry(b, i, e);
         },
         "section 'VPOS' count 1152921504606846976 is inconsistent"},
        {"2^62-byte index section",
         [](std::vector<uint8_t>& b) {
             const uint32_t i = *entryIndex(b, kTagIndices);
             SectionEntry e = entryAt(b, i);
             e.size = uint64_t(1) << 62;
             e.count = e.size / 4;
             setEntry(b, i, e);
         },
         "truncated: section 'INDX' ends at byte"},
        {"a 65536 x 65536 texture (22 GiB with mips) in a few bytes of texels",
         [](std::vector<uint8_t>& b) {
             TextureRecord t = readElement<TextureRecord>(b, kTagTextures, 0);
             t.width = t.height = kMaxTextureDimension;
             t.mipCount = 17; // consistent with the size: the MIPS and TEXL runs must catch it
             t.texelSize = 0; // RGBA8, full chain: 22.9 GB
             for (uint64_t w = t.width, h = t.height;; w = std::max<uint64_t>(w / 2, 1), h = std::max<uint64_t>(h / 2, 1)) {
                 t.texelSize += w * h * 4;
                 if (w == 1 && h == 1)
                     break;
             }
             writeElement(b, kTagTextures, 0, t);
         },
         "texture 0: mip levels [0, +17) do not follow the previous texture's"},
        {"2^40 animation keys",
         [](std::vector<uint8_t>& b) {
             ChannelRecord c = readElement<ChannelRecord>(b, kTagChannels, 0);
             c.keyCount = uint64_t(1) << 40;
             writeElement(b, kTagChannels, 0, c);
         },
         "animation 0 channel 0: keys [0, +1099511627776)"},
        {"2^32 - 16 channels",
         [](std::vector<uint8_t>& b) {
             AnimationRecord a = readElement<AnimationRecord>(b, kTagAnimations, 1);
             a.channelCount = 0xFFFFFFF0u;
             writeElement(b, kTagAnimations, 1, a);
         },
         "animation 1: channels [3, +4294967280)"},
        {"a 4 GiB mesh name",
         [](std::vector<uint8_t>& b) {
             writeElement<uint32_t>(b, kTagMeshes, 0, 0xFFFFFFF0u, offsetof(MeshRecord, name) + 4);
         },
         "mesh 0: name ["},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        std::vector<uint8_t> bytes = smallPack();
        c.patch(bytes);
        resealPack(bytes);
        EXPECT_EQ(rejectedUnderMemoryCap(bytes, c.needle), "ok");
    }
}

TEST(PackReject, OutOfRangeIndex)
{
    expectPatchRejected([](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagIndices, 5, 8); },
                        "index 5 (triangle 1) is 8 but there are 8 vertices");
}

TEST(PackReject, NonFiniteFloats)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagPositions, 3, nan, 4); },
                        "vertex 3: position is not finite");
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagNormals, 0, inf); },
                        "vertex 0: normal is not finite");
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagUvs, 7, nan, 4); },
                        "vertex 7: uv is not finite");
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagTriangleStats, 1, nan, 8); },
                        "triangle 1: statistics are not finite");
    expectPatchRejected(
        [&](std::vector<uint8_t>& b) {
            writeElement(b, kTagMaterials, 0, inf, offsetof(MaterialRecord, roughnessFactor));
        },
        "material 0: factors are not finite");
    expectPatchRejected(
        [&](std::vector<uint8_t>& b) { writeElement(b, kTagNodes, 2, nan, offsetof(NodeRecord, rotation)); },
        "node 2: transform is not finite");
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagKeyValues, 1, nan); },
                        "animation 0 channel 0: key 1 is not finite");
    expectPatchRejected([&](std::vector<uint8_t>& b) { writeElement(b, kTagBounds, 0, inf); },
                        "scene bounds are not finite");
    expectPatchRejected(
        [&](std::vector<uint8_t>& b) {
            writeElement(b, kTagBakeSettings, 0, nan, offsetof(BakeSettingsRecord, framingFill));
        },
        "bake settings are not finite");
}

TEST(PackReject, DanglingReferences)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<int32_t>(b, kTagPrimitives, 1, 2, offsetof(PrimitiveRecord, material));
        },
        "primitive 1: material 2 does not exist (2 materials)");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<int32_t>(b, kTagMaterials, 0, 2, offsetof(MaterialRecord, normalTexture));
        },
        "material 0: normal texture 2 does not exist (2 textures)");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<int32_t>(b, kTagMaterials, 1, -2, offsetof(MaterialRecord, baseColorTexture));
        },
        "material 1: baseColor texture -2 does not exist");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<int32_t>(b, kTagNodes, 3, 7, offsetof(NodeRecord, mesh)); },
        "node 3: mesh 7 does not exist (2 meshes)");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagChannels, 2, 4, offsetof(ChannelRecord, node)); },
        "animation 0 channel 2: node 4 does not exist (4 nodes)");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagMeshes, 1, 2, offsetof(MeshRecord, primitiveCount));
        },
        "mesh 1: primitive range [2, +2) exceeds the 3 primitives");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagPrimitives, 2, 9, offsetof(PrimitiveRecord, indexCount));
        },
        "primitive 2: index range [6, +9) exceeds the 12 indices");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagPrimitives, 0, 1, offsetof(PrimitiveRecord, firstIndex));
        },
        "primitive 0: index range [1, +3) is not made of whole triangles");
}

TEST(PackReject, ParentMustPrecedeChild)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<int32_t>(b, kTagNodes, 1, 1, offsetof(NodeRecord, parent)); },
        "node 1: parent 1 does not precede the node");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<int32_t>(b, kTagNodes, 1, 3, offsetof(NodeRecord, parent)); },
        "node 1: parent 3 does not precede the node");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<int32_t>(b, kTagNodes, 2, -5, offsetof(NodeRecord, parent)); },
        "node 2: parent -5 does not precede the node");
}

TEST(PackReject, InvalidEnumsAndFlags)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagMaterials, 0, 3, offsetof(MaterialRecord, alphaMode));
        },
        "material 0: invalid alpha mode 3");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagMaterials, 0, 2, offsetof(MaterialRecord, doubleSided));
        },
        "material 0: doubleSided is 2");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagChannels, 1, 4, offsetof(ChannelRecord, path)); },
        "animation 0 channel 1: invalid path 4");
    expectPatchRejected( // weights (path 3) exist only in ACHN version 2
        [](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagChannels, 1, 3, offsetof(ChannelRecord, path)); },
        "animation 0 channel 1: a weights channel in a version-1 'ACHN' section");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagChannels, 1, 2, offsetof(ChannelRecord, interpolation));
        },
        "animation 0 channel 1: invalid interpolation 2");
    expectPatchRejected([](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagTriangleStats, 0, 4u, 20); },
                        "triangle 0: unknown flags");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagTextures, 0, 4, offsetof(TextureRecord, flags)); },
        "texture 0: unknown flags 4");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagPrimitives, 0, 1, offsetof(PrimitiveRecord, reserved));
        },
        "primitive 0: non-zero reserved field");
}

TEST(PackReject, AnimationKeys)
{
    expectPatchRejected([](std::vector<uint8_t>& b) { writeElement(b, kTagKeyTimes, 2, 0.5f); },
                        "animation 0 channel 0: key times are not strictly increasing at key 2");
    expectPatchRejected([](std::vector<uint8_t>& b) { writeElement(b, kTagKeyTimes, 1, 0.0f); },
                        "not strictly increasing at key 1");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            // Move a key from channel 0 to channel 1: the runs no longer follow each other.
            writeElement<uint64_t>(b, kTagChannels, 1, 2, offsetof(ChannelRecord, firstKey));
        },
        "animation 0 channel 1: keys [2, +2) do not follow");
}

TEST(PackReject, MipChainAndTexelRanges)
{
    expectPatchRejected([](std::vector<uint8_t>& b) { writeElement<uint32_t>(b, kTagMipLevels, 1, 2); },
                        "texture 0: mip level 1 is 2x1");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagTextures, 1, 3, offsetof(TextureRecord, mipCount));
        },
        "texture 1: 3 mip levels, a 1x2 texture has 2");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint64_t>(b, kTagTextures, 1, 4, offsetof(TextureRecord, texelOffset));
        },
        "texture 1: texels [4, +12) are not the next 12 bytes");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagTextures, 0, 0, offsetof(TextureRecord, width));
        },
        "texture 0: size 0x2 is outside 1..65536");
}

TEST(PackReject, StringsOutOfRange)
{
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            writeElement<uint32_t>(b, kTagMeshes, 0, 0xFFFFFFF0u, offsetof(MeshRecord, name));
        },
        "mesh 0: name [4294967280, +");
    // Many records pointing at the same bytes would multiply allocations: refused.
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const StringRef all{0, uint32_t(entryFor(b, kTagStrings).size)};
            writeElement(b, kTagNodes, 0, all, offsetof(NodeRecord, name));
        },
        "names add up to more bytes than the string section holds");
}

TEST(PackReject, SectionTableRules)
{
    auto retag = [](uint32_t from, uint32_t to) {
        return [from, to](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, from);
            SectionEntry e = entryAt(b, i);
            e.tag = to;
            setEntry(b, i, e);
        };
    };
    expectPatchRejected(retag(kTagIndices, makeTag("ZZZZ")), "missing required section 'INDX'");
    expectPatchRejected(retag(kTagNormals, kTagPositions), "duplicate section 'VPOS'");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagMeshes);
            SectionEntry e = entryAt(b, i);
            e.version = 2;
            setEntry(b, i, e);
        },
        "section 'MESH' has unsupported version 2");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            const uint32_t i = *entryIndex(b, kTagIndices);
            SectionEntry e = entryAt(b, i);
            e.stride = 2;
            e.count *= 2;
            setEntry(b, i, e);
        },
        "section 'INDX' has element size 2, expected 4");
    expectPatchRejected(
        [](std::vector<uint8_t>& b) {
            FileHeader h = headerOf(b);
            h.reserved = 1;
            setHeader(b, h);
        },
        "malformed header");
}

TEST(PackReject, UnknownSectionsAreSkipped)
{
    // A section this reader does not know (here: tangents renamed) is checked for bounds
    // and checksum, then ignored; the rest of the scene reads normally.
    std::vector<uint8_t> bytes = smallPack();
    const uint32_t i = *entryIndex(bytes, kTagTangents);
    SectionEntry e = entryAt(bytes, i);
    e.tag = makeTag("XTRA");
    e.version = 7;
    e.stride = 3; // unknown sections may use any element size
    setEntry(bytes, i, e);
    resealPack(bytes);
    Scene expected = smallScene();
    expected.vertices.tangents.clear();
    expectSameScene(expected, readPackFromMemory(bytes.data(), bytes.size(), kTestPackName));

    // ...but its payload is still covered by its checksum.
    bytes[size_t(e.offset)] ^= 1;
    expectPackRejected(bytes, "section 'XTRA' checksum mismatch");
}

TEST(PackReject, ErrorMessagesStayOnOneLine)
{
    std::vector<uint8_t> bytes = smallPack();
    bytes[0] = 'X';
    const std::string what = packRejection(bytes, "evil\nname.lfdpack");
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_NE(what.find("evil name.lfdpack: "), std::string::npos) << what;
    // Non-printable tag bytes are escaped in messages.
    EXPECT_EQ(tagName(makeTag("A\nB\x01")), "A\\x0aB\\x01");
}

} // namespace
} // namespace lfd::test
