// lfd-bake: glTF 2.0 -> .lfdpack (see docs/baker/lfd-bake.md) and `lfd-bake --inspect PACK`.
// Flags to BakeOptions only; the bake itself is bake() (pipeline/bake.h).
#include "bake.h"
#include "bake_bench.h"
#include "bake_outputs.h"
#include "bake_report.h"
#include "gltf_issue_codes.h"
#include "rgbd_import.h"
#include "texture_compression.h"
#include "lfd/pack.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <map>
#include <cstdio>
#include <iostream>
#include <new>

namespace {

using namespace lfd;
using namespace lfd::bake;

// The flags: the bake's options, and what only the tool needs (--inspect, --quiet,
// --strict, --bench, the RGB-D flags before they become BakeOptions::rgbd).
struct Options {
    BakeOptions bake;
    std::filesystem::path inspect;
    bool quiet = false;
    bool strict = false;
    bool bench = false;
    bool listIssueCodes = false;
    unsigned benchRun = 0; // > 0: one --bench run in this process (started by --bench)
    BenchOptions benchOptions;
    std::vector<std::filesystem::path> rgbd; // --rgbd COLOR [DEPTH]: an RGB-D image instead of glTF
    RgbdOptions rgbdOptions;
    std::vector<double> rgbdDepthRange;
};

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
    const std::string file = o.bake.input.string();
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

// Every lfd-bake flag (docs/baker/lfd-bake.md).
void addBakeFlags(CLI::App& app, Options& o)
{
    app.add_option("input", o.bake.input, "glTF 2.0 scene (.gltf or .glb)");
    app.add_option("-o,--output", o.bake.output, "output pack (.lfdpack)");
    app.add_option("--inspect", o.inspect, "verify a pack and print its summary (exit 0 only if it verifies)");
    app.add_option("--display", o.bake.display, "display profile JSON or Looking Glass visual.json (default: the paper's prototype)");
    app.add_option("--max-edge-px", o.bake.maxEdgePx, "split triangles whose edges exceed this many view pixels (default 100)")
        ->check(CLI::Range(1.0, 1e6));
    app.add_option("--simplify", o.bake.simplifyPx,
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
    app.add_option("--fill", o.bake.fill, "fraction of the largest sphere fitting every view (formats/display_profiles.md 4.) the scene's bounding sphere fills (default 1)")
        ->check(CLI::Range(0.01, 1.0));
    app.add_option("--max-texture-size", o.bake.maxTextureSize, "largest texture dimension kept (GPU limit, default 16384)")
        ->check(CLI::Range(1u, 65536u));
    app.add_option("--texture-detail", o.bake.textureDetail,
                   "keep textures this many times finer than the finest view pixel (default 2: room for 2x supersampling)")
        ->check(CLI::Range(0.1, 64.0));
    app.add_flag("--keep-full-textures", o.bake.keepFullTextures, "never drop mip levels the views cannot resolve");
    app.add_option("--texture-compression", o.bake.textureCompression,
                   "bc: block-compress every texture by what its materials read (BC1/BC3 colour, BC5 normals, BC4 "
                   "single channels); none: RGBA8 (default bc)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, TextureCompression>{{"none", TextureCompression::None}, {"bc", TextureCompression::Bc}},
            CLI::ignore_case));
    app.add_option("--depfile", o.bake.depfile,
                   "also write the files the bake read (glTF, buffers, images, display profile) as a Make/Ninja "
                   "depfile with the output as its target, for incremental batch builds");
    addRgbdFlags(app, o);
    app.add_flag("-q,--quiet", o.quiet, "print warnings and errors only");
    app.add_flag("--strict", o.strict, "treat every warning (e.g. a glTF schema violation the baker can work around) as an error");
    app.add_flag("--list-issue-codes", o.listIssueCodes,
                 "print the catalogue of glTF issue codes (code, severity, meaning) as a Markdown table and exit");
    app.add_option("--threads", o.bake.threads,
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
        if (o.listIssueCodes) {
            std::cout << lfd::bake::gltf::issueCodeTable();
            return 0;
        }
        if (!o.inspect.empty())
            return inspect(o.inspect);
        if (o.benchRun > 0)
            return runBenchChild(o.benchOptions, o.benchRun, std::cout);
        if (o.bench) {
            if (o.bake.threads > 2)
                o.benchOptions.threads.push_back(o.bake.threads);
            return runBench(o.benchOptions, std::cout);
        }
        if (!o.rgbd.empty()) {
            if (!o.bake.input.empty())
                throw BakeError("--rgbd: give either a glTF INPUT or --rgbd, not both");
            o.rgbdOptions.color = o.rgbd[0];
            o.rgbdOptions.depth = o.rgbd.size() > 1 ? o.rgbd[1] : std::filesystem::path();
            if (o.rgbdDepthRange.size() == 2) {
                o.rgbdOptions.depthLow = o.rgbdDepthRange[0];
                o.rgbdOptions.depthHigh = o.rgbdDepthRange[1];
            }
            o.bake.input = o.rgbd[0]; // names the bake in messages, the settings and a folder output
            o.bake.rgbd = o.rgbdOptions;
        }
        if (o.bake.input.empty() || o.bake.output.empty()) {
            std::cerr << "lfd-bake: need INPUT and -o OUTPUT (or --inspect PACK); see --help\n";
            return 2;
        }
        // Checked before the import: a wrong output path is reported in a moment, not
        // after the whole bake.
        o.bake.output = resolveOutputPath(o.bake.input, o.bake.output);
        if (!o.bake.depfile.empty())
            o.bake.depfile = resolveOutputPath(o.bake.input, o.bake.depfile, ".d");
        const BakeReport report = lfd::bake::bake(o.bake, bakeLog(o));
        if (!o.quiet) // --quiet: warnings and errors only
            printBakeReport(std::cout, o.bake.output, report);
        return 0;
    } catch (const std::bad_alloc&) {
        // Input sizes are checked before allocation; this is the last line of defence.
        std::cerr << "lfd-bake: error: " << (o.inspect.empty() ? o.bake.input : o.inspect).string()
                  << ": out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        // Every stage reports one line naming the file and the problem.
        std::cerr << "lfd-bake: error: " << e.what() << "\n";
        return 1;
    }
}
