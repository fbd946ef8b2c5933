// Atomic file replacement (common/atomic_file.h): the target holds the old file or the
// whole new one, and nothing is left beside it after a failure.
#include "atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("lfd_atomic_file_" + std::string(info->name()) + "_" +
                                            std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    size_t entries() const { return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }

    fs::path dir_;
};

std::string contents(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(AtomicFileTest, WritesAndReplacesLeavingOnlyTheTarget)
{
    const fs::path target = dir_ / "stats.json";
    lfd::writeFileAtomically(target, std::string_view("first"));
    lfd::writeFileAtomically(target, std::string_view("second, longer"));
    EXPECT_EQ(contents(target), "second, longer");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AThrowingWriterLeavesTheOldFileAndNoTemporary)
{
    const fs::path target = dir_ / "clip.mp4";
    lfd::writeFileAtomically(target, std::string_view("old"));
    fs::path seen;
    EXPECT_THROW(lfd::replaceFileAtomically(target,
                                                [&](const fs::path& temporary) {
                                                    seen = temporary;
                                                    std::ofstream(temporary) << "half";
                                                    throw std::runtime_error("encoder failed");
                                                }),
                 std::runtime_error);
    EXPECT_EQ(seen.parent_path(), dir_); // beside the target: rename stays on one file system
    EXPECT_EQ(contents(target), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, FailuresNameTheTargetInOneLine)
{
    const fs::path missing = dir_ / "no_such_dir" / "out.csv";
    try {
        lfd::writeFileAtomically(missing, std::string_view("x"));
        FAIL() << "writing into a missing directory must throw";
    } catch (const lfd::AtomicWriteError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    // A rename over a non-empty directory fails: the temporary goes too.
    const fs::path occupied = dir_ / "occupied";
    fs::create_directories(occupied / "inside");
    EXPECT_THROW(lfd::writeFileAtomically(occupied, std::string_view("x")), lfd::AtomicWriteError);
    EXPECT_EQ(entries(), 1u);
}

} // namespace
