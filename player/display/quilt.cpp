// Quilt layout, assembly and file naming (Looking Glass convention).
#include "quilt.h"

#include "lfd/display_profile.h"
#include "lfd/looking_glass_devices.h"
#include "view_targets.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <regex>
#include <stdexcept>

namespace lfd::player {

QuiltLayout chooseQuiltLayout(uint32_t viewCount, uint32_t viewWidth, uint32_t viewHeight,
                              double targetAspect) {
    if (viewCount == 0 || viewWidth == 0 || viewHeight == 0)
        throw std::invalid_argument("quilt layout: view count and view size must be > 0");
    if (!(targetAspect > 0.0) || !std::isfinite(targetAspect))
        throw std::invalid_argument("quilt layout: target aspect must be a positive number");

    QuiltLayout best;
    double bestCost = std::numeric_limits<double>::infinity();
    uint32_t bestEmpty = 0;
    for (uint32_t cols = 1; cols <= viewCount; ++cols) {
        const uint32_t rows = (viewCount + cols - 1) / cols;
        const uint32_t empty = cols * rows - viewCount;
        const double aspect =
            (double(cols) * viewWidth) / (double(rows) * viewHeight);
        const double cost = std::abs(std::log(aspect / targetAspect));
        // note: compare with a tolerance so exact ties (equal aspects) fall to the
        // tie-breakers instead of to rounding noise.
        const bool better = cost < bestCost - 1e-12 ||
                            (std::abs(cost - bestCost) <= 1e-12 && empty < bestEmpty);
        if (better) {
            best = QuiltLayout{cols, rows, viewWidth, viewHeight};
            bestCost = cost;
            bestEmpty = empty;
        }
    }
    return best;
}

QuiltLayout chooseQuiltLayout(const DisplayProfile& profile) {
    if (profile.panelHeight == 0)
        throw std::invalid_argument("quilt layout: profile has no panel height");
    QuiltLayout layout = chooseQuiltLayout(profile.viewCount, profile.viewWidth, profile.viewHeight,
                                           double(profile.panelWidth) / double(profile.panelHeight));
    const auto standard = standardQuiltFor(profile.panelWidth, profile.panelHeight, profile.screenWidthMm);
    // The device's quilt only when it holds these views unscaled: other view counts or
    // sizes (--views, --view-size) would leave tiles empty or cut.
    if (standard && standard->tileWidth() == profile.viewWidth && standard->tileHeight() == profile.viewHeight &&
        standard->cols * standard->rows >= profile.viewCount)
        layout = QuiltLayout{standard->cols, standard->rows, profile.viewWidth, profile.viewHeight,
                             standard->width, standard->height};
    if (profile.screenWidthMm > 0.0 && profile.screenHeightMm > 0.0)
        layout.displayAspect = profile.screenWidthMm / profile.screenHeightMm;
    return layout;
}

QuiltLayout overrideQuiltLayout(QuiltLayout layout, uint32_t viewCount, uint32_t cols, uint32_t rows, double aspect)
{
    if (cols == 0 || rows == 0 || uint64_t(cols) * rows < viewCount)
        throw std::invalid_argument("quilt layout " + std::to_string(cols) + "x" + std::to_string(rows) +
                                    " has fewer tiles than the " + std::to_string(viewCount) + " views");
    layout.cols = cols;
    layout.rows = rows;
    layout.totalWidth = layout.totalHeight = 0;
    if (aspect > 0.0)
        layout.displayAspect = aspect;
    return layout;
}

std::vector<uint8_t> assembleQuilt(const QuiltLayout& layout,
                                   const std::vector<std::vector<uint8_t>>& views) {
    const size_t tileBytes = size_t(layout.tileWidth) * layout.tileHeight * 4;
    if (views.size() > size_t(layout.cols) * layout.rows)
        throw std::invalid_argument("quilt: " + std::to_string(views.size()) +
                                    " views do not fit " + std::to_string(layout.cols) + "x" +
                                    std::to_string(layout.rows) + " tiles");
    const uint32_t W = layout.width(), H = layout.height();
    std::vector<uint8_t> quilt(size_t(W) * H * 4, 0);
    for (size_t i = 0; i < quilt.size(); i += 4)
        quilt[i + 3] = 255; // empty tiles: opaque black

    for (size_t v = 0; v < views.size(); ++v) {
        if (views[v].size() != tileBytes)
            throw std::invalid_argument("quilt: view " + std::to_string(v) + " has " +
                                        std::to_string(views[v].size()) + " bytes, expected " +
                                        std::to_string(tileBytes));
        // View v sits in tile column v % cols, tile row v / cols counted from the bottom;
        // in image order (row 0 = top) that tile row starts at (rows - 1 - v / cols) * h.
        const uint32_t tileX = uint32_t(v % layout.cols);
        const uint32_t tileYFromBottom = uint32_t(v / layout.cols);
        const uint32_t x0 = tileX * layout.tileWidth;
        const uint32_t y0 = H - (tileYFromBottom + 1) * layout.tileHeight;
        for (uint32_t y = 0; y < layout.tileHeight; ++y) {
            const uint8_t* src = &views[v][size_t(y) * layout.tileWidth * 4];
            uint8_t* dst = &quilt[(size_t(y0 + y) * W + x0) * 4];
            std::copy(src, src + size_t(layout.tileWidth) * 4, dst);
        }
    }
    return quilt;
}

std::vector<uint8_t> assembleQuilt(const QuiltLayout& layout, const ViewTargets& views) {
    if (views.width() != layout.tileWidth || views.height() != layout.tileHeight)
        throw std::invalid_argument("quilt: view targets are " + std::to_string(views.width()) +
                                    "x" + std::to_string(views.height()) +
                                    ", layout tiles are " + std::to_string(layout.tileWidth) +
                                    "x" + std::to_string(layout.tileHeight));
    std::vector<std::vector<uint8_t>> images;
    images.reserve(views.viewCount());
    for (uint32_t v = 0; v < views.viewCount(); ++v)
        images.push_back(views.readView(v));
    return assembleQuilt(layout, images);
}

std::string quiltSuffix(uint32_t cols, uint32_t rows, double aspect) {
    char number[64];
    std::snprintf(number, sizeof(number), "%.2f", aspect);
    std::string a = number;
    if (a.find('.') != std::string::npos) {
        while (a.back() == '0')
            a.pop_back();
        if (a.back() == '.')
            a.pop_back();
    }
    return "_qs" + std::to_string(cols) + "x" + std::to_string(rows) + "a" + a;
}

namespace {

const std::regex& existingSuffix() {
    static const std::regex suffix(R"(_qs\d+x\d+a\d+(\.\d+)?$)");
    return suffix;
}

// The requested name without extension and without a _qs suffix, and its extension
// (".png" when it has none; "q_qs8x6a1.33" has none: ".33" belongs to the suffix).
std::pair<std::string, std::string> baseAndExtension(const std::filesystem::path& requested) {
    const std::string filename = requested.filename().string();
    std::smatch m;
    if (std::regex_search(filename, m, existingSuffix()))
        return {m.prefix().str(), ".png"};
    std::string extension = requested.extension().string();
    if (extension.empty())
        extension = ".png";
    std::string stem = requested.stem().string();
    if (std::regex_search(stem, m, existingSuffix()))
        stem = m.prefix().str();
    return {stem, extension};
}

// printf patterns (ffmpeg's image2 input) read "%%" as one '%'.
std::string escapePercent(const std::string& text) {
    std::string escaped;
    for (const char c : text)
        escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return escaped;
}

std::string frameNumber(uint32_t frame) {
    char number[16];
    std::snprintf(number, sizeof(number), "_%04u", frame);
    return number;
}

} // namespace

std::filesystem::path quiltFileName(const std::filesystem::path& requested, const QuiltLayout& layout) {
    return quiltFileName(requested, layout.cols, layout.rows, layout.nameAspect());
}

std::filesystem::path quiltSequenceFileName(const std::filesystem::path& requested, const QuiltLayout& layout,
                                            uint32_t frame) {
    const auto [base, extension] = baseAndExtension(requested);
    return requested.parent_path() /
           (base + frameNumber(frame) + quiltSuffix(layout.cols, layout.rows, layout.nameAspect()) + extension);
}

std::filesystem::path quiltSequencePattern(const std::filesystem::path& requested, const QuiltLayout& layout) {
    const auto [base, extension] = baseAndExtension(requested);
    const std::string name =
        escapePercent(base) + "_%04d" + quiltSuffix(layout.cols, layout.rows, layout.nameAspect()) + escapePercent(extension);
    return std::filesystem::path(escapePercent(requested.parent_path().string())) / name;
}

std::filesystem::path quiltFileName(const std::filesystem::path& requested, uint32_t cols,
                                    uint32_t rows, double aspect) {
    const std::regex& suffix = existingSuffix();
    // "view_qs8x6a1.33" has no extension: ".33" belongs to the suffix.
    const std::string filename = requested.filename().string();
    if (std::regex_search(filename, suffix))
        return requested.parent_path() / (filename + ".png");
    std::string extension = requested.extension().string();
    if (extension.empty())
        extension = ".png";
    const std::string stem = requested.stem().string();
    if (std::regex_search(stem, suffix))
        return requested.parent_path() / (stem + extension);
    return requested.parent_path() / (stem + quiltSuffix(cols, rows, aspect) + extension);
}

} // namespace lfd::player
