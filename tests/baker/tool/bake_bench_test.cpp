// `lfd-bake --bench` at a small size: the report has a line per thread count with every
// figure (triangles per second, megapixels per second, peak memory), a speed-up line, and
// says that the outputs of every thread count are identical.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <regex>
#include <string>

namespace {

using lfd::test::kBake;
using lfd::test::run;
using lfd::test::RunResult;
TEST(BakeBench, SmallBenchReportsEveryFigureForOneAndTwoThreads)
{
    const RunResult r = run(kBake + " --bench --bench-triangles 20000 --bench-texture-size 512");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("8 meshes, 19600 triangles"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("512x512 sRGB texture"), std::string::npos) << r.out;

    // threads N: tessellation IN -> OUT triangles in S s = R Mtri/s (C cores); statistics OUT triangles in
    // S s = R Mtri/s (C cores); mips MP MP in S s = R MP/s (C cores); BC1 compression MP MP in S s = R MP/s
    // (C cores); peak memory M MiB
    const std::regex line(
        R"(threads (\d+): tessellation (\d+) -> (\d+) triangles in ([0-9.]+) s = ([0-9.]+) Mtri/s \([0-9.]+ cores\); )"
        R"(statistics (\d+) triangles in ([0-9.]+) s = ([0-9.]+) Mtri/s \([0-9.]+ cores\); )"
        R"(mips ([0-9.]+) MP in ([0-9.]+) s = ([0-9.]+) MP/s \([0-9.]+ cores\); )"
        R"(BC1 compression ([0-9.]+) MP in ([0-9.]+) s = ([0-9.]+) MP/s \([0-9.]+ cores\); peak memory ([0-9.]+) MiB)");
    std::vector<unsigned> threads;
    for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), line); it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        SCOPED_TRACE(m.str());
        threads.push_back(unsigned(std::stoul(m[1])));
        EXPECT_EQ(std::stoul(m[2]), 19600u);
        // Every triangle has one edge (its quad's diagonal) over the bound: cut in two.
        EXPECT_EQ(std::stoul(m[3]), 2u * 19600u);
        EXPECT_EQ(std::stoul(m[6]), 2u * 19600u);
        for (int rate : {5, 8, 11, 14})
            EXPECT_GT(std::stod(m[rate]), 0.0) << "rate " << rate;
        EXPECT_NEAR(std::stod(m[9]), 0.262144, 0.06); // 512 x 512 = 0.26 MP, printed to 0.1
        EXPECT_NEAR(std::stod(m[12]), 0.262144, 0.06);
        const double peakMiB = std::stod(m[15]);
        EXPECT_GT(peakMiB, 1.0);
        EXPECT_LT(peakMiB, 1024.0) << "a small bench must stay small";
    }
    EXPECT_EQ(threads, (std::vector<unsigned>{1, 2})) << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(speed-up 2 vs 1 threads: tessellation [0-9.]+x, )"
                                                    R"(statistics [0-9.]+x, mips [0-9.]+x, compression [0-9.]+x)")))
        << r.out;
    EXPECT_NE(r.out.find("identical output for every thread count: yes"), std::string::npos) << r.out;
}

TEST(BakeBench, ExtraThreadCountIsMeasuredToo)
{
    const RunResult r = run(kBake + " --bench --bench-triangles 2000 --bench-texture-size 64 --threads 3");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("threads 3: tessellation"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("speed-up 3 vs 1 threads"), std::string::npos) << r.out;
}

TEST(BakeBench, BadSizesAreRejected)
{
    EXPECT_NE(run(kBake + " --bench --bench-texture-size 0").exitCode, 0);
    EXPECT_NE(run(kBake + " --bench --bench-texture-size 32768").exitCode, 0);
    EXPECT_NE(run(kBake + " --bench --bench-triangles 1").exitCode, 0);
}

} // namespace
