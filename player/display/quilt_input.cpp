#include "quilt_input.h"

#include "view_targets.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <regex>

namespace lfd::player {

namespace {

namespace fs = std::filesystem;

// How far the views' aspect may be from the screen's before they are padded rather than
// stretched: the names carry two decimals (1.78 for 16:9 is 0.1% off).
constexpr double kAspectTolerance = 0.01;

// "{cols}x{rows}" and an optional "a{aspect}", not followed by more of the same (so
// "_qs8x6a.png" is refused rather than read without its broken aspect).
constexpr const char* kLayoutPattern = R"((\d{1,4})x(\d{1,4})(?:a(\d+(?:\.\d+)?))?(?!a|\d|\.\d))";

// A layout match of kLayoutPattern: cols, rows >= 1, an aspect > 0 when given.
QuiltName layoutOf(const std::smatch& m, const std::string& what)
{
    QuiltName q;
    q.cols = uint32_t(std::stoul(m[1].str()));
    q.rows = uint32_t(std::stoul(m[2].str()));
    const bool hasAspect = m[3].matched;
    q.aspect = hasAspect ? std::stod(m[3].str()) : 0.0;
    if (q.cols == 0 || q.rows == 0 || (hasAspect && (!(q.aspect > 0.0) || !std::isfinite(q.aspect))))
        throw QuiltInputError(what + " needs cols, rows >= 1 and an aspect > 0");
    return q;
}

bool isImageFile(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const std::array<const char*, 8> known = {".png", ".jpg", ".jpeg", ".webp", ".bmp", ".tif", ".tiff", ".exr"};
    return std::find(known.begin(), known.end(), ext) != known.end();
}

bool hasQuiltName(const fs::path& path)
{
    try {
        parseQuiltName(path);
        return true;
    } catch (const QuiltInputError&) {
        return false;
    }
}

// Bilinear RGBA sample of the quilt at pixel-space (x, y) (pixel centres at integers),
// neighbours clamped to [x0, x1] x [y0, y1] so a tile never reads its neighbour.
void sampleBilinear(const metrics::Image& q, double x, double y, int x0, int x1, int y0, int y1, uint8_t out[4])
{
    x = std::clamp(x, double(x0), double(x1));
    y = std::clamp(y, double(y0), double(y1));
    const int xa = int(std::floor(x)), ya = int(std::floor(y));
    const int xb = std::min(xa + 1, x1), yb = std::min(ya + 1, y1);
    const double fx = x - xa, fy = y - ya;
    auto at = [&](int px, int py, int c) { return double(q.pixels[(size_t(py) * q.width + size_t(px)) * 4 + c]); };
    for (int c = 0; c < 4; ++c) {
        const double top = at(xa, ya, c) * (1.0 - fx) + at(xb, ya, c) * fx;
        const double bottom = at(xa, yb, c) * (1.0 - fx) + at(xb, yb, c) * fx;
        out[c] = uint8_t(std::lround(top * (1.0 - fy) + bottom * fy));
    }
}

// Tile (col, rowFromTop) of the quilt as a tileW x tileH view. The view pixel (x, y) centre
// sits at quilt pixel ((col * tileW + x + 0.5) * W / (cols * tileW)) - 0.5, written so it
// is an exact integer when W = cols * tileW.
std::vector<uint8_t> cutTile(const metrics::Image& q, const QuiltName& name, uint32_t col, uint32_t rowFromTop,
                             uint32_t tileW, uint32_t tileH)
{
    const double sx = double(q.width) / (double(name.cols) * tileW);
    const double sy = double(q.height) / (double(name.rows) * tileH);
    // The tile's pixel range in the quilt (its real extent [c W / cols, (c + 1) W / cols)).
    const int x0 = int(std::ceil(double(col) * q.width / name.cols - 0.5));
    const int x1 = std::max(x0, int(std::floor(double(col + 1) * q.width / name.cols - 0.5)));
    const int y0 = int(std::ceil(double(rowFromTop) * q.height / name.rows - 0.5));
    const int y1 = std::max(y0, int(std::floor(double(rowFromTop + 1) * q.height / name.rows - 0.5)));
    std::vector<uint8_t> view(size_t(tileW) * tileH * 4);
    // The usual case, a quilt of whole tiles: bilinear sampling at pixel centres is a copy,
    // done row by row (a Portrait quilt video's 11M pixels per frame).
    if (q.width == name.cols * tileW && q.height == name.rows * tileH) {
        for (uint32_t y = 0; y < tileH; ++y)
            std::copy_n(&q.pixels[(size_t(rowFromTop * tileH + y) * q.width + size_t(col) * tileW) * 4],
                        size_t(tileW) * 4, &view[size_t(y) * tileW * 4]);
        return view;
    }
    for (uint32_t y = 0; y < tileH; ++y)
        for (uint32_t x = 0; x < tileW; ++x) {
            const double qx = (double(col) * tileW + x + 0.5) * sx - 0.5;
            const double qy = (double(rowFromTop) * tileH + y + 0.5) * sy - 0.5;
            sampleBilinear(q, qx, qy, x0, std::min(x1, int(q.width) - 1), y0, std::min(y1, int(q.height) - 1),
                           &view[(size_t(y) * tileW + x) * 4]);
        }
    return view;
}

// Centres a w x h view on an opaque black canvas of cw x ch (cw >= w, ch >= h).
std::vector<uint8_t> padView(const std::vector<uint8_t>& view, uint32_t w, uint32_t h, uint32_t cw, uint32_t ch)
{
    std::vector<uint8_t> canvas(size_t(cw) * ch * 4, 0);
    for (size_t i = 3; i < canvas.size(); i += 4)
        canvas[i] = 255;
    const uint32_t left = (cw - w) / 2, top = (ch - h) / 2;
    for (uint32_t y = 0; y < h; ++y)
        std::copy_n(&view[size_t(y) * w * 4], size_t(w) * 4, &canvas[(size_t(top + y) * cw + left) * 4]);
    return canvas;
}

} // namespace

QuiltName parseQuiltName(const fs::path& file)
{
    static const std::regex suffix("_qs" + std::string(kLayoutPattern));
    const std::string name = file.filename().string();
    std::optional<QuiltName> q;
    for (auto it = std::sregex_iterator(name.begin(), name.end(), suffix); it != std::sregex_iterator(); ++it)
        q = layoutOf(*it, file.string() + ": quilt layout in the name");
    if (!q)
        throw QuiltInputError(file.string() + ": no quilt layout in the name (expected _qs{cols}x{rows}a{aspect}, "
                                              "e.g. scene_qs8x6a0.75.png)");
    return *q;
}

QuiltName parseQuiltLayout(const std::string& text, const std::string& flag)
{
    static const std::regex whole(kLayoutPattern);
    std::smatch m;
    if (!std::regex_match(text, m, whole))
        throw QuiltInputError(flag + ": expected CxR or CxRaASPECT (e.g. 8x6a0.75), got '" + text + "'");
    return layoutOf(m, flag);
}

QuiltName quiltNameOf(const fs::path& file, const std::optional<QuiltName>& given)
{
    if (!given)
        return parseQuiltName(file);
    QuiltName name = *given;
    if (name.aspect == 0.0 && hasQuiltName(file))
        name.aspect = parseQuiltName(file).aspect;
    return name;
}

std::vector<fs::path> listQuiltFiles(const fs::path& fileOrDirectory, bool layoutGiven)
{
    std::error_code ec;
    if (fs::is_regular_file(fileOrDirectory, ec)) {
        if (!layoutGiven)
            parseQuiltName(fileOrDirectory);
        return {fileOrDirectory};
    }
    if (!fs::is_directory(fileOrDirectory, ec))
        throw QuiltInputError(fileOrDirectory.string() + ": no such quilt file or directory");
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fileOrDirectory, ec))
        if (entry.is_regular_file() && isImageFile(entry.path()) && (layoutGiven || hasQuiltName(entry.path())))
            files.push_back(entry.path());
    if (files.empty())
        throw QuiltInputError(fileOrDirectory.string() + ": directory holds no quilt images (names with "
                                                         "_qs{cols}x{rows}a{aspect})");
    std::sort(files.begin(), files.end());
    return files;
}

QuiltViews extractQuiltViews(const metrics::Image& quilt, const QuiltName& name, uint32_t viewCount, double screenAspect)
{
    const uint32_t tiles = name.cols * name.rows;
    const uint32_t count = viewCount == 0 ? tiles : viewCount;
    if (count > tiles)
        throw QuiltInputError(std::to_string(count) + " views asked of a " + std::to_string(name.cols) + "x" +
                              std::to_string(name.rows) + " quilt");
    if (quilt.channels != 4)
        throw QuiltInputError("quilt image has " + std::to_string(quilt.channels) + " channels, expected 4 (RGBA8)");
    const uint32_t tileW = quilt.width / name.cols, tileH = quilt.height / name.rows;
    if (tileW == 0 || tileH == 0)
        throw QuiltInputError(std::to_string(quilt.width) + "x" + std::to_string(quilt.height) +
                              " image is too small for " + std::to_string(name.cols) + "x" +
                              std::to_string(name.rows) + " tiles");

    // Letter- or pillarbox to the screen's aspect when the views were made for another; a
    // name without an aspect is taken as made for this screen (as Looking Glass players do).
    const double aspect = name.aspect > 0.0 ? name.aspect : screenAspect > 0.0 ? screenAspect : double(tileW) / tileH;
    uint32_t outW = tileW, outH = tileH;
    if (screenAspect > 0.0 && std::abs(aspect / screenAspect - 1.0) > kAspectTolerance) {
        if (aspect < screenAspect)
            outW = uint32_t(std::lround(tileW * screenAspect / aspect));
        else
            outH = uint32_t(std::lround(tileH * aspect / screenAspect));
    }

    QuiltViews result;
    result.width = outW;
    result.height = outH;
    result.views.reserve(count);
    for (uint32_t v = 0; v < count; ++v) {
        const uint32_t col = v % name.cols, rowFromTop = name.rows - 1 - v / name.cols;
        std::vector<uint8_t> view = cutTile(quilt, name, col, rowFromTop, tileW, tileH);
        if (outW != tileW || outH != tileH)
            view = padView(view, tileW, tileH, outW, outH);
        result.views.push_back(std::move(view));
    }
    return result;
}

QuiltViews loadQuiltViews(const fs::path& file, const QuiltName& name, uint32_t viewCount, double screenAspect)
{
    try {
        return extractQuiltViews(metrics::readImage(file, 4), name, viewCount, screenAspect);
    } catch (const QuiltInputError& e) {
        throw QuiltInputError(file.string() + ": " + e.what());
    }
}

void uploadViews(ViewTargets& targets, const QuiltViews& views)
{
    if (targets.viewCount() != views.views.size() || targets.width() != views.width ||
        targets.height() != views.height)
        throw std::invalid_argument("uploadViews: view targets do not match the quilt's views");
    // GL rows run bottom-up: flip each view while copying into one layer-ordered buffer.
    const size_t row = size_t(views.width) * 4;
    std::vector<uint8_t> glOrder(row * views.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (size_t v = 0; v < views.views.size(); ++v) {
        for (uint32_t y = 0; y < views.height; ++y)
            std::copy_n(&views.views[v][size_t(views.height - 1 - y) * row], row, &glOrder[size_t(y) * row]);
        glTextureSubImage3D(targets.colorArray(), 0, 0, 0, GLint(v), GLsizei(views.width), GLsizei(views.height), 1,
                            GL_RGBA, GL_UNSIGNED_BYTE, glOrder.data());
    }
}

} // namespace lfd::player
