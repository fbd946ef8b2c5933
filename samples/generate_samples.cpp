// lfd-make-samples: writes the project's own glTF 2.0 sample scenes.
//
//   lfd-make-samples OUTDIR [--scene gallery|car|room|dense|character|crowd|rgbd|spheres|terrain|all] [--texture-size N]
//                    [--instances N] [--quiet]
//
// Each scene goes to OUTDIR/<scene>/ (<scene>.gltf, <scene>.bin, PNG textures). A scene
// is written into a hidden staging directory beside it and renamed into place when
// complete, so OUTDIR/<scene> is either the old scene or the whole new one.
// Exit status: 0 success, 1 failure while writing, 2 bad command line.
#include "sample_scenes.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace lfd::samples;

namespace {

constexpr const char* kUsage =
    "usage: lfd-make-samples OUTDIR [--scene gallery|car|room|dense|character|crowd|rgbd|spheres|terrain|all] [--texture-size N] "
    "[--instances N] [--quiet]\n"
    "  --scene         which scene to write (default: all)\n"
    "  --texture-size  gallery painting size in pixels, 16..32768 (default: 2048)\n"
    "  --instances     cars in the room scene (default 16), objects in the dense scene\n"
    "                  (default 240: about 1.1M drawn triangles), characters in the crowd\n"
    "                  (default 100: about 1M drawn triangles), 1..10000\n"
    "  --quiet         print errors only\n";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    fs::path outDir;
    std::vector<std::string> scenes;
    int textureSize = 2048;
    int instances = 0; // 0: the scene's default
    bool quiet = false;
};

int parseInt(std::string_view option, std::string_view text, int lo, int hi)
{
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
        throw UsageError(std::string(option) + " expects an integer in " + std::to_string(lo) +
                         ".." + std::to_string(hi) + ", got '" + std::string(text) + "'");
    return value;
}

Options parseArguments(int argc, char** argv)
{
    Options options;
    std::string scene = "all";
    bool haveOutDir = false;
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        std::string_view value;
        // Accept both "--opt value" and "--opt=value".
        const size_t eq = arg.find('=');
        const bool inlineValue = arg.rfind("--", 0) == 0 && eq != std::string_view::npos;
        if (inlineValue) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
        }
        auto takeValue = [&]() -> std::string_view {
            if (inlineValue)
                return value;
            if (i + 1 >= argc)
                throw UsageError(std::string(arg) + " needs a value");
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        } else if (arg == "--scene") {
            scene = takeValue();
        } else if (arg == "--texture-size") {
            options.textureSize = parseInt(arg, takeValue(), 16, 32768);
        } else if (arg == "--instances") {
            options.instances = parseInt(arg, takeValue(), 1, 10000);
        } else if (arg == "--quiet") {
            options.quiet = true;
        } else if (arg.rfind("-", 0) == 0 && arg.size() > 1) {
            throw UsageError("unknown option '" + std::string(arg) + "'");
        } else if (!haveOutDir) {
            options.outDir = std::string(arg);
            haveOutDir = true;
        } else {
            throw UsageError("unexpected argument '" + std::string(arg) + "' (only one OUTDIR)");
        }
    }
    if (!haveOutDir || options.outDir.empty())
        throw UsageError("missing OUTDIR");
    if (scene == "all")
        options.scenes = {"gallery", "car", "room"}; // dense is for benchmarks: ask for it
    else if (scene == "gallery" || scene == "car" || scene == "room" || scene == "dense" || scene == "character" ||
             scene == "crowd" || scene == "rgbd" || scene == "spheres" ||
             scene == "terrain")
        options.scenes = {scene};
    else
        throw UsageError("unknown scene '" + scene +
                         "' (expected gallery, car, room, dense, character, crowd, rgbd, spheres, terrain or all)");
    return options;
}

uintmax_t directoryBytes(const fs::path& dir)
{
    uintmax_t total = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file())
            total += entry.file_size();
    return total;
}

// Writes one scene into a staging directory, then swaps it into OUTDIR/<name>.
SceneSummary writeSceneAtomically(const Options& options, const std::string& name)
{
    const fs::path target = options.outDir / name;
    const std::string suffix = std::to_string(::getpid());
    const fs::path staging = options.outDir / ("." + name + ".tmp-" + suffix);
    const fs::path retired = options.outDir / ("." + name + ".old-" + suffix);
    if (fs::exists(target) && !fs::is_directory(target))
        throw std::runtime_error(target.string() + ": exists and is not a directory");

    fs::remove_all(staging);
    std::error_code ec;
    if (!fs::create_directory(staging, ec) || ec)
        throw std::runtime_error(staging.string() + ": cannot create staging directory: " +
                                 (ec ? ec.message() : "already exists"));
    SceneSummary summary;
    try {
        if (name == "gallery")
            summary = writeGalleryScene(staging, options.textureSize);
        else if (name == "car")
            summary = writeCarScene(staging);
        else if (name == "rgbd")
            summary = writeRgbdSample(staging);
        else if (name == "spheres")
            summary = writeSpheresScene(staging);
        else if (name == "terrain")
            summary = writeTerrainScene(staging);
        else if (name == "character")
            summary = writeCharacterScene(staging);
        else if (name == "crowd")
            summary = writeCrowdScene(staging, options.instances > 0 ? options.instances : 100);
        else if (name == "room")
            summary = writeRoomScene(staging, options.instances > 0 ? options.instances : 16);
        else
            summary = writeDenseScene(staging, options.instances > 0 ? options.instances : 240);
        // Replace the previous version only once the new one is complete.
        if (fs::exists(target)) {
            fs::rename(target, retired);
            fs::rename(staging, target);
            fs::remove_all(retired);
        } else {
            fs::rename(staging, target);
        }
    } catch (...) {
        std::error_code ignored;
        fs::remove_all(staging, ignored);
        throw;
    }
    return summary;
}

void run(const Options& options)
{
    std::error_code ec;
    if (fs::exists(options.outDir, ec) && !fs::is_directory(options.outDir, ec))
        throw std::runtime_error(options.outDir.string() + ": exists and is not a directory");
    fs::create_directories(options.outDir, ec);
    if (ec)
        throw std::runtime_error(options.outDir.string() +
                                 ": cannot create output directory: " + ec.message());
    if (::access(options.outDir.c_str(), W_OK) != 0)
        throw std::runtime_error(options.outDir.string() + ": output directory is not writable");

    for (const std::string& name : options.scenes) {
        const auto start = std::chrono::steady_clock::now();
        const SceneSummary summary = writeSceneAtomically(options, name);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!options.quiet) {
            const fs::path dir = options.outDir / name;
            if (name == "rgbd")
                std::printf("rgbd: photo, depth map and side-by-side image -> %s (for lfd-bake --rgbd; %.1f s)\n",
                            dir.c_str(), seconds);
            else
                std::printf("%s: %zu triangles stored, %zu drawn, %d textures, %.1f MiB -> %s (%.1f s)\n",
                            name.c_str(), summary.storedTriangles, summary.drawnTriangles,
                            summary.textures, double(directoryBytes(dir)) / (1024.0 * 1024.0),
                            (dir / (name + ".gltf")).c_str(), seconds);
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    try {
        options = parseArguments(argc, argv);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "lfd-make-samples: error: %s (see --help)\n", e.what());
        return 2;
    }
    try {
        run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lfd-make-samples: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
