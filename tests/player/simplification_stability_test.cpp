// Simplification where it could show (issue 40, "Speed against accuracy": the stability case
// for `lfd-bake --simplify`): the thin part's silhouette and a texture seam, the two places
// a display-aware simplifier is most likely to be seen. One scene, over-dense as a scan is:
// * a thin pole: a closed, smooth ellipsoid 3.5 view pixels across (radius 1.75 px) and
//   ~52 rows long, 48 x 512 segments (edges 0.1-0.25 px), no uvs and smooth normals, so it
//   has neither border nor seam and nothing locks it: only the error bound keeps its silhouette;
// * a textured plane 0.9 x 0.8 units (40 x 48 view pixels) of 0.32-px cells (28K
//   triangles) with a UV seam down its middle (x = 0, the centre column of every view): the vertices
//   on the seam are duplicated, the right half's uvs shifted by half a checker square, so
//   the checker jumps there; simplification must keep the seam vertices and both halves'
//   uvs, or the jump smears into the neighbouring triangles.
// The scene is simplified as lfd-bake does (simplifyScene with the framing's
// minViewPixelWorld, 2 threads) at --simplify 0 (the reference), the default 0.25 and 2,
// and rendered by mvr (8 views of 160 x 120, prototype profile, time 0). Each part is
// rendered alone (the other node dropped) so its region is its own: the pole's region is
// its --simplify 0 coverage grown by 2 px (the silhouette and both sides of it: the pole is
// all silhouette at 3.5 px), the seam's the 6 columns about the seam over the plane's rows.
// The numbers are printed ("[ numbers  ] ..."); LFD_KEEP_TEST_IMAGES=1 keeps the centre
// view of every level as PNGs.
#include "gl_test_support.h"
#include "render_test_util.h"
#include "test_scenes.h"

#include "bake_log.h"
#include "triangle_stats.h"
#include "image_metrics.h"
#include "simplification.h"

#include "lfd/framing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>

namespace lfd::test {
namespace {

using metrics::Image;

class SimplificationStabilityTest : public GlTest {};

DisplayProfile testProfile() { return smallProfile(8, 160, 120); }

// A closed ellipsoid about `centre`: radius r across (x, z), half-length h along y,
// `slices` x `stacks` segments, smooth normals, one vertex per pole, the wrap shared (no
// seam), uvs all 0 (untextured).
std::vector<uint32_t> addPole(Scene& scene, glm::vec3 centre, float r, float h, uint32_t slices, uint32_t stacks)
{
    const float pi = std::numbers::pi_v<float>;
    auto vertexAt = [&](float theta, float phi) {
        const glm::vec3 p(r * std::sin(theta) * std::cos(phi), h * std::cos(theta), -r * std::sin(theta) * std::sin(phi));
        const glm::vec3 n = glm::normalize(glm::vec3(p.x / (r * r), p.y / (h * h), p.z / (r * r)));
        return addVertex(scene, centre + p, n, glm::vec2(0.0f));
    };
    const uint32_t top = vertexAt(0.0f, 0.0f);
    const uint32_t first = uint32_t(scene.vertices.positions.size());
    for (uint32_t j = 1; j < stacks; ++j)
        for (uint32_t i = 0; i < slices; ++i)
            vertexAt(pi * float(j) / float(stacks), 2.0f * pi * float(i) / float(slices));
    const uint32_t bottom = vertexAt(pi, 0.0f);
    auto ring = [&](uint32_t j, uint32_t i) { return first + (j - 1) * slices + i % slices; };
    std::vector<uint32_t> idx;
    for (uint32_t i = 0; i < slices; ++i) {
        idx.insert(idx.end(), {top, ring(1, i), ring(1, i + 1)});
        idx.insert(idx.end(), {bottom, ring(stacks - 1, i + 1), ring(stacks - 1, i)});
    }
    for (uint32_t j = 1; j + 1 < stacks; ++j)
        for (uint32_t i = 0; i < slices; ++i) {
            const uint32_t a = ring(j, i), b = ring(j, i + 1), c = ring(j + 1, i + 1), d = ring(j + 1, i);
            idx.insert(idx.end(), {a, d, c, a, c, b});
        }
    return idx;
}

// A plane facing +z over [x0, x1] x [y0, y1] at z = 0, cells of `cell` units, with a UV
// seam at x = 0: u = x / 0.5 + 1 on the left, the same plus half a checker square (1/16:
// squares of 8 texels in 64) on the right; v = y / 0.5 + 1. The seam's vertices are
// duplicated, one copy per side, at the same positions.
std::vector<uint32_t> addSeamedPlane(Scene& scene, float x0, float x1, float y0, float y1, float cell)
{
    std::vector<uint32_t> idx;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    auto half = [&](float a, float b, float uShift) {
        const uint32_t nx = uint32_t(std::lround((b - a) / cell)), ny = uint32_t(std::lround((y1 - y0) / cell));
        const uint32_t base = uint32_t(scene.vertices.positions.size());
        for (uint32_t j = 0; j <= ny; ++j)
            for (uint32_t i = 0; i <= nx; ++i) {
                const float x = a + (b - a) * float(i) / float(nx), y = y0 + (y1 - y0) * float(j) / float(ny);
                addVertex(scene, glm::vec3(x, y, 0.0f), n, glm::vec2(x / 0.5f + 1.0f + uShift, 1.0f - y / 0.5f));
            }
        for (uint32_t j = 0; j < ny; ++j)
            for (uint32_t i = 0; i < nx; ++i) {
                const uint32_t p = base + j * (nx + 1) + i, q = p + 1, s = p + nx + 1, t = s + 1;
                idx.insert(idx.end(), {p, q, t, p, t, s});
            }
    };
    half(x0, 0.0f, 0.0f);
    half(0.0f, x1, 1.0f / 16.0f);
    return idx;
}

struct Parts {
    Scene scene;
    bake::SimplificationStats stats;
};

// The scene simplified at `errorPx` view pixels as lfd-bake simplifies it; node 0 draws
// the pole, node 1 the plane.
Parts simplifiedScene(const DisplayProfile& profile, double errorPx)
{
    const glm::dvec2 px = pixelUnits(profile);
    Parts parts;
    Scene& scene = parts.scene;
    scene.textures.push_back(checkerTexture(64, 8, {230, 200, 60, 255}, {40, 90, 200, 255}, true));
    Material pole;
    pole.baseColorFactor = glm::vec4(0.85f, 0.85f, 0.8f, 1.0f);
    pole.metallicFactor = 0.0f;
    pole.roughnessFactor = 0.6f;
    Material plane = pole;
    plane.baseColorFactor = glm::vec4(1.0f);
    plane.baseColorTexture = 0;
    scene.materials = {pole, plane};
    addNode(scene, addMesh(scene, addPole(scene, {-0.6f, 0.0f, 0.0f}, float(1.75 * px.x), 0.45f, 48, 512), 0),
            glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    addNode(scene, addMesh(scene, addSeamedPlane(scene, -0.3f, 0.6f, -0.4f, 0.4f, float(0.32 * px.x)), 1),
            glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    const double viewPixelWorld = minViewPixelWorld(profile, fitSceneToDisplay(profile, unitBounds()));
    parts.stats = bake::simplifyScene(scene, errorPx, viewPixelWorld, bake::Log{}, 2);
    bake::computeTriangleStats(scene);
    scene.bounds = unitBounds();
    return parts;
}

// The scene with only node `keep` (the other's mesh stays in the scene, undrawn).
Scene only(const Scene& scene, size_t keep)
{
    Scene s = scene;
    s.nodes = {scene.nodes[keep]};
    return s;
}

std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, uint32_t w, uint32_t h, int radius)
{
    std::vector<uint8_t> out(mask.size(), 0);
    for (int y = 0; y < int(h); ++y)
        for (int x = 0; x < int(w); ++x) {
            if (!mask[size_t(y) * w + size_t(x)])
                continue;
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && u < int(w) && v < int(h))
                        out[size_t(v) * w + size_t(u)] = 1;
                }
        }
    return out;
}

size_t countSet(const std::vector<uint8_t>& m) { return size_t(std::count(m.begin(), m.end(), uint8_t(1))); }

// One level against the --simplify 0 reference, over all views.
struct Measured {
    double poleRmse = 0.0, poleSsim = 1.0; // over the pole's region, mean over the views
    double poleWorstSsim = 1.0;
    double poleCoverage = 1.0; // covered pixels / the reference's
    size_t poleXor = 0;        // pixels covered by one of the two only, all views
    double seamRmse = 0.0, seamSsim = 1.0, seamWorstSsim = 1.0; // the 6 columns about the seam
    double planeRmse = 0.0;                                    // the whole plane
};

Measured measure(const RenderedFrame& pole, const RenderedFrame& pole0, const RenderedFrame& plane,
                 const RenderedFrame& plane0)
{
    Measured m;
    size_t covered = 0, covered0 = 0;
    const size_t n = pole0.views.size();
    for (size_t v = 0; v < n; ++v) {
        const Image& ref = pole0.views[v];
        const std::vector<uint8_t> c0 = coverageMask(ref), c = coverageMask(pole.views[v]);
        covered0 += countSet(c0);
        covered += countSet(c);
        for (size_t i = 0; i < c0.size(); ++i)
            m.poleXor += c0[i] != c[i];
        const std::vector<uint8_t> region = dilate(c0, ref.width, ref.height, 2);
        m.poleRmse += maskedRmse(pole.views[v], ref, region) / double(n);
        const double ssim = ssimOverMaskBox(pole.views[v], ref, region);
        m.poleSsim += (ssim - 1.0) / double(n);
        m.poleWorstSsim = std::min(m.poleWorstSsim, ssim);

        const Image& pref = plane0.views[v];
        const std::vector<uint8_t> p0 = coverageMask(pref);
        std::vector<uint8_t> seam(p0.size(), 0);
        const uint32_t mid = pref.width / 2;
        for (uint32_t y = 0; y < pref.height; ++y)
            for (uint32_t x = mid - 3; x < mid + 3; ++x)
                seam[size_t(y) * pref.width + x] = p0[size_t(y) * pref.width + x];
        m.seamRmse += maskedRmse(plane.views[v], pref, seam) / double(n);
        const double s = ssimOverMaskBox(plane.views[v], pref, seam);
        m.seamSsim += (s - 1.0) / double(n);
        m.seamWorstSsim = std::min(m.seamWorstSsim, s);
        m.planeRmse += maskedRmse(plane.views[v], pref, p0) / double(n);
    }
    m.poleCoverage = covered0 ? double(covered) / double(covered0) : 1.0;
    return m;
}

void keepImages(const std::string& level, const RenderedFrame& pole, const RenderedFrame& plane,
                const RenderedFrame& whole)
{
    if (!std::getenv("LFD_KEEP_TEST_IMAGES"))
        return;
    const std::filesystem::path dir = testOutputDir("simplification_stability_s" + level);
    const size_t v = whole.views.size() / 2;
    metrics::writeImage(dir / "pole.png", pole.views[v]);
    metrics::writeImage(dir / "plane.png", plane.views[v]);
    metrics::writeImage(dir / "scene.png", whole.views[v]);
    std::printf("[ images   ] %s\n", dir.string().c_str());
}

TEST_F(SimplificationStabilityTest, ThinSilhouetteAndTextureSeamHoldAtTheDefault)
{
    const DisplayProfile profile = testProfile();
    const Parts s0 = simplifiedScene(profile, 0.0);
    const RenderedFrame pole0 = renderFrame("mvr", only(s0.scene, 0), profile);
    const RenderedFrame plane0 = renderFrame("mvr", only(s0.scene, 1), profile);
    keepImages("0", pole0, plane0, renderFrame("mvr", s0.scene, profile));
    const size_t poleIn = s0.scene.primitives[0].indexCount / 3, planeIn = s0.scene.primitives[1].indexCount / 3;

    struct Level {
        double px;
        Measured m;
        size_t poleTriangles, planeTriangles;
        double maxErrorPx;
    };
    std::vector<Level> levels;
    for (double px : {0.25, 2.0}) {
        const Parts s = simplifiedScene(profile, px);
        const RenderedFrame pole = renderFrame("mvr", only(s.scene, 0), profile);
        const RenderedFrame plane = renderFrame("mvr", only(s.scene, 1), profile);
        char name[16];
        std::snprintf(name, sizeof name, "%g", px);
        keepImages(name, pole, plane, renderFrame("mvr", s.scene, profile));
        Level l{px, measure(pole, pole0, plane, plane0), s.scene.primitives[0].indexCount / 3,
                s.scene.primitives[1].indexCount / 3, s.stats.maxErrorPx};
        std::printf("[ numbers  ] --simplify %g: pole %zu -> %zu triangles, plane %zu -> %zu, largest error %.3f px; "
                    "pole region RMSE %.2f SSIM %.4f (worst view %.4f), coverage %.3f of level 0, %zu px differ; "
                    "seam RMSE %.2f SSIM %.4f (worst view %.4f); whole plane RMSE %.2f\n",
                    px, poleIn, l.poleTriangles, planeIn, l.planeTriangles, l.maxErrorPx, l.m.poleRmse,
                    l.m.poleSsim, l.m.poleWorstSsim, l.m.poleCoverage, l.m.poleXor, l.m.seamRmse, l.m.seamSsim,
                    l.m.seamWorstSsim, l.m.planeRmse);
        levels.push_back(l);
    }

    // The default simplifies both parts a lot (the point of the stage) ...
    const Level& d = levels[0];
    EXPECT_LT(d.poleTriangles, poleIn / 4);
    EXPECT_LT(d.planeTriangles, planeIn / 20);
    EXPECT_LE(d.maxErrorPx, 0.25 + 1e-9);
    // ... and the silhouette and the seam hold. Measured on llvmpipe (8 views of 160 x 120):
    // pole 49,056 -> 336 triangles, plane 28,476 -> 700, largest error 0.247 px; pole
    // region SSIM 0.9909 (worst view 0.9848), RMSE 11.3, coverage 0.985 of level 0 (20
    // pixels differ over the 8 views); seam SSIM 1.0000, RMSE
    // 0.01 (the whole plane too). Why the pole shrinks at all: the simplified surface uses
    // the input's own vertices, so a convex part can only lose area, by up to the bound
    // per side (0.25 px of 3.5: at most 14%); a pixel flips only where the silhouette
    // crosses its centre. A pole exactly 3 px across (its edges on pixel centres over its
    // middle, the worst case) measured coverage 0.903, SSIM 0.933: the bound holds, the
    // flips are what a 0.25-px shift of an edge lying on pixel centres costs in a
    // single-sample raster. Bounds: coverage >= 0.95, SSIM >= 0.97 (worst view 0.95),
    // between the measured values and the worst case above.
    EXPECT_GE(d.m.poleCoverage, 0.95);
    EXPECT_LE(d.m.poleCoverage, 1.0 + 1e-9); // inscribed: never grows
    EXPECT_GE(d.m.poleSsim, 0.97);
    EXPECT_GE(d.m.poleWorstSsim, 0.95);
    // The seam: its vertices are kept with both sides' uvs and the plane is flat, so the
    // texture is the same to rounding (measured RMSE 0.01); a seam vertex merged across
    // would shift half a checker square over the neighbouring triangles (RMSE tens).
    EXPECT_LE(d.m.seamRmse, 1.0);
    EXPECT_GE(d.m.seamSsim, 0.999);

    // --simplify 2 (recorded, what the user asks for there): the pole becomes a spindle of
    // 32 triangles, largest error 1.87 px: coverage 0.749 of level 0, 327 pixels differ,
    // region SSIM 0.767 (worst view 0.666), RMSE 51: a part 3.5 px across loses a quarter
    // of its pixels, visible. The seam still holds (locked at every bound: RMSE 0.01), and
    // the plane is already at its 700 triangles (its locked border and seam) at 0.25.
    const Level& coarse = levels[1];
    EXPECT_LT(coarse.poleTriangles, d.poleTriangles);
    EXPECT_LT(coarse.m.poleCoverage, d.m.poleCoverage); // the metric sees the coarser bound
    EXPECT_LE(coarse.m.seamRmse, 1.0);
}

} // namespace
} // namespace lfd::test
