// The bake's outputs as a build system sees them (docs/baker/batch-baking.md): the output path
// (a folder names "<stem>.lfdpack" in it; a missing folder is refused before the import),
// the depfile (every file read, Make/Ninja escapes), and the progress clock long stages
// print by.
#include "bake_outputs.h"
#include "progress_clock.h"

#include "tool_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using lfd::test::kBake;
using lfd::test::kMakeSamples;
using lfd::test::quoted;
using lfd::test::run;
using lfd::test::RunResult;

namespace {

class BakeOutputs : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("lfd_bake_outputs_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

std::string fileText(const fs::path& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}


TEST(DepfileText, EscapesForMakeAndNinjaAndListsEachFileOnce)
{
    const std::string text = lfd::bake::depfileText("out dir/a.lfdpack", {"/x/a b#1$.gltf", "/x/a.bin", "/x/a.bin"});
    EXPECT_EQ(text, "out\\ dir/a.lfdpack: \\\n  /x/a\\ b\\#1$$.gltf \\\n  /x/a.bin\n");
}

TEST(ProgressClock, IsDueOncePerIntervalAndNotAtTheStart)
{
    lfd::ProgressClock clock(0.05);
    EXPECT_FALSE(clock.due()); // a fast stage prints nothing
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    EXPECT_TRUE(clock.due());
    EXPECT_FALSE(clock.due()); // not twice in one interval
}

TEST_F(BakeOutputs, FolderOutputNamesThePackAfterTheInputAndDepfileListsEveryFileRead)
{
    ASSERT_EQ(run(kMakeSamples + " " + quoted(dir_ / "s") + " --scene gallery --texture-size 64 --quiet").exitCode, 0);
    const fs::path profile = fs::path(LFD_SOURCE_DIR) / "samples/profiles/looking_glass_portrait_visual.json";
    fs::create_directories(dir_ / "out");
    const RunResult r = run(kBake + " " + quoted(dir_ / "s/gallery/gallery.gltf") + " -o " + quoted(dir_ / "out") +
                            " --depfile " + quoted(dir_ / "out/") + " --display " + quoted(profile) + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    ASSERT_TRUE(fs::exists(dir_ / "out/gallery.lfdpack"));
    const std::string depfile = fileText(dir_ / "out/gallery.d");
    EXPECT_EQ(depfile.rfind((dir_ / "out/gallery.lfdpack").string() + ":", 0), 0u) << depfile;
    for (const char* file : {"gallery/gallery.gltf", "gallery/gallery.bin", "gallery/picture.png",
                             "gallery/floor_normal.png"})
        EXPECT_NE(depfile.find((fs::weakly_canonical(dir_ / "s") / file).string()), std::string::npos)
            << file << " missing from\n" << depfile;
    EXPECT_NE(depfile.find(fs::weakly_canonical(profile).string()), std::string::npos) << depfile;
}

TEST_F(BakeOutputs, MissingOutputFolderIsRefusedBeforeTheInputIsRead)
{
    // The input is malformed too: the error names the output folder, so it came first.
    std::ofstream(dir_ / "bad.gltf") << "{ not json";
    const RunResult r = run(kBake + " " + quoted(dir_ / "bad.gltf") + " -o " + quoted(dir_ / "nowhere/x.lfdpack"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, "lfd-bake: error: " + (dir_ / "nowhere/x.lfdpack").string() + ": cannot write: folder '" +
                         (dir_ / "nowhere").string() + "' does not exist\n");
    const RunResult slash = run(kBake + " " + quoted(dir_ / "bad.gltf") + " -o " + quoted(dir_ / "nowhere") + "/");
    EXPECT_EQ(slash.exitCode, 1);
    EXPECT_NE(slash.out.find("cannot write: folder"), std::string::npos) << slash.out;
    EXPECT_FALSE(fs::exists(dir_ / "nowhere"));
}

} // namespace
