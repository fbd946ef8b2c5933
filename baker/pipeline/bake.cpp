// bake(): the stages in order (docs/baker/lfd-bake.md "What a bake does"), each timed for the report.
#include "bake.h"

#include "bake_outputs.h"
#include "gltf_import.h"
#include "mip_chain.h"
#include "parallel.h"
#include "rgbd_import.h"
#include "scene_bounds.h"
#include "simplification.h"
#include "tessellation.h"
#include "texture_bake.h"
#include "texture_budget.h"
#include "texture_compression.h"
#include "texture_prefetch.h"
#include "triangle_stats.h"
#include "lfd/display_profile.h"
#include "lfd/framing.h"
#include "lfd/pack.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace lfd::bake {

namespace {

using Clock = std::chrono::steady_clock;

// Most texture memory held at once while textures are baked ahead of the writer: a
// 16384² texture (1.33 GiB with its mips) is still baked alone, as without threads;
// 8192² ones (341 MiB) two or three at a time.
constexpr uint64_t kTextureMemoryLimit = uint64_t(1) << 30;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Framing: the scene fitted to the display volume decides what a view pixel measures (scene
// units per view pixel at the nearest depth; docs/baker/lfd-bake.md "What a bake does", step 4).
double viewPixelWorldOf(const Scene& scene, const DisplayProfile& profile, const BakeOptions& o, const Log& log)
{
    const Framing framing = fitSceneToDisplay(profile, scene.bounds, o.fill);
    const double viewPixelWorld = minViewPixelWorld(profile, framing);
    log.info("framing: radius " + std::to_string(framing.sceneRadius) + " units, 1 view pixel >= " +
             std::to_string(viewPixelWorld) + " units, edge bound " + std::to_string(o.maxEdgePx * viewPixelWorld) +
             " units");
    return viewPixelWorld;
}

// Texture sizes: GPU limit and what the views can resolve (n_tex uses the stored size).
void planTextureSizes(ImportedScene& imported, double viewPixelWorld, const BakeOptions& o, BakeReport& report)
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

void recordSettings(Scene& scene, const DisplayProfile& profile, double viewPixelWorld, const BakeOptions& o)
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
void bakeTexturesAndWrite(const ImportedScene& imported, const BakeOptions& o, const Log& log, BakeReport& report)
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
            const CompressedTextureReport compressed =
                compressForUses(baked, uses[index], o.textureCompression, threads);
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

void finishReport(const ImportedScene& imported, double viewPixelWorld, const BakeOptions& o, BakeReport& report)
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

// Every file the bake read: the glTF, its buffer and image files, the display profile.
std::vector<std::filesystem::path> bakeInputs(const ImportedScene& imported, const BakeOptions& o)
{
    std::vector<std::filesystem::path> files = imported.filesRead;
    for (const TextureSource& source : imported.textureSources)
        if (!source.file.empty())
            files.push_back(source.file);
    if (!o.display.empty())
        files.push_back(o.display);
    return files;
}

} // namespace

BakeReport bake(const BakeOptions& o, const Log& log)
{
    BakeReport report;
    // Display profile: the tessellation bound is measured in its view pixels.
    const DisplayProfile profile = o.display.empty() ? prototypeDisplayProfile() : loadDisplayProfile(o.display);
    auto timed = [&report](const char* name, auto&& step) {
        const auto start = Clock::now();
        step();
        report.stageSeconds.emplace_back(name, secondsSince(start));
    };

    ImportedScene imported;
    timed("import", [&] { imported = !o.rgbd ? importGltf(o.input, log, o.threads) : importRgbd(*o.rgbd, log); });
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
    return report;
}

} // namespace lfd::bake
