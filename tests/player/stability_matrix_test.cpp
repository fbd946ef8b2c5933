// Stability where methods fail, measured against the gold standard (issue 8): every case
// is rendered by every method (mvr, mvr-layered, lfdpr, lfdpr-paper) and by gstd, and each
// method's views are compared with gstd's: mean RMSE over the views, FLIP of the centre
// view, holes (pixels gstd covers well inside a surface that the method leaves as
// background) and extra coverage (the reverse), with the point count and wall time.
// Cases: huge quad, sliver fan, grazing quad, edge-on quad, degenerate triangles, 96 views,
// the point-buffer limit (lfdpr with a tiny cap), and the three added here: a 16K texture
// minified onto a small object, 128 views over a wide (100 degree) cone, and geometry
// crossing the near plane.
//
// As a CI test (small sizes: 2048^2 texture, 12 views of 96x72) it checks the invariants:
// nothing throws or raises a GL error, every figure is finite, and holes stay within the
// bounds stated at kHoleBound. With LFD_STABILITY_DOC=FILE it writes the results table as
// Markdown (docs/stability.md; `bash scripts/stability-doc.sh` regenerates it at the
// documented sizes: 16384^2 texture, 16 views of 160x120, 128 views of 96x72).
#include "gl_test_support.h"
#include "test_scenes.h"

#include "gpu_scene.h"
#include "gpu_timer.h"
#include "image_metrics.h"
#include "image_metrics.h"
#include "frame_uniforms.h"
#include "renderer_registry.h"
#include "view_targets.h"

#include "lfd/framing.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace lfd::test {
namespace {

using metrics::Image;

// Holes against gstd inside surfaces, fraction of gstd's interior pixels (all 8
// neighbours covered). gstd covers a pixel where any of its sub-views at 4x resolution see
// the surface (4 per view interval, spread across it), every other method where the one
// view's pixel centre is covered, so the two differ along silhouettes of geometry that
// moves across a view interval (near and edge-on geometry most); measured at the CI sizes:
// 0-3.2% (edge-on), identical for all four methods in every case but the point limit. So
// the bound is 4% against gstd, and a point method may leave at most 0.5% more holes than
// mvr does (the method's own holes).
constexpr double kHoleBound = 0.04;
constexpr double kHolesOverMvr = 0.005;

bool envSet(const char* name)
{
    const char* v = std::getenv(name);
    return v && *v;
}

Material flat(glm::vec3 colour, int32_t texture = kNone)
{
    Material m;
    m.baseColorFactor = glm::vec4(colour, 1.0f);
    m.baseColorTexture = texture;
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    m.doubleSided = true;
    return m;
}

// A quad with corners c + (+-u) + (+-v), normal u x v, uvs 0..uvScale.
void addQuad(Scene& s, glm::vec3 c, glm::vec3 u, glm::vec3 v, int32_t material, float uvScale = 1.0f)
{
    const uint32_t base = uint32_t(s.vertices.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& k : corners) {
        s.vertices.positions.push_back(c + k.x * u + k.y * v);
        s.vertices.normals.push_back(n);
        s.vertices.uvs.push_back(uvScale * (0.5f * k + 0.5f));
        s.vertices.tangents.push_back(glm::vec4(glm::normalize(u), 1.0f));
    }
    addNode(s, addMesh(s, {base, base + 1, base + 2, base, base + 2, base + 3}, material), glm::vec3(0.0f),
            glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
}

Scene finish(Scene s)
{
    finishScene(s);
    s.bounds = unitBounds(); // fixed framing: one unit = 97.15 display mm on the prototype
    return s;
}

Scene hugeQuad()
{
    Scene s;
    s.textures.push_back(checkerTexture(256, 16, {230, 200, 60, 255}, {40, 60, 160, 255}, true));
    s.materials = {flat(glm::vec3(1.0f), 0)};
    addQuad(s, {0, 0, -0.2f}, {6, 0, 0}, {0, 6, 0}, 0, 12.0f); // two triangles far beyond every view
    return finish(s);
}

Scene sliverFan()
{
    Scene s;
    s.materials = {flat({0.8f, 0.3f, 0.2f}), flat({0.2f, 0.4f, 0.8f})};
    // 1024 triangles around a centre: each spans 0.35 degrees, under a view pixel wide over
    // most of its length.
    for (int m = 0; m < 2; ++m) {
        const uint32_t centre = uint32_t(s.vertices.positions.size());
        s.vertices.positions.push_back({0, 0, 0});
        s.vertices.normals.push_back({0, 0, 1});
        std::vector<uint32_t> idx;
        const int n = 1024;
        for (int i = 0; i <= n / 2; ++i) {
            const float a = 3.14159265f * (float(m) + float(i) / float(n / 2));
            s.vertices.positions.push_back({0.9f * std::cos(a), 0.9f * std::sin(a), 0});
            s.vertices.normals.push_back({0, 0, 1});
            if (i > 0)
                idx.insert(idx.end(), {centre, centre + uint32_t(i), centre + uint32_t(i) + 1});
        }
        addNode(s, addMesh(s, idx, m), glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    }
    return finish(s);
}

Scene grazingQuad()
{
    Scene s;
    s.textures.push_back(checkerTexture(256, 8, {230, 200, 60, 255}, {40, 60, 160, 255}, true));
    s.materials = {flat(glm::vec3(1.0f), 0)};
    const float a = glm::radians(88.0f); // 88 degrees from facing the cameras
    addQuad(s, {0, 0, 0}, {0.9f, 0, 0}, glm::vec3(0, std::cos(a), -std::sin(a)) * 0.9f, 0, 4.0f);
    return finish(s);
}

Scene edgeOnQuad()
{
    Scene s;
    s.materials = {flat({0.9f, 0.9f, 0.2f}), flat({0.3f, 0.6f, 0.9f})};
    addQuad(s, {0, 0, 0}, {0.9f, 0, 0}, {0, 0, 0.9f}, 0);      // the plane y = 0 holds the camera line
    addQuad(s, {0, 0, -0.8f}, {0.5f, 0, 0}, {0, 0.5f, 0}, 1); // something to see behind it
    return finish(s);
}

Scene degenerate()
{
    Scene s = cubeAndSphereScene();
    const uint32_t b = uint32_t(s.vertices.positions.size());
    for (const glm::vec3& p : {glm::vec3(0.1f, 0.1f, 0.6f), glm::vec3(0.1f, 0.1f, 0.6f), glm::vec3(0.3f, 0.2f, 0.6f),
                               glm::vec3(-0.5f, 0.4f, 0.6f), glm::vec3(0.5f, 0.4f, 0.6f), glm::vec3(0.0f, 0.4f, 0.6f)}) {
        s.vertices.positions.push_back(p);
        s.vertices.normals.push_back({0, 0, 1});
        s.vertices.tangents.push_back({1, 0, 0, 1});
        s.vertices.uvs.push_back({0.5f, 0.5f}); // collapsed uvs
    }
    // A repeated vertex, a collinear triple and a point triangle.
    addNode(s, addMesh(s, {b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 2, b + 2, b + 2}, 0), glm::vec3(0.0f),
            glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    finishScene(s);
    return s;
}

Scene bigTextureSmallObject(uint32_t size)
{
    // One texel squares: every view pixel covers hundreds of texels (minification far past
    // the finest mip); the correct result is the checker's mean colour.
    Scene s;
    s.textures.push_back(checkerTexture(size, 1, {255, 255, 255, 255}, {0, 0, 0, 255}, true));
    s.materials = {flat(glm::vec3(1.0f), 0)};
    addQuad(s, {0, 0, 0}, {0.25f, 0, 0}, {0, 0.25f, 0}, 0);
    return finish(s);
}

Scene nearPlaneCrossing()
{
    // A textured plank from behind the scene to z = +4 units (the near plane is at about
    // z = +1.4, the cameras at z = +6.2): everything in front of the near plane is clipped.
    Scene s;
    s.textures.push_back(checkerTexture(256, 16, {230, 200, 60, 255}, {40, 60, 160, 255}, true));
    s.materials = {flat(glm::vec3(1.0f), 0), flat({0.8f, 0.2f, 0.2f})};
    addQuad(s, {0, -0.4f, 1.5f}, {0.3f, 0, 0}, {0, 0, 2.5f}, 0, 8.0f);
    addQuad(s, {0, 0.2f, -0.5f}, {0.4f, 0, 0}, {0, 0.4f, 0}, 1);
    return finish(s);
}

struct Case {
    std::string name, description;
    Scene scene;
    DisplayProfile profile;
    player::RendererOptions options; // lfdpr's point cap for the buffer-limit case
};

std::vector<Case> cases(bool full)
{
    const DisplayProfile base = prototypeDisplayProfile();
    const DisplayProfile small = withViews(base, full ? 16 : 12, full ? 160 : 96, full ? 120 : 72);
    DisplayProfile many = withViews(base, 96, full ? 96 : 64, full ? 72 : 48);
    DisplayProfile wide = withViews(base, 128, full ? 96 : 64, full ? 72 : 48);
    wide.viewConeDeg = 100.0;
    player::RendererOptions capped;
    capped.lfdpr.initialPointCapacity = 2048;
    capped.lfdpr.maxPointCapacity = 4096;
    const uint32_t texture = full ? 16384u : 2048u;
    std::vector<Case> out;
    out.push_back({"huge", "one quad of two triangles far larger than every view", hugeQuad(), small, {}});
    out.push_back({"sliver", "a fan of 1024 slivers, each under a view pixel wide", sliverFan(), small, {}});
    out.push_back({"grazing", "a checker quad at 88 degrees to the cameras", grazingQuad(), small, {}});
    out.push_back({"edge-on", "a quad in the plane of the camera line (edge-on to every view)", edgeOnQuad(), small, {}});
    out.push_back({"degenerate", "repeated-vertex, collinear and point triangles with collapsed uvs",
                   degenerate(), small, {}});
    out.push_back({"views-96", "the cube-and-sphere scene at 96 views", cubeAndSphereScene(), many, {}});
    out.push_back({"point-limit", "lfdpr capped at 4096 points (the others as usual)", cubeAndSphereScene(), small,
                   capped});
    out.push_back({"texture-" + std::to_string(texture / 1024) + "k",
                   "a " + std::to_string(texture) + "^2 one-texel checker minified onto a 0.5-unit quad",
                   bigTextureSmallObject(texture), small, {}});
    out.push_back({"views-128-wide", "128 views over a 100 degree cone", cubeAndSphereScene(), wide, {}});
    out.push_back({"near-plane", "a plank crossing the near plane towards the cameras", nearPlaneCrossing(), small,
                   {}});
    return out;
}

struct Result {
    double viewsRmse = 0.0, centreFlip = 0.0, holes = 0.0, extra = 0.0, points = -1.0, ms = 0.0;
    bool finite = true;
    std::string error;
};

std::vector<Image> render(const std::string& name, const Case& c, const player::RendererOptions& options,
                          double& ms, double& points)
{
    player::GpuScene gpu(c.scene);
    const Framing framing = fitSceneToDisplay(c.profile, c.scene.bounds);
    const player::FrameSetup frame = player::makeFrameSetup(c.profile, framing, 0.0, 0.0);
    player::ViewTargets targets(c.profile.viewCount, c.profile.viewWidth, c.profile.viewHeight);
    auto renderer = player::createRenderer(name, options);
    player::GpuTimer timer;
    const auto start = std::chrono::steady_clock::now();
    renderer->render(gpu, frame, targets, timer);
    timer.finish();
    std::vector<Image> views;
    for (uint32_t i = 0; i < c.profile.viewCount; ++i)
        views.push_back({c.profile.viewWidth, c.profile.viewHeight, 4, targets.readView(i)});
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (const auto& [key, value] : renderer->extraStats())
        if (key == "points")
            points = value;
    if (const GLenum e = glGetError(); e != GL_NO_ERROR)
        throw std::runtime_error(name + ": GL error " + std::to_string(e));
    return views;
}

// Holes and extra coverage against the reference, over pixels well inside (8 neighbours
// agree) the reference's covered or background area.
void coverage(const std::vector<Image>& test, const std::vector<Image>& ref, double& holes, double& extra)
{
    const auto bg = [](const Image& im, uint32_t x, uint32_t y) {
        const uint8_t* p = &im.pixels[(size_t(y) * im.width + x) * 4];
        const int b = int(std::lround(player::kBackground[0] * 255.0)); // cleared as is (not encoded)
        return std::abs(p[0] - b) <= 2 && std::abs(p[1] - b) <= 2 && std::abs(p[2] - b) <= 2;
    };
    size_t covered = 0, hole = 0, empty = 0, more = 0;
    for (size_t v = 0; v < ref.size(); ++v) {
        const Image& r = ref[v];
        for (uint32_t y = 1; y + 1 < r.height; ++y)
            for (uint32_t x = 1; x + 1 < r.width; ++x) {
                int refCovered = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        refCovered += !bg(r, x + uint32_t(dx), y + uint32_t(dy));
                if (refCovered == 9) {
                    ++covered;
                    hole += bg(test[v], x, y);
                } else if (refCovered == 0) {
                    ++empty;
                    more += !bg(test[v], x, y);
                }
            }
    }
    holes = covered ? double(hole) / double(covered) : 0.0;
    extra = empty ? double(more) / double(empty) : 0.0;
}

class StabilityMatrix : public GlTest {};

TEST_F(StabilityMatrix, EveryMethodAgainstGstd)
{
    const bool full = envSet("LFD_STABILITY_FULL");
    const char* doc = std::getenv("LFD_STABILITY_DOC");
    const std::vector<std::string> methods = {"mvr", "mvr-layered", "lfdpr", "lfdpr-paper"};
    std::ostringstream table;
    table << "| case | what | method | views RMSE | centre FLIP | holes % | extra % | points | ms |\n"
          << "|---|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : cases(full)) {
        double refMs = 0.0, refPoints = -1.0;
        player::RendererOptions refOptions;
        refOptions.gstd.factor = full ? 4 : 2;
        // Views are compared here: the panel model's views (4 sub-views per view interval,
        // Gaussian-reconstructed), rendered without its panel passes, which only make the
        // EIA and would add a pass over the full panel to every case.
        refOptions.gstd.model = player::GstdModel::Views;
        refOptions.gstd.subViews = player::GstdOptions{}.subViewCount();
        const std::vector<Image> ref = render("gstd", c, refOptions, refMs, refPoints);
        double mvrHoles = 0.0; // methods run in order, mvr first
        for (const std::string& m : methods) {
            Result r;
            std::vector<Image> views;
            try {
                views = render(m, c, c.options, r.ms, r.points);
            } catch (const std::exception& e) {
                r.error = e.what();
            }
            EXPECT_TRUE(r.error.empty()) << c.name << " " << m << ": " << r.error;
            if (!r.error.empty())
                continue;
            double mse = 0.0;
            for (size_t v = 0; v < views.size(); ++v)
                mse += std::pow(metrics::rmse(views[v], ref[v]), 2.0);
            r.viewsRmse = std::sqrt(mse / double(views.size()));
            const size_t centre = views.size() / 2;
            const auto rgb = [](const Image& im) {
                return metrics::rgbFromPixels8(im.pixels.data(), int(im.width), int(im.height), int(im.channels));
            };
            r.centreFlip = metrics::flip(rgb(ref[centre]), rgb(views[centre]));
            coverage(views, ref, r.holes, r.extra);
            r.finite = std::isfinite(r.viewsRmse) && std::isfinite(r.centreFlip) && std::isfinite(r.points);
            EXPECT_TRUE(r.finite) << c.name << " " << m;
            if (m == "mvr")
                mvrHoles = r.holes;
            if (!(c.name == "point-limit" && m.rfind("lfdpr", 0) == 0)) {
                EXPECT_LE(r.holes, kHoleBound) << c.name << " " << m;
                EXPECT_LE(r.holes, mvrHoles + kHolesOverMvr) << c.name << " " << m;
            }
            char line[512];
            std::snprintf(line, sizeof(line), "| %s | %s | %s | %.2f | %.4f | %.2f | %.2f | %s | %.0f |\n",
                          c.name.c_str(), c.description.c_str(), m.c_str(), r.viewsRmse, r.centreFlip,
                          100.0 * r.holes, 100.0 * r.extra,
                          r.points >= 0.0 ? std::to_string(int64_t(r.points)).c_str() : "-", r.ms);
            table << line;
            std::printf("[ stability] %s", line);
        }
        std::printf("[ stability] %s: gstd %.0f ms, %u views of %ux%u\n", c.name.c_str(), refMs, c.profile.viewCount,
                    c.profile.viewWidth, c.profile.viewHeight);
    }
    if (doc && *doc) {
        std::ofstream out(std::string(doc) + ".table");
        out << table.str();
    }
}

} // namespace
} // namespace lfd::test
