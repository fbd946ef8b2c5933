// libFuzzer entry point for glTF ingestion (built with -DLFD_BUILD_FUZZERS=ON, run by
// scripts/fuzz.sh): the input is written to a file (.gltf JSON or .glb, told apart by
// the importer from the "glTF" magic) and taken through the CPU bake stages up to a
// tessellated, statistics-complete scene (gltf_fuzz_pipeline.h).
// Any input must either get there or throw lfd::bake::BakeError: crashes, sanitizer
// reports, other exceptions, timeouts and huge allocations are bugs.
#include "gltf_fuzz_pipeline.h"

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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const fs::path& file = inputFile();
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try {
        lfd::fuzz::bakeToStatistics(file);
    } catch (const lfd::bake::BakeError&) {
    }
    return 0;
}
