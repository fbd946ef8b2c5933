// lfd-bake: glTF 2.0 -> .lfdpack (see docs/baker/lfd-bake.md) and `lfd-bake --inspect PACK`.
#include "bake.h"
#include "bake_bench.h"
#include "bake_outputs.h"
#include "bake_report.h"
#include "mip_chain.h"
#include "parallel.h"
#include "rgbd_import.h"
#include "simplification.h"
#include "texture_compression.h"
#include "texture_prefetch.h"
#include "lfd/pack.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <iostream>
#include <new>

namespace {

using namespace lfd;
using namespace lfd::bake;
using Clock = std::chrono::steady_clock;

// Most texture memory held at once while textures are baked ahead of the writer: a
// 16384² texture (1.33 GiB with its mips) is still baked alone, as without threads;
// 8192² ones (341 MiB) two or three at a time.
constexpr uint64_t kTextureMemoryLimit = uint64_t(1) << 30;

struct Options {
    std::filesystem::path input, output, display, inspect;
    std::filesystem::path depfile; // --depfile: the files the bake read, Make/Ninja syntax
    double maxEdgePx = 100.0;
    double simplifyPx = 0.25; // --simplify: merge triangles within this error, view pixels (0: off)
    double fill = 1.0;
    uint32_t maxTextureSize = 16384;
    double textureDetail = 2.0;
    bool keepFullTextures = false;
    TextureCompression textureCompression = TextureCompression::Bc;
    bool quiet = false;
    bool strict = false;
    unsigned threads = 0; // 0: one per hardware thread
    bool bench = false;
    unsigned benchRun = 0; // > 0: one --bench run in this process (started by --bench)
    BenchOptions benchOptions;
    std::vector<std::filesystem::path> rgbd; // --rgbd COLOR [DEPTH]: an RGB-D image instead of glTF
    RgbdOptions rgbdOptions;
    std::vector<double> rgbdDepthRange;
};

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

int inspect(const std::filesystem::path& path)
{
    PackInfo info;
    const Scene scene = readPack(path, &info); // one read: verified, decoded, section table
    printInspectReport(std::cout, path, info, scene);
    return 0;
}

// Where the bake's messages go: warnings to stderr (or, with --strict, the first one
// refuses the input), progress to stdout unless --quiet.
Log bakeLog(const Options& o)
{
    Log log;
    const std::string file = o.input.string();
    if (o.strict) {
        // --strict: the first warning (schema or otherwise) refuses the input.
        log.warn = [file](const std::string& s) { throw BakeError(file + ": " + s + " (--strict)"); };
    } else {
        log.warn = [file](const std::string& s) { std::cerr << "lfd-bake: warning: " << file << ": " << s << "\n"; };
    }
    if (!o.quiet)
        log.info = [](const std::string& s) { std::cout << s << "\n" << std::flush; };
    return log;
}

// Framing: the scene fitted to the display volume decides what a view pixel measures (scene units
// per view pixel at the nearest depth; docs/baker/lfd-bake.md "What a bake does", step 4).
double viewPixelWorldOf(const Scene& scene, const DisplayProfile& profile, const Options& o, const Log& log)
{
    const Framing framing = fitSceneToDisplay(profile, scene.bounds, o.fill);
    const double viewPixelWorld = minViewPixelWorld(profile, framing);
    log.info("framing: radius " + std::to_string(framing.sceneRadius) + " units, 1 view pixel >= " +
             std::to_string(viewPixelWorld) + " units, edge bound " + std::to_string(o.maxEdgePx * viewPixelWorld) +
             " units");
    return viewPixelWorld;
}

// Texture sizes: GPU limit and what the views can resolve (n_tex uses the stored size).
void planTextureSizes(ImportedScene& imported, double viewPixelWorld, const Options& o, BakeReport& report)
{
    Scene& scene = imported.scene;
    const std::vector<float> meshScale = meshMaxWorldScale(scene);
    for (size_t t = 0; t < scene.textures.size(); ++t) {
        Texture& texture = scene.textures[t];
        const glm::uvec2 source = probeTextureSize(imported.textureSources[t]);
        glm::uvec2 stored = storedTextureSize(source, TextureBakeOptions{o.maxTextureSize});
        if (!o.keepFullTextures)
            stored = glm::min(stored, resolvableTextureSize(scene, uint32_t(t), stored, viewPixelWorld, meshScale,
                                                            o.textureDetail));
        texture.sourceWidth = source.x;
        texture.sourceHeight = source.y;
        texture.width = stored.x;
        texture.height = stored.y;
        report.textures.push_back({texture.name, source, stored, texture.srgb});
    }
}

void recordSettings(Scene& scene, const DisplayProfile& profile, double viewPixelWorld, const Options& o)
{
    scene.settings.bakerVersion = LFD_VERSION;
    scene.settings.sourceFile = o.input.filename().string();
    scene.settings.displayProfile = profile.name;
    scene.settings.viewWidth = profile.viewWidth;
    scene.settings.viewHeight = profile.viewHeight;
    scene.settings.viewCount = profile.viewCount;
    scene.settings.maxEdgePx = float(o.maxEdgePx);
    scene.settings.framingFill = float(o.fill);
    scene.settings.viewPixelWorld = float(viewPixelWorld);
    scene.settings.maxTextureSize = o.maxTextureSize;
}

// Textures are decoded, mipmapped and block-compressed (texture_compression.h) in the
// order the writer needs them, the ones after the texture being written on spare threads
// as far as kTextureMemoryLimit allows; the writer streams the pack out.
void bakeTexturesAndWrite(const ImportedScene& imported, const Options& o, const Log& log, BakeReport& report)
{
    const Scene& scene = imported.scene;
    ThreadBudget threads(o.threads);
    std::vector<uint64_t> textureBytes;
    for (const Texture& t : scene.textures)
        textureBytes.push_back(mip::chainBytes(mip::chainLayout(t.width, t.height)));
    const std::vector<uint32_t> uses = textureUses(scene);
    TexturePrefetcher prefetcher(
        [&](uint32_t index) {
            const Texture& meta = scene.textures[index];
            Texture baked = bakeTexture(imported.textureSources[index],
                                        TextureBakeOptions{std::max(meta.width, meta.height), 0, &threads});
            const TextureFormat format = o.textureCompression == TextureCompression::None
                                             ? TextureFormat::Rgba8
                                             : chooseTextureFormat(uses[index], opaqueAlpha(baked));
            const CompressedTextureReport compressed = compressTexture(baked, format, uses[index], threads);
            TextureReport& line = report.textures[index];
            line.format = compressed.format;
            line.bytes = compressed.bytes;
            line.psnr = compressed.psnr;
            return baked;
        },
        textureBytes, threads, kTextureMemoryLimit);
    size_t done = 0;
    const TextureProducer produce = [&](uint32_t index) {
        const Texture& meta = scene.textures[index];
        Texture baked = prefetcher.take(index);
        baked.name = meta.name;
        log.info("textures: " + std::to_string(++done) + "/" + std::to_string(scene.textures.size()) + " " +
                 meta.name + " " + std::to_string(baked.width) + "x" + std::to_string(baked.height) + " " +
                 textureFormatName(baked.format));
        return baked;
    };
    writePack(o.output, scene, produce);
}

void finishReport(const ImportedScene& imported, double viewPixelWorld, const Options& o, BakeReport& report)
{
    report.pack = verifyPack(o.output);
    report.trianglesIn = imported.sourceTriangles;
    report.trianglesOut = imported.scene.triangleCount();
    report.vertices = imported.scene.vertices.size();
    report.maxEdgePxBefore = report.tessellation.maxEdgeWorldBefore / viewPixelWorld;
    report.maxEdgePxAfter = report.tessellation.maxEdgeWorldAfter / viewPixelWorld;
    report.meanEdgePxAfter = report.tessellation.meanEdgeWorldAfter / viewPixelWorld;
    report.meanPieceEdgePx = report.tessellation.meanPieceEdgeWorld / viewPixelWorld;
    report.warnings = imported.warnings.size();
    report.extensionLines = materialAndLightLines(imported.scene);
    report.peakRssBytes = peakResidentBytes();
    report.threads = resolveThreads(o.threads);
}

// RGB-D input (rgbd_import.h): a photo and depth map, or one side-by-side image.
void addRgbdFlags(CLI::App& app, Options& o)
{
    RgbdOptions& r = o.rgbdOptions;
    app.add_option("--rgbd", o.rgbd,
                   "bake a photo and its depth map (COLOR DEPTH), or one side-by-side image (COLOR|DEPTH), instead "
                   "of a glTF scene")
        ->expected(1, 2);
    app.add_option("--rgbd-relief", r.relief, "RGB-D: depth of the relief in image heights (default 0.5)")
        ->check(CLI::Range(0.0, 100.0));
    app.add_option("--rgbd-depth-range", o.rgbdDepthRange,
                   "RGB-D: the depth-map values (0..1) mapped to far and near; others are clamped (default 0 1)")
        ->expected(2);
    app.add_flag("--rgbd-invert", r.invert, "RGB-D: black is near (default: white is near)");
    app.add_option("--rgbd-edges", r.edges,
                   "RGB-D: triangles across a depth discontinuity: drop (default) or stretch")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, RgbdEdges>{{"drop", RgbdEdges::Drop}, {"stretch", RgbdEdges::Stretch}},
            CLI::ignore_case));
    app.add_option("--rgbd-edge-threshold", r.edgeThreshold,
                   "RGB-D: a triangle spanning more than this fraction of the depth range is a discontinuity "
                   "(default 0.05)")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--rgbd-flatness", r.flatness,
                   "RGB-D: merge grid triangles where the surface is flat within this many image heights "
                   "(default 0.001; 0: one vertex per depth pixel)")
        ->check(CLI::Range(0.0, 1.0));
}

// Every file the bake read: the glTF, its buffer and image files, the display profile.
std::vector<std::filesystem::path> bakeInputs(const ImportedScene& imported, const Options& o)
{
    std::vector<std::filesystem::path> files = imported.filesRead;
    for (const TextureSource& source : imported.textureSources)
        if (!source.file.empty())
            files.push_back(source.file);
    if (!o.display.empty())
        files.push_back(o.display);
    return files;
}

// The bake, stage by stage (docs/baker/lfd-bake.md "What a bake does"), each stage timed for the
// report.
int bakeScene(const Options& o)
{
    BakeReport report;
    const Log log = bakeLog(o);
    // Display profile: the tessellation bound is measured in its view pixels.
    const DisplayProfile profile = o.display.empty() ? prototypeDisplayProfile() : loadDisplayProfile(o.display);
    auto timed = [&report](const char* name, auto&& step) {
        const auto start = Clock::now();
        step();
        report.stageSeconds.emplace_back(name, secondsSince(start));
    };

    ImportedScene imported;
    timed("import", [&] { imported = o.rgbd.empty() ? importGltf(o.input, log, o.threads) : importRgbd(o.rgbdOptions, log); });
    Scene& scene = imported.scene;
    double viewPixelWorld = 0.0;
    timed("bounds", [&] {
        scene.bounds = computeBounds(scene);
        viewPixelWorld = viewPixelWorldOf(scene, profile, o, log);
    });
    // Merge what the display cannot resolve, then split what is too long (issue 40): one
    // view-pixel measure for both, so the output still meets the --max-edge-px bound.
    timed("simplify",
          [&] { report.simplification = simplifyScene(scene, o.simplifyPx, viewPixelWorld, log, o.threads); });
    timed("tessellate",
          [&] { report.tessellation = tessellateScene(scene, o.maxEdgePx * viewPixelWorld, log, o.threads); });
    timed("triangle stats", [&] {
        planTextureSizes(imported, viewPixelWorld, o, report);
        computeTriangleStats(scene, o.threads);
    });
    recordSettings(scene, profile, viewPixelWorld, o);
    timed("textures + write", [&] { bakeTexturesAndWrite(imported, o, log, report); });

    finishReport(imported, viewPixelWorld, o, report);
    if (!o.depfile.empty())
        writeDepfile(o.depfile, o.output, bakeInputs(imported, o));
    if (!o.quiet) // --quiet: warnings and errors only
        printBakeReport(std::cout, o.output, report);
    return 0;
}

// Every lfd-bake flag (docs/baker/lfd-bake.md).
void addBakeFlags(CLI::App& app, Options& o)
{
    app.add_option("input", o.input, "glTF 2.0 scene (.gltf or .glb)");
    app.add_option("-o,--output", o.output, "output pack (.lfdpack)");
    app.add_option("--inspect", o.inspect, "verify a pack and print its summary (exit 0 only if it verifies)");
    app.add_option("--display", o.display, "display profile JSON or Looking Glass visual.json (default: the paper's prototype)");
    app.add_option("--max-edge-px", o.maxEdgePx, "split triangles whose edges exceed this many view pixels (default 100)")
        ->check(CLI::Range(1.0, 1e6));
    app.add_option("--simplify", o.simplifyPx,
                   "merge triangles finer than the display resolves, keeping the surface within this many view "
                   "pixels (same measure as --max-edge-px; seams, borders and material boundaries kept; default "
                   "0.25; 0: off)")
        ->check(CLI::Validator(
            [](std::string& value) -> std::string {
                // note: CLI::Range lets NaN through (every comparison with it is false).
                double px = 0.0;
                try {
                    size_t used = 0;
                    px = std::stod(value, &used);
                    if (used != value.size())
                        return "expected a number of view pixels, got '" + value + "'";
                } catch (const std::exception&) {
                    return "expected a number of view pixels, got '" + value + "'";
                }
                if (!std::isfinite(px) || px < 0.0 || px > 1e6)
                    return "expected view pixels in [0, 1e6], got '" + value + "'";
                return std::string();
            },
            "PX"));
    app.add_option("--fill", o.fill, "fraction of the largest sphere fitting every view (formats/display_profiles.md 4.) the scene's bounding sphere fills (default 1)")
        ->check(CLI::Range(0.01, 1.0));
    app.add_option("--max-texture-size", o.maxTextureSize, "largest texture dimension kept (GPU limit, default 16384)")
        ->check(CLI::Range(1u, 65536u));
    app.add_option("--texture-detail", o.textureDetail,
                   "keep textures this many times finer than the finest view pixel (default 2: room for 2x supersampling)")
        ->check(CLI::Range(0.1, 64.0));
    app.add_flag("--keep-full-textures", o.keepFullTextures, "never drop mip levels the views cannot resolve");
    app.add_option("--texture-compression", o.textureCompression,
                   "bc: block-compress every texture by what its materials read (BC1/BC3 colour, BC5 normals, BC4 "
                   "single channels); none: RGBA8 (default bc)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, TextureCompression>{{"none", TextureCompression::None}, {"bc", TextureCompression::Bc}},
            CLI::ignore_case));
    app.add_option("--depfile", o.depfile,
                   "also write the files the bake read (glTF, buffers, images, display profile) as a Make/Ninja "
                   "depfile with the output as its target, for incremental batch builds");
    addRgbdFlags(app, o);
    app.add_flag("-q,--quiet", o.quiet, "print warnings and errors only");
    app.add_flag("--strict", o.strict, "treat every warning (e.g. a glTF schema violation the baker can work around) as an error");
    app.add_option("--threads", o.threads,
                   "threads for Draco/meshopt decoding, simplification, tessellation, triangle statistics and mip chains (default 0: "
                   "one per hardware thread; 1: serial); the pack is the same bytes for any count")
        ->check(CLI::Range(0u, 1024u));
    app.add_flag("--bench", o.bench,
                 "measure tessellation, triangle statistics, mip chains and BC1 compression with 1 and 2 threads (and --threads N "
                 "if above 2) on a generated scene; no input or output");
    app.add_option("--bench-triangles", o.benchOptions.triangles, "--bench scene size (default 1048576 triangles)")
        ->check(CLI::Range(size_t(16), size_t(1) << 26));
    app.add_option("--bench-texture-size", o.benchOptions.textureSize,
                   "--bench texture width and height (default 16384)")
        ->check(CLI::Range(1u, 16384u));
    app.add_option("--bench-repeat", o.benchOptions.repeat,
                   "--bench runs each stage this many times per thread count and reports the fastest (default 3)")
        ->check(CLI::Range(1u, 100u));
    app.add_option("--bench-run", o.benchRun)->check(CLI::Range(1u, 1024u))->group(""); // internal, see bake_bench.h
}

} // namespace

int main(int argc, char** argv)
{
    Options o;
    CLI::App app{"lfd-bake: bake a glTF 2.0 scene into a .lfdpack for light field display rendering"};
    addBakeFlags(app, o);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "lfd-bake: " << e.what() << "\n";
        return 2;
    }

    try {
        if (!o.inspect.empty())
            return inspect(o.inspect);
        if (o.benchRun > 0)
            return runBenchChild(o.benchOptions, o.benchRun, std::cout);
        if (o.bench) {
            if (o.threads > 2)
                o.benchOptions.threads.push_back(o.threads);
            return runBench(o.benchOptions, std::cout);
        }
        if (!o.rgbd.empty()) {
            if (!o.input.empty())
                throw BakeError("--rgbd: give either a glTF INPUT or --rgbd, not both");
            o.rgbdOptions.color = o.rgbd[0];
            o.rgbdOptions.depth = o.rgbd.size() > 1 ? o.rgbd[1] : std::filesystem::path();
            if (o.rgbdDepthRange.size() == 2) {
                o.rgbdOptions.depthLow = o.rgbdDepthRange[0];
                o.rgbdOptions.depthHigh = o.rgbdDepthRange[1];
            }
            o.input = o.rgbd[0]; // names the bake in messages, the settings and a folder output
        }
        if (o.input.empty() || o.output.empty()) {
            std::cerr << "lfd-bake: need INPUT and -o OUTPUT (or --inspect PACK); see --help\n";
            return 2;
        }
        // Checked before the import: a wrong output path is reported in a moment, not
        // after the whole bake.
        o.output = resolveOutputPath(o.input, o.output);
        if (!o.depfile.empty())
            o.depfile = resolveOutputPath(o.input, o.depfile, ".d");
        return bakeScene(o);
    } catch (const std::bad_alloc&) {
        // Input sizes are checked before allocation; this is the last line of defence.
        std::cerr << "lfd-bake: error: " << (o.inspect.empty() ? o.input : o.inspect).string()
                  << ": out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        // Every stage reports one line naming the file and the problem.
        std::cerr << "lfd-bake: error: " << e.what() << "\n";
        return 1;
    }
}
