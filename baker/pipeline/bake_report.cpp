// Formatting of the bake report and the --inspect summary.
#include "bake_report.h"

#include "lfd/pack_layout.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace lfd::bake {
namespace {

std::string bytes(uint64_t n)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(n >= (1u << 20) ? 1 : 0);
    if (n >= (uint64_t(1) << 30))
        s << double(n) / double(uint64_t(1) << 30) << " GiB";
    else if (n >= (1u << 20))
        s << double(n) / double(1u << 20) << " MiB";
    else if (n >= 1024)
        s << double(n) / 1024.0 << " KiB";
    else
        s << n << " B";
    return s.str();
}

void printSections(std::ostream& out, const PackInfo& info)
{
    out << "  sections (format v" << info.formatVersion << ", " << bytes(info.fileSize) << "):\n";
    for (const PackSectionInfo& s : info.sections)
        out << "    " << s.tag << "  v" << s.version << "  " << std::setw(10) << s.count << " items  "
            << std::setw(10) << bytes(s.size) << (s.encoding == pack::kEncodingZstd ? "  zstd" : "") << "\n";
}

// "1 directional, 2 point" for the counts that are not zero.
std::string countList(std::initializer_list<std::pair<size_t, const char*>> counts)
{
    std::string out;
    for (const auto& [n, what] : counts)
        if (n > 0)
            out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    return out;
}

// Most per-mesh simplification lines printed; the rest are counted in one line.
constexpr size_t kMeshLines = 20;

// Issue 40: triangles in and out and the largest error per mesh, in view pixels.
void printSimplification(std::ostream& out, const SimplificationStats& s)
{
    if (!(s.boundPx > 0.0)) {
        out << "  simplification: off (--simplify 0)\n";
        return;
    }
    const auto precision = out.precision();
    out << std::setprecision(3);
    out << "  simplification (bound " << s.boundPx << " view px): " << s.trianglesIn << " -> " << s.trianglesOut
        << " triangles, " << s.verticesIn << " -> " << s.verticesOut << " vertices, largest error " << s.maxErrorPx
        << " view px, " << s.lockedSeamVertices << " seam vertices kept\n";
    size_t printed = 0, rest = 0;
    for (const SimplifiedMesh& m : s.meshes) {
        if (m.leftWhole.empty() && m.trianglesOut == m.trianglesIn)
            continue;
        if (printed == kMeshLines) {
            ++rest;
            continue;
        }
        ++printed;
        out << "    mesh '" << m.name << "': ";
        if (!m.leftWhole.empty())
            out << m.trianglesIn << " triangles, " << m.leftWhole << "\n";
        else
            out << m.trianglesIn << " -> " << m.trianglesOut << " triangles, largest error " << m.maxErrorPx
                << " view px\n";
    }
    if (rest > 0)
        out << "    ... and " << rest << " more meshes\n";
    out << std::setprecision(int(precision));
}

} // namespace

std::vector<std::string> materialAndLightLines(const Scene& scene)
{
    std::vector<std::string> lines;
    size_t byType[3] = {};
    for (const Light& l : scene.lights)
        ++byType[std::min<size_t>(size_t(l.type), 2)];
    if (!scene.lights.empty())
        lines.push_back("lights: " + std::to_string(scene.lights.size()) + " (" +
                        countList({{byType[0], "directional"}, {byType[1], "point"}, {byType[2], "spot"}}) +
                        "; KHR_lights_punctual)");
    size_t unlit = 0, transformed = 0;
    for (const Material& m : scene.materials) {
        unlit += m.unlit ? 1 : 0;
        transformed += std::any_of(std::begin(m.textureTransforms), std::end(m.textureTransforms),
                                   [](const TextureTransform& t) { return !t.identity(); })
                           ? 1
                           : 0;
    }
    if (unlit + transformed > 0)
        lines.push_back("materials: " + countList({{unlit, "unlit (KHR_materials_unlit)"},
                                                  {transformed, "with texture transforms (KHR_texture_transform)"}}));
    return lines;
}

size_t peakResidentBytes()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0)
            return size_t(std::stoull(line.substr(6))) * 1024; // reported in kB
    return 0;
}

void printBakeReport(std::ostream& out, const std::filesystem::path& pack, const BakeReport& r)
{
    out << std::fixed << std::setprecision(1);
    out << "bake report: " << pack.string() << "\n";
    out << "  triangles: " << r.trianglesIn << " in, " << r.trianglesOut << " out ("
        << r.tessellation.trianglesSplit << " oversized split), " << r.vertices << " vertices\n";
    printSimplification(out, r.simplification);
    if (r.tessellation.trianglesSplit > 0)
        out << "  new points: OpenSubdiv bilinear surface of " << r.tessellation.surfaceMeshes
            << " meshes (refused: " << r.tessellation.surfaceMeshesRefused
            << "), split triangles placed by barycentric weights instead: " << r.tessellation.surfaceFallbacks
            << "\n";
    for (const std::string& line : r.extensionLines)
        out << "  " << line << "\n";
    out << "  max edge: " << r.maxEdgePxBefore << " view px before, " << r.maxEdgePxAfter << " after\n";
    out << "  mean edge after: " << r.meanEdgePxAfter << " view px (" << r.meanPieceEdgePx
        << " over the pieces of split triangles)\n";
    for (const TextureReport& t : r.textures) {
        out << "  texture " << t.name << (t.srgb ? " (sRGB)" : " (linear)") << ": " << t.source.x << "x"
            << t.source.y;
        if (t.stored != t.source)
            out << " reduced to " << t.stored.x << "x" << t.stored.y;
        out << ", " << textureFormatName(t.format) << " " << bytes(t.bytes);
        if (std::isfinite(t.psnr))
            out << ", PSNR " << std::setprecision(1) << t.psnr << " dB";
        out << "\n";
    }
    printSections(out, r.pack);
    out << "  time:";
    double total = 0.0;
    for (const auto& [name, seconds] : r.stageSeconds) {
        out << " " << name << " " << std::setprecision(3) << seconds << " s,";
        total += seconds;
    }
    out << " total " << total << " s (" << r.threads << (r.threads == 1 ? " thread" : " threads") << ")\n";
    out << "  peak memory: " << bytes(r.peakRssBytes) << "\n";
    if (r.warnings)
        out << "  warnings: " << r.warnings << " (see above)\n";
}

void printInspectReport(std::ostream& out, const std::filesystem::path& pack, const PackInfo& info,
                        const Scene& scene)
{
    size_t textured = 0;
    for (const TriangleStats& s : scene.triangleStats)
        textured += (s.flags & kTriangleTextured) ? 1 : 0;
    out << "pack: " << pack.string() << " (verified)\n";
    out << "  baked from " << scene.settings.sourceFile << " by lfd-bake " << scene.settings.bakerVersion
        << " for '" << scene.settings.displayProfile << "' (" << scene.settings.viewCount << " views of "
        << scene.settings.viewWidth << "x" << scene.settings.viewHeight << "), max edge "
        << scene.settings.maxEdgePx << " px\n";
    out << "  " << scene.triangleCount() << " triangles (" << textured << " textured), " << scene.vertices.size()
        << " vertices, streams:" << ((scene.vertices.mask() & kStreamNormal) ? " normal" : "")
        << ((scene.vertices.mask() & kStreamTangent) ? " tangent" : "")
        << ((scene.vertices.mask() & kStreamUv) ? " uv" : "") << "\n";
    out << "  " << scene.meshes.size() << " meshes, " << scene.primitives.size() << " primitives, "
        << scene.materials.size() << " materials, " << scene.textures.size() << " textures, " << scene.nodes.size()
        << " nodes, " << scene.animations.size() << " animations\n";
    for (const std::string& line : materialAndLightLines(scene))
        out << "  " << line << "\n";
    out << std::setprecision(4) << "  bounds: min (" << scene.bounds.min.x << ", " << scene.bounds.min.y << ", "
        << scene.bounds.min.z << ") max (" << scene.bounds.max.x << ", " << scene.bounds.max.y << ", "
        << scene.bounds.max.z << ") radius " << scene.bounds.radius << "\n";
    for (const Texture& t : scene.textures)
        out << "  texture " << t.name << ": " << t.width << "x" << t.height << " " << textureFormatName(t.format)
            << ", " << t.mips.size() << " levels" << (t.srgb ? ", sRGB" : "") << "\n";
    printSections(out, info);
}

} // namespace lfd::bake
