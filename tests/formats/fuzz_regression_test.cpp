// Inputs the fuzzers found (scripts/fuzz.sh), committed under tests/data/fuzz/pack: each
// is read as found and resealed (checksums fixed up, as tests/fuzz/pack_fuzz.cpp does, so
// it reaches the structure checks) and must be rejected with one PackError line. In the
// sanitizer build (scripts/sanitize.sh) these also prove the undefined behaviour they
// once triggered is gone.
#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

namespace fs = std::filesystem;
const fs::path kFindings = fs::path(LFD_TEST_DATA) / "fuzz" / "pack";

std::vector<uint8_t> readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string rejection(const std::vector<uint8_t>& bytes, const std::string& name)
{
    try {
        lfd::readPackFromMemory(bytes.data(), bytes.size(), name);
    } catch (const lfd::PackError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(name + ": ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        return what;
    }
    ADD_FAILURE() << name << " was accepted";
    return "";
}

TEST(PackFuzzRegression, FindingsAreRejectedWithOneLine)
{
    struct Finding {
        const char* file;
        const char* asFound;  // part of the error for the bytes as found
        const char* resealed; // part of the error once the checksums are fixed up
    };
    const Finding findings[] = {
        // sectionCount 0: the table copy was a memcpy from a null vector (UBSan).
        {"empty_section_table.lfdpack", "header checksum mismatch", "trailing bytes: the last section ends at byte 64"},
    };
    for (const Finding& f : findings) {
        SCOPED_TRACE(f.file);
        std::vector<uint8_t> bytes = readBytes(kFindings / f.file);
        ASSERT_FALSE(bytes.empty());
        EXPECT_NE(rejection(bytes, f.file).find(f.asFound), std::string::npos);
        lfd::pack::resealPack(bytes);
        const std::string resealed = rejection(bytes, f.file);
        EXPECT_NE(resealed.find(f.resealed), std::string::npos) << resealed;
    }
    // Every committed finding is in the table.
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kFindings))
        files += entry.is_regular_file();
    EXPECT_EQ(files, std::size(findings));
}

} // namespace
