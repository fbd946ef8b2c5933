// libFuzzer entry point for glTF ingestion (built with -DLFD_BUILD_FUZZERS=ON, run by
// scripts/fuzz.sh): the input is written to a file (.gltf JSON or .glb, told apart by
// the importer from the "glTF" magic) and taken through the CPU bake stages up to a
// tessellated, statistics-complete scene - import, bounds, framing on the prototype
// display, tessellation at the default 100-pixel edge bound, triangle statistics.
// Any input must either get there or throw lfd::bake::BakeError: crashes, sanitizer
// reports, other exceptions, timeouts and huge allocations are bugs.
#include "bake.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// One private directory per fuzzing process: relative URIs in the input resolve inside
// it, where nothing else exists.
const fs::path& inputFile()
{
    static const fs::path path = [] {
        const fs::path dir = fs::temp_directory_path() / ("lfd_gltf_fuzz_" + std::to_string(::getpid()));
        fs::create_directories(dir);
        return dir / "input.gltf";
    }();
    return path;
}

void bakeToStatistics(const fs::path& file)
{
    using namespace lfd::bake;
    const Log quiet;
    ImportedScene imported = importGltf(file, quiet);
    lfd::Scene& scene = imported.scene;
    scene.bounds = computeBounds(scene);
    const lfd::DisplayProfile profile = lfd::prototypeDisplayProfile();
    const lfd::Framing framing = lfd::fitSceneToDisplay(profile, scene.bounds, 1.0);
    const double viewPixelWorld = lfd::minViewPixelWorld(profile, framing);
    tessellateScene(scene, 100.0 * viewPixelWorld, quiet);
    // Images are not decoded here (texture_bake has its own tests): every texture is
    // taken as 256x256 so that the texel statistics run.
    for (lfd::Texture& texture : scene.textures)
        texture.width = texture.height = 256;
    computeTriangleStats(scene);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const fs::path& file = inputFile();
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try {
        bakeToStatistics(file);
    } catch (const lfd::bake::BakeError&) {
    }
    return 0;
}
