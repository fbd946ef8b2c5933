// The self-contained player (docs/player/another-machine.md): lfd-play links
// no image library and few others, scripts/bundle-player.sh makes a bundle within 15 MB in
// which every library the tools load resolves to the bundle, glibc or the GL driver, and
// the bundle's lfd-play renders what the build tree's does.
#include "gl_test_support.h"
#include "test_scenes.h"
#include "tool_run.h"

#include "image_metrics.h"
#include "lfd/pack.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace lfd::test {
namespace {

namespace fs = std::filesystem;

// The libraries ldd resolves for `binary` (name -> path; "not found" as the path).
std::vector<std::pair<std::string, std::string>> resolvedLibraries(const std::string& lddOutput)
{
    std::vector<std::pair<std::string, std::string>> libs;
    std::istringstream lines(lddOutput);
    std::string line;
    const std::regex resolved(R"(^\s*(\S+) => (\S+))");
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_search(line, m, resolved))
            libs.emplace_back(m[1], m[2] == "not" ? "not found" : std::string(m[2]));
    return libs;
}

// glibc's own libraries and the GL driver's loaders: what the target machine provides.
bool providedByTheTarget(const std::string& name)
{
    static const std::regex provided(
        R"(^(libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv\.so|ld-linux|libEGL|libGL|libOpenGL|libGLX|libGLdispatch))");
    return std::regex_search(name, provided);
}

uint64_t folderBytes(const fs::path& dir)
{
    uint64_t bytes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file())
            bytes += entry.file_size();
    return bytes;
}

class BundleTest : public GlTest {};

TEST(PlayerLibraries, LfdPlayLinksNoImageLibraryAndFewOthers)
{
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    const auto [rc, ldd] = run("ldd '" + play.string() + "'");
    ASSERT_EQ(rc, 0) << ldd;
    size_t lines = 0;
    std::istringstream in(ldd);
    for (std::string line; std::getline(in, line);)
        lines += !line.empty();
    EXPECT_LE(lines, 20u) << ldd;
    EXPECT_EQ(ldd.find("OpenImageIO"), std::string::npos) << ldd;
    EXPECT_EQ(ldd.find("not found"), std::string::npos) << ldd;
}

TEST_F(BundleTest, BundleIsSelfContainedSmallAndRendersLikeTheBuild)
{
    const fs::path dir = testOutputDir("bundle");
    const fs::path pack = dir / "scene.lfdpack";
    writePack(pack, cubeAndSphereScene());
    const fs::path bundle = dir / "lfd-bundle";
    const auto [rc, out] = run("LFD_BUILD_DIR='" + std::string(LFD_BINARY_DIR) + "' bash '" LFD_SOURCE_DIR
                               "/scripts/bundle-player.sh' '" + bundle.string() + "' '" + pack.string() + "'");
    ASSERT_EQ(rc, 0) << out;
    ASSERT_TRUE(fs::exists(bundle / "lfd-play"));
    ASSERT_TRUE(fs::exists(dir / "lfd-bundle.tar.gz"));
    EXPECT_TRUE(fs::exists(bundle / "packs" / "scene.lfdpack"));
    EXPECT_TRUE(fs::exists(bundle / "MANIFEST.txt"));

    // Within 15 MB: the tools and every library they need.
    const uint64_t bytes = folderBytes(bundle / "libexec") + folderBytes(bundle / "lib");
    EXPECT_LE(bytes, 15u * 1000u * 1000u) << bytes << " bytes";
    std::printf("[ bundle   ] tools and libraries: %.1f MB\n", double(bytes) / 1e6);

    // Every library resolves inside the bundle or to what the target provides.
    for (const char* tool : {"lfd-play", "lfd-bench"}) {
        const auto [lddRc, ldd] =
            run("LD_LIBRARY_PATH='" + (bundle / "lib").string() + "' ldd '" + (bundle / "libexec" / tool).string() + "'");
        ASSERT_EQ(lddRc, 0) << ldd;
        for (const auto& [name, path] : resolvedLibraries(ldd)) {
            if (providedByTheTarget(name))
                continue;
            EXPECT_EQ(path.rfind((bundle / "lib").string(), 0), 0u) << tool << ": " << name << " resolves to " << path;
        }
    }

    // The bundle's lfd-play renders the build's EIA.
    const fs::path play = fs::path(LFD_BINARY_DIR) / "player" / "lfd-play";
    const std::string flags = " --headless '" + pack.string() + "' --renderer lfdpr --views 6 --view-size 64x48 --out ";
    const auto [a, aOut] = run("'" + (bundle / "lfd-play").string() + "'" + flags + "'" + (dir / "bundle.png").string() + "'");
    ASSERT_EQ(a, 0) << aOut;
    const auto [b, bOut] = run("'" + play.string() + "'" + flags + "'" + (dir / "build.png").string() + "'");
    ASSERT_EQ(b, 0) << bOut;
    const metrics::Image fromBundle = metrics::readImage(dir / "bundle.png", 4);
    const metrics::Image fromBuild = metrics::readImage(dir / "build.png", 4);
    EXPECT_EQ(fromBundle.pixels, fromBuild.pixels);
}

} // namespace
} // namespace lfd::test
