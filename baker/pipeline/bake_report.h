// The bake report (printed at the end of lfd-bake) and the --inspect summary.
#pragma once

#include "tessellation.h"
#include "simplification.h"
#include "lfd/pack.h"

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace lfd::bake {

struct TextureReport {
    std::string name;
    glm::uvec2 source{0};
    glm::uvec2 stored{0};
    bool srgb = false;
    // Filled once the texture is baked: stored format, bytes of its chain as the GPU
    // takes it, and level 0's PSNR against the RGBA8 level (infinite when uncompressed).
    TextureFormat format = TextureFormat::Rgba8;
    uint64_t bytes = 0;
    double psnr = 0.0;
};

struct BakeReport {
    size_t trianglesIn = 0, trianglesOut = 0, vertices = 0, warnings = 0;
    double maxEdgePxBefore = 0.0, maxEdgePxAfter = 0.0;
    double meanEdgePxAfter = 0.0, meanPieceEdgePx = 0.0;
    SimplificationStats simplification;
    TessellationStats tessellation;
    std::vector<std::string> extensionLines; // materialAndLightLines of the baked scene
    std::vector<TextureReport> textures;
    std::vector<std::pair<std::string, double>> stageSeconds;
    PackInfo pack;
    size_t peakRssBytes = 0;
    unsigned threads = 1;
};

// Peak resident set size of this process (VmHWM), 0 where unavailable.
size_t peakResidentBytes();

// What the scene uses of the glTF extensions the pack keeps, one line each and only when
// present: "lights: 3 (1 directional, 1 point, 1 spot)", "materials: 1 unlit, 2 with
// texture transforms".
std::vector<std::string> materialAndLightLines(const Scene& scene);

void printBakeReport(std::ostream& out, const std::filesystem::path& pack, const BakeReport& report);
void printInspectReport(std::ostream& out, const std::filesystem::path& pack, const PackInfo& info,
                        const Scene& scene);

} // namespace lfd::bake
