#include "rgbd_import.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace lfd::bake {

namespace {

// A depth map as values in [0, 1] (8- and 16-bit maps normalised by OIIO, float maps as
// stored), row 0 = top.
struct DepthMap {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> values;
};

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem)
{
    throw BakeError(file.string() + ": " + problem);
}

std::unique_ptr<OIIO::ImageInput> openImage(const std::filesystem::path& file)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        fail(file, "cannot open: file not found");
    auto input = OIIO::ImageInput::open(file.string());
    if (!input)
        fail(file, "cannot decode: " + OIIO::geterror());
    input->threads(1);
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 1 || spec.height <= 1 || spec.nchannels <= 0)
        fail(file, "cannot use: image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                       " with " + std::to_string(spec.nchannels) + " channels (need at least 2x2)");
    if (size_t(spec.width) * size_t(spec.height) > size_t(1) << 28)
        fail(file, "cannot use: image too large (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) + ")");
    return input;
}

// All of an image's first `channels` channels as floats (1.0 = full scale).
std::vector<float> readFloats(OIIO::ImageInput& input, const std::filesystem::path& file, int channels)
{
    const OIIO::ImageSpec& spec = input.spec();
    std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(channels));
    if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        fail(file, "cannot decode: " + input.geterror());
    return pixels;
}

DepthMap depthFromChannel0(const std::vector<float>& pixels, int stride, uint32_t x0, uint32_t width, uint32_t rowWidth,
                           uint32_t height)
{
    DepthMap map{width, height, std::vector<float>(size_t(width) * height)};
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            map.values[size_t(y) * width + x] = pixels[(size_t(y) * rowWidth + x0 + x) * size_t(stride)];
    return map;
}

// The colour half of a side-by-side image, encoded as an 8-bit PNG in memory so that the
// texture stage reads it like an embedded glTF image.
std::vector<uint8_t> encodeLeftHalf(const std::vector<float>& pixels, int channels, uint32_t width, uint32_t height,
                                    const std::filesystem::path& file)
{
    const uint32_t half = width / 2;
    std::vector<uint8_t> rgb(size_t(half) * height * size_t(channels));
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < half; ++x)
            for (int c = 0; c < channels; ++c) {
                const float v = pixels[(size_t(y) * width + x) * size_t(channels) + size_t(c)];
                rgb[(size_t(y) * half + x) * size_t(channels) + size_t(c)] =
                    uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            }
    std::vector<unsigned char> png;
    OIIO::Filesystem::IOVecOutput proxy(png);
    auto output = OIIO::ImageOutput::create("png");
    OIIO::ImageSpec spec(int(half), int(height), channels, OIIO::TypeDesc::UINT8);
    if (!output || !output->set_ioproxy(&proxy) || !output->open("colour.png", spec) ||
        !output->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !output->close())
        fail(file, "cannot encode the colour half: " + (output ? output->geterror() : OIIO::geterror()));
    return {png.begin(), png.end()};
}

// The depth map and the photo's texture source, from two files or one side-by-side image.
DepthMap loadInputs(const RgbdOptions& o, TextureSource& photo)
{
    photo.srgb = true;
    photo.name = o.color.filename().string();
    if (!o.depth.empty()) {
        auto depthInput = openImage(o.depth);
        const OIIO::ImageSpec spec = depthInput->spec();
        const std::vector<float> pixels = readFloats(*depthInput, o.depth, 1);
        const auto colorInput = openImage(o.color);
        const OIIO::ImageSpec& colour = colorInput->spec();
        const double depthAspect = double(spec.width) / spec.height;
        const double colourAspect = double(colour.width) / colour.height;
        if (std::abs(depthAspect / colourAspect - 1.0) > 0.01)
            fail(o.depth, "aspect " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                              " does not match the colour image's " + std::to_string(colour.width) + "x" +
                              std::to_string(colour.height));
        photo.file = o.color;
        return depthFromChannel0(pixels, 1, 0, uint32_t(spec.width), uint32_t(spec.width), uint32_t(spec.height));
    }
    auto input = openImage(o.color);
    const OIIO::ImageSpec spec = input->spec();
    if (spec.width % 2 != 0)
        fail(o.color, "side-by-side RGBD image has an odd width " + std::to_string(spec.width) +
                          " (colour left, depth right: two equal halves)");
    const int channels = std::min(spec.nchannels, 4);
    const std::vector<float> pixels = readFloats(*input, o.color, channels);
    const auto half = uint32_t(spec.width / 2);
    photo.encoded = encodeLeftHalf(pixels, channels, uint32_t(spec.width), uint32_t(spec.height), o.color);
    photo.mimeType = "image/png";
    photo.name += " (colour half)";
    return depthFromChannel0(pixels, channels, half, half, uint32_t(spec.width), uint32_t(spec.height));
}

// The relief grid: the depth map resampled to a square (2^k + 1)^2 grid - the shape a
// right-triangulated irregular network (RTIN) needs - with at least one grid point per
// depth pixel along each axis (the grid is anisotropic when the image is not square).
struct Grid {
    uint32_t size = 0;                // points per side, 2^k + 1
    std::vector<float> nearness;      // per point, 0 = far .. 1 = near
    std::vector<uint8_t> discontinuous; // a neighbour's nearness differs by more than the threshold
    VertexStreams points;             // positions, normals, uvs per grid point
    size_t index(uint32_t x, uint32_t y) const { return size_t(y) * size + x; }
};

float sampleBilinear(const DepthMap& map, double x, double y)
{
    const auto x0 = uint32_t(std::floor(x)), y0 = uint32_t(std::floor(y));
    const uint32_t x1 = std::min(x0 + 1, map.width - 1), y1 = std::min(y0 + 1, map.height - 1);
    const auto fx = float(x - x0), fy = float(y - y0);
    const auto at = [&](uint32_t px, uint32_t py) { return map.values[size_t(py) * map.width + px]; };
    return (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
}

Grid buildGrid(const DepthMap& map, const RgbdOptions& o, uint32_t size)
{
    Grid g;
    g.size = size;
    const size_t count = size_t(size) * size;
    g.nearness.resize(count);
    g.points.positions.resize(count);
    g.points.uvs.resize(count);
    const double aspect = double(map.width) / map.height;
    const double range = o.depthHigh - o.depthLow;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            // Grid point -> depth-map pixel centres, first to last.
            const double px = double(x) / (size - 1) * (map.width - 1), py = double(y) / (size - 1) * (map.height - 1);
            double t = std::clamp((double(sampleBilinear(map, px, py)) - o.depthLow) / range, 0.0, 1.0);
            if (o.invert)
                t = 1.0 - t;
            const glm::vec2 uv(float((px + 0.5) / map.width), float((py + 0.5) / map.height));
            g.nearness[g.index(x, y)] = float(t);
            g.points.positions[g.index(x, y)] = glm::vec3(float((uv.x - 0.5) * aspect), 0.5f - uv.y, float(o.relief * t));
            g.points.uvs[g.index(x, y)] = uv;
        }
    // Normals of the relief itself (central differences), so a simplified mesh keeps the
    // shading of the full-resolution surface; discontinuities between neighbours.
    g.points.normals.resize(count);
    g.discontinuous.resize(count);
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const uint32_t xl = x > 0 ? x - 1 : 0, xr = std::min(x + 1, size - 1);
            const uint32_t yu = y > 0 ? y - 1 : 0, yd = std::min(y + 1, size - 1);
            const auto p = [&](uint32_t px, uint32_t py) { return g.points.positions[g.index(px, py)]; };
            const glm::vec3 n = glm::cross(p(xr, y) - p(xl, y), p(x, yu) - p(x, yd));
            g.points.normals[g.index(x, y)] = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
            const float t = g.nearness[g.index(x, y)];
            for (const size_t nb : {g.index(xl, y), g.index(xr, y), g.index(x, yu), g.index(x, yd)})
                if (std::abs(g.nearness[nb] - t) > o.edgeThreshold)
                    g.discontinuous[g.index(x, y)] = 1;
        }
    return g;
}

// The RTIN of the grid (Evans, Kirkpatrick & Townsend 2001, "Right-triangulated
// irregular networks"): each right triangle splits at its hypotenuse's midpoint into two.
// errors[m] is the largest height error of any triangle whose split point is m, itself or
// below it; neighbours sharing a hypotenuse share its midpoint, so cutting the hierarchy
// where errors[m] <= tolerance leaves no cracks. Points next to a depth discontinuity
// have infinite error: the mesh reaches pixel size there.
class Rtin {
public:
    explicit Rtin(const Grid& g) : g_(g), errors_(size_t(g.size) * g.size, 0.0f)
    {
        const uint32_t n = g.size - 1;
        computeErrors(0, 0, n, n, n, 0);
        computeErrors(n, n, 0, 0, 0, n);
    }

    // Triangles (grid point indices, counter-clockwise seen from +z) of the coarsest mesh
    // within `tolerance` scene units of the full grid (tolerance < 0: the full grid).
    std::vector<uint32_t> mesh(double tolerance) const
    {
        std::vector<uint32_t> triangles;
        const uint32_t n = g_.size - 1;
        emit(0, 0, n, n, n, 0, float(tolerance), triangles);
        emit(n, n, 0, 0, 0, n, float(tolerance), triangles);
        return triangles;
    }

private:
    // Triangle (a, b, c): c is the right angle, a-b the hypotenuse.
    static bool isLeaf(uint32_t ax, uint32_t ay, uint32_t cx, uint32_t cy)
    {
        return (ax > cx ? ax - cx : cx - ax) + (ay > cy ? ay - cy : cy - ay) <= 1;
    }

    float computeErrors(uint32_t ax, uint32_t ay, uint32_t bx, uint32_t by, uint32_t cx, uint32_t cy)
    {
        if (isLeaf(ax, ay, cx, cy))
            return 0.0f;
        const uint32_t mx = (ax + bx) / 2, my = (ay + by) / 2;
        const size_t m = g_.index(mx, my);
        const float left = computeErrors(cx, cy, ax, ay, mx, my);
        const float right = computeErrors(bx, by, cx, cy, mx, my);
        const float interpolated = 0.5f * (g_.points.positions[g_.index(ax, ay)].z + g_.points.positions[g_.index(bx, by)].z);
        float error = std::abs(interpolated - g_.points.positions[m].z);
        if (g_.discontinuous[m])
            error = std::numeric_limits<float>::infinity();
        errors_[m] = std::max({errors_[m], error, left, right});
        return errors_[m];
    }

    void emit(uint32_t ax, uint32_t ay, uint32_t bx, uint32_t by, uint32_t cx, uint32_t cy, float tolerance,
              std::vector<uint32_t>& out) const
    {
        const uint32_t mx = (ax + bx) / 2, my = (ay + by) / 2;
        if (!isLeaf(ax, ay, cx, cy) && errors_[g_.index(mx, my)] > tolerance) {
            emit(cx, cy, ax, ay, mx, my, tolerance, out);
            emit(bx, by, cx, cy, mx, my, tolerance, out);
            return;
        }
        // The two roots are counter-clockwise seen from +z (scene y is grid y flipped) and
        // a split keeps the orientation, so (a, b, c) is too.
        out.insert(out.end(), {uint32_t(g_.index(ax, ay)), uint32_t(g_.index(bx, by)), uint32_t(g_.index(cx, cy))});
    }

    const Grid& g_;
    std::vector<float> errors_;
};

// Drops the triangles with an edge between neighbouring grid points across a depth
// discontinuity (only pixel-sized triangles have such edges: the error forces the mesh
// down to them there; a large triangle over a smooth slope is never dropped). Returns how
// many.
size_t dropDiscontinuities(const Grid& g, double threshold, std::vector<uint32_t>& triangles)
{
    const auto jumps = [&](uint32_t a, uint32_t b) {
        const uint32_t ax = a % g.size, ay = a / g.size, bx = b % g.size, by = b / g.size;
        const bool neighbours = (ax > bx ? ax - bx : bx - ax) <= 1 && (ay > by ? ay - by : by - ay) <= 1;
        return neighbours && std::abs(g.nearness[a] - g.nearness[b]) > threshold;
    };
    size_t kept = 0;
    for (size_t t = 0; t < triangles.size(); t += 3) {
        const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        if (jumps(a, b) || jumps(b, c) || jumps(c, a))
            continue;
        std::copy_n(triangles.begin() + std::ptrdiff_t(t), 3, triangles.begin() + std::ptrdiff_t(kept));
        kept += 3;
    }
    const size_t dropped = (triangles.size() - kept) / 3;
    triangles.resize(kept);
    return dropped;
}

// The relief as a scene: the grid points the triangles use (renumbered in grid order),
// one mesh, one node, the photo as an emissive texture over a black base colour.
Scene reliefScene(const Grid& g, std::vector<uint32_t> triangles, const std::string& textureName)
{
    Scene scene;
    std::vector<uint32_t> renumber(g.points.positions.size(), UINT32_MAX);
    for (uint32_t p : triangles)
        renumber[p] = 0;
    for (size_t p = 0; p < renumber.size(); ++p)
        if (renumber[p] == 0) {
            renumber[p] = uint32_t(scene.vertices.positions.size());
            scene.vertices.positions.push_back(g.points.positions[p]);
            scene.vertices.normals.push_back(g.points.normals[p]);
            scene.vertices.uvs.push_back(g.points.uvs[p]);
        }
    for (uint32_t& p : triangles)
        p = renumber[p];
    scene.indices = std::move(triangles);

    Material photo;
    photo.name = "rgbd photo";
    photo.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    photo.emissiveFactor = glm::vec3(1.0f);
    photo.metallicFactor = 0.0f;
    photo.roughnessFactor = 1.0f;
    photo.doubleSided = true;
    photo.emissiveTexture = 0;
    scene.materials.push_back(photo);
    Texture texture;
    texture.name = textureName;
    texture.srgb = true;
    scene.textures.push_back(texture);
    scene.primitives.push_back({0, uint32_t(scene.indices.size()), 0});
    scene.meshes.push_back({"rgbd relief", 0, 1});
    Node node;
    node.name = "rgbd relief";
    node.mesh = 0;
    scene.nodes.push_back(node);
    return scene;
}

// Points per grid side: 2^k + 1 covering the depth map's larger side, at most
// kMaxRgbdGridSize.
uint32_t gridSizeFor(const DepthMap& map)
{
    uint32_t cells = 1;
    while (cells + 1 < std::max(map.width, map.height) && cells + 1 < kMaxRgbdGridSize)
        cells *= 2;
    return cells + 1;
}

} // namespace

ImportedScene importRgbd(const RgbdOptions& o, const Log& log)
{
    if (!(o.depthHigh > o.depthLow)) {
        char values[64];
        std::snprintf(values, sizeof(values), "%g %g", o.depthLow, o.depthHigh);
        throw BakeError(std::string("--rgbd-depth-range: the near value must exceed the far one, got ") + values);
    }
    ImportedScene result;
    TextureSource photo;
    const DepthMap map = loadInputs(o, photo);
    const std::filesystem::path& depthFile = o.depth.empty() ? o.color : o.depth;

    const uint32_t size = gridSizeFor(map);
    if (size - 1 < std::max(map.width, map.height) - 1)
        result.warnings.push_back("depth map " + std::to_string(map.width) + "x" + std::to_string(map.height) +
                                  " sampled on a " + std::to_string(size) + "x" + std::to_string(size) +
                                  " grid (the largest the RGB-D import builds)");
    const Grid grid = buildGrid(map, o, size);
    std::vector<uint32_t> triangles = Rtin(grid).mesh(o.flatness > 0.0 ? o.flatness : -1.0);
    const size_t dropped = o.edges == RgbdEdges::Drop ? dropDiscontinuities(grid, o.edgeThreshold, triangles) : 0;
    if (triangles.empty())
        fail(depthFile, "no triangle left: every one spans a depth discontinuity (raise --rgbd-edge-threshold "
                        "or use --rgbd-edges stretch)");
    result.scene = reliefScene(grid, std::move(triangles), photo.name);
    result.textureSources.push_back(photo);
    result.filesRead.push_back(o.color);
    if (!o.depth.empty())
        result.filesRead.push_back(o.depth);
    result.sourceTriangles = result.scene.triangleCount();
    for (const std::string& w : result.warnings)
        log.warn(w);
    const size_t full = size_t(size - 1) * (size - 1) * 2;
    log.info("rgbd: depth " + std::to_string(map.width) + "x" + std::to_string(map.height) + " on a " +
             std::to_string(size) + "x" + std::to_string(size) + " grid: " +
             std::to_string(result.scene.triangleCount()) + " triangles (" + std::to_string(full) +
             " at full resolution; flat areas merged within " + std::to_string(o.flatness) + " image heights, " +
             std::to_string(dropped) + " dropped at depth discontinuities), " +
             std::to_string(result.scene.vertices.size()) + " vertices");
    return result;
}

} // namespace lfd::bake
