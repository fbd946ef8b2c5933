// lfd-play's streaming flags end to end (docs/player/streaming.md): the default (mapped,
// streamed, resident before timing) and --no-streaming write the same views and report
// the loading figures in --stats; --gpu-memory-budget too small for the geometry, and a
// pack with a corrupt texel, end with one line naming the file and a non-zero exit.
#include "gl_test_support.h"
#include "player_cli_fixture.h"
#include "render_test_util.h"
#include "test_scenes.h"
#include "tool_run.h"

#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;


std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct PlayRun {
    int status = -1;
    std::string err;
};

PlayRun play(const fs::path& dir, const std::string& args)
{
    const fs::path err = dir / "stderr.txt";
    const std::string command = "'" + kPlay.string() + "' " + args + " > /dev/null 2> '" + err.string() + "'";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(err)};
}

class StreamingCliTest : public PlayerCliTest {
protected:
    StreamingCliTest() : PlayerCliTest("streaming_", "streaming-small") {}
    std::string common() const
    {
        return "--headless " + quoted(pack_) + " --display " + quoted(profile_) + " --views 4 --view-size 48x36 --frames 2";
    }
};

TEST_F(StreamingCliTest, StreamedAndNotStreamedWriteTheSameViewsAndReportLoading)
{
    nlohmann::json stats[2];
    for (int streamed = 0; streamed < 2; ++streamed) {
        const fs::path out = dir_ / (streamed ? "streamed" : "eager");
        fs::create_directories(out);
        const PlayRun r = play(dir_, common() + (streamed ? "" : " --no-streaming") + " --views-out " + quoted(out / "views") +
                                     " --stats " + quoted(out / "stats.json"));
        ASSERT_EQ(r.status, 0) << r.err;
        stats[streamed] = nlohmann::json::parse(slurp(out / "stats.json"));
    }
    for (uint32_t v = 0; v < 4; ++v) {
        char name[32];
        std::snprintf(name, sizeof(name), "view_%03u.png", v);
        EXPECT_EQ(slurp(dir_ / "streamed" / "views" / name), slurp(dir_ / "eager" / "views" / name)) << name;
    }
    for (int streamed = 0; streamed < 2; ++streamed) {
        const nlohmann::json& s = stats[streamed];
        SCOPED_TRACE(streamed ? "streamed" : "--no-streaming");
        EXPECT_EQ(s.at("streaming").get<bool>(), streamed == 1);
        EXPECT_GT(s.at("time_to_first_frame_ms").get<double>(), 0.0);
        EXPECT_GT(s.at("time_to_resident_ms").get<double>(), 0.0);
        EXPECT_GT(s.at("peak_host_memory_mib").get<double>(), 1.0);
        EXPECT_GT(s.at("gpu_scene_bytes").get<uint64_t>(), 0u);
    }
    // Streaming shows a frame before the finer levels are in; --no-streaming only after.
    EXPECT_LE(stats[1].at("time_to_first_frame_ms").get<double>(), stats[1].at("time_to_resident_ms").get<double>());
    EXPECT_GE(stats[0].at("time_to_first_frame_ms").get<double>(), stats[0].at("time_to_resident_ms").get<double>());
    EXPECT_EQ(stats[0].at("gpu_scene_bytes"), stats[1].at("gpu_scene_bytes"));
}

TEST_F(StreamingCliTest, BudgetBelowTheGeometryIsAOneLineErrorWithTheFigures)
{
    for (const char* mode : {"", " --no-streaming"}) {
        const PlayRun r = play(dir_, common() + mode + " --gpu-memory-budget 0");
        EXPECT_EQ(r.status, 1) << r.err;
        EXPECT_NE(r.err.find("scene.lfdpack"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("geometry needs"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("MiB"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    }
}

TEST_F(StreamingCliTest, CorruptTexelIsAOneLineErrorNamingTheFile)
{
    std::vector<uint8_t> bytes = writePackToMemory(cubeAndSphereScene());
    pack::FileHeader header{};
    std::memcpy(&header, bytes.data(), sizeof header);
    for (uint32_t i = 0; i < header.sectionCount; ++i) {
        pack::SectionEntry e{};
        std::memcpy(&e, bytes.data() + sizeof header + i * sizeof e, sizeof e);
        if (e.tag == pack::kTagTexels)
            bytes[size_t(e.offset + e.size - 1)] ^= 0x01; // the 1x1 level: read first
    }
    const fs::path bad = dir_ / "corrupt.lfdpack";
    std::ofstream(bad, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    const PlayRun r = play(dir_, "--headless " + quoted(bad) + " --display " + quoted(profile_) + " --views 4 --view-size 48x36");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(bad.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("TEXL"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

} // namespace
} // namespace lfd::test
