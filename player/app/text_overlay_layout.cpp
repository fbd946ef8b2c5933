#include "text_overlay_layout.h"

#include <algorithm>
#include <cstring>
#include <string>

// stb_easy_font's functions are static (one copy per file that includes it) and read
// only their own tables; its C casts and unused functions would warn under our flags.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace lfd::player {

namespace {

constexpr int kLineHeight = 12;  // stb_easy_font's line advance, font units
constexpr int kPadding = 4;      // inside the box, font units
constexpr int kMargin = 4;       // between the window's corner and the box, font units
constexpr int kColumnGap = 8;    // between a '\t' line's first part and the column

// stb_easy_font indexes its tables by character - 32 and reads one entry past it, so only
// ' '..'~' are valid; anything else (UTF-8 in a pack name, control characters) shows as '?'.
std::string printable(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
        if (c < ' ' || c > '~')
            c = '?';
    return out;
}

int textWidth(std::string text)
{
    return text.empty() ? 0 : stb_easy_font_width(text.data());
}

struct SplitLine {
    std::string left, right; // right: after the '\t', empty without one
    bool tab = false;
};

SplitLine split(const OverlayLine& line)
{
    const size_t tab = line.text.find('\t');
    if (tab == std::string::npos)
        return {printable(line.text), {}, false};
    return {printable(line.text.substr(0, tab)), printable(line.text.substr(tab + 1)), true};
}

// Appends the segments of `text` at (x, y) font units, scaled, offset to the box's origin.
void addText(std::vector<OverlayRect>& rects, std::string text, int x, int y, int scale, float originX,
             float originY, const std::array<uint8_t, 4>& rgba)
{
    if (text.empty())
        return;
    // stb writes 4 vertices of 16 bytes per segment, about 270 bytes per character.
    std::vector<char> vertices(text.size() * 400 + 64);
    const int quads = stb_easy_font_print(float(x), float(y), text.data(), nullptr, vertices.data(),
                                          int(vertices.size()));
    for (int q = 0; q < quads; ++q) {
        float corner[4][2];
        for (int v = 0; v < 4; ++v)
            std::memcpy(corner[v], &vertices[size_t(q * 4 + v) * 16], sizeof(corner[v]));
        // Vertices 0 and 2 are opposite corners of the axis-aligned segment.
        rects.push_back({originX + corner[0][0] * float(scale), originY + corner[0][1] * float(scale),
                         originX + corner[2][0] * float(scale), originY + corner[2][1] * float(scale), rgba});
    }
}

} // namespace

OverlayLayout layoutOverlay(const std::vector<OverlayLine>& lines, int windowWidth, int windowHeight)
{
    OverlayLayout layout;
    if (lines.empty())
        return layout;
    // Each block of lines (up to a blank line) has its own column: the key help's long
    // key names do not push the readout's values to the right.
    std::vector<SplitLine> parts;
    for (const OverlayLine& line : lines)
        parts.push_back(split(line));
    std::vector<int> column(lines.size(), 0);
    for (size_t start = 0; start < lines.size();) {
        size_t end = start;
        int blockColumn = 0;
        for (; end < lines.size() && !lines[end].text.empty(); ++end)
            if (parts[end].tab)
                blockColumn = std::max(blockColumn, textWidth(parts[end].left) + kColumnGap);
        std::fill(column.begin() + std::ptrdiff_t(start), column.begin() + std::ptrdiff_t(end), blockColumn);
        start = end + 1;
    }
    int width = 0;
    for (size_t i = 0; i < parts.size(); ++i)
        width = std::max(width, parts[i].tab ? column[i] + textWidth(parts[i].right) : textWidth(parts[i].left));
    const int boxW = width + 2 * kPadding, boxH = int(lines.size()) * kLineHeight + 2 * kPadding;

    const int maxScale = windowWidth >= 2400 ? 3 : 2;
    layout.scale = 1;
    for (int s = maxScale; s > 1; --s)
        if ((boxW + 2 * kMargin) * s <= windowWidth && (boxH + 2 * kMargin) * s <= windowHeight) {
            layout.scale = s;
            break;
        }
    const int scale = layout.scale;
    const float x0 = float(kMargin * scale), y0 = float(kMargin * scale);
    layout.box = {x0, y0, x0 + float(boxW * scale), y0 + float(boxH * scale), kOverlayBoxColor};
    layout.rects.push_back(layout.box);
    for (size_t i = 0; i < lines.size(); ++i) {
        const auto& rgba = lines[i].highlight ? kOverlayHighlightColor : kOverlayTextColor;
        const int y = kPadding + int(i) * kLineHeight;
        addText(layout.rects, parts[i].left, kPadding, y, scale, x0, y0, rgba);
        if (parts[i].tab)
            addText(layout.rects, parts[i].right, kPadding + column[i], y, scale, x0, y0, rgba);
    }
    return layout;
}

} // namespace lfd::player
