// Quilt images (Looking Glass convention, docs/player/lfd-play.md): all N views tiled into one
// image, `cols` x `rows` tiles, view 0 in the bottom-left tile (the leftmost camera), then
// left to right and upwards, so view cols-1 is bottom-right and view cols sits above view 0.
// Tiles past the last view stay black. File names carry the layout as a suffix
// `_qs{cols}x{rows}a{aspect}`, e.g. `_qs8x6a1.78`, so Looking Glass tools read the layout
// from the name. The aspect is the one each view is shown at - the screen's (width mm /
// height mm), which Looking Glass players stretch a tile to - not the tile's pixel aspect:
// the prototype's 480x360 views cover a 16:9 screen, so its quilts are `_qs8x6a1.78`.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lfd {
struct DisplayProfile;
}

namespace lfd::player {

class ViewTargets;

struct QuiltLayout {
    uint32_t cols = 0, rows = 0;
    uint32_t tileWidth = 0, tileHeight = 0; // = the view size
    // A vendor's standard quilt may be a few pixels larger than its tiles (8192 for 9 tiles
    // of 910): the tiles sit from the bottom-left corner, the rest stays black.
    uint32_t totalWidth = 0, totalHeight = 0;
    uint32_t width() const { return std::max(cols * tileWidth, totalWidth); }
    uint32_t height() const { return std::max(rows * tileHeight, totalHeight); }
    double aspect() const { return double(tileWidth) / double(tileHeight); } // tile pixels
    double displayAspect = 0.0; // aspect the views are shown at; 0: the tile's
    double nameAspect() const { return displayAspect > 0.0 ? displayAspect : aspect(); }
};

// Layout rule: rows = ceil(N / cols), so fewer than one row of tiles is ever empty; among
// those, cols is chosen so that the quilt's aspect (cols * w) / (rows * h) is closest to
// `targetAspect` (ratio compared on a log scale), ties broken by fewer empty tiles, then by
// fewer columns. With targetAspect = the panel's aspect the quilt has the panel's shape,
// which for the prototype (48 views of 480x360 on 3840x2160) gives exactly 8x6 tiles of
// 3840x2160, one sample per panel pixel. Throws std::invalid_argument on zero sizes.
QuiltLayout chooseQuiltLayout(uint32_t viewCount, uint32_t viewWidth, uint32_t viewHeight,
                              double targetAspect);
// The profile's quilt: its device's standard quilt (looking_glass_devices.h, e.g. 8x6 at
// 3360x3360 on a Looking Glass Portrait) when the profile's views are that quilt's tiles,
// else the rule above with target aspect = panel width / panel height; displayAspect =
// the screen's width / height in mm.
QuiltLayout chooseQuiltLayout(const DisplayProfile& profile);

// --quilt-layout CxR[aASPECT]: `layout` with cols x rows tiles (and, when aspect > 0, that
// name aspect). Throws std::invalid_argument when the views do not fit the tiles.
QuiltLayout overrideQuiltLayout(QuiltLayout layout, uint32_t viewCount, uint32_t cols, uint32_t rows, double aspect);

// Tiles RGBA8 views (image order, row 0 = top, each tileWidth x tileHeight) into an RGBA8
// quilt in image order. Throws std::invalid_argument when the views do not fit the layout.
std::vector<uint8_t> assembleQuilt(const QuiltLayout& layout,
                                   const std::vector<std::vector<uint8_t>>& views);
// Same from the GPU view array (reads every layer back).
std::vector<uint8_t> assembleQuilt(const QuiltLayout& layout, const ViewTargets& views);

// "_qs8x6a1.33": aspect with at most two decimals, trailing zeros removed ("a2", "a0.75").
std::string quiltSuffix(uint32_t cols, uint32_t rows, double aspect);

// Inserts quiltSuffix before the extension ("out/q.png" -> "out/q_qs8x6a1.33.png") unless
// the stem already ends with a _qs{cols}x{rows}a{aspect} suffix (then the name is kept as
// given). A name without an extension gets ".png".
std::filesystem::path quiltFileName(const std::filesystem::path& requested, uint32_t cols,
                                    uint32_t rows, double aspect);
// quiltFileName(requested, layout) for the layout's name aspect.
std::filesystem::path quiltFileName(const std::filesystem::path& requested, const QuiltLayout& layout);

// Frame `frame` of a quilt sequence: the frame number (4 digits, more when needed) goes
// before the suffix, so every file still ends in it and Looking Glass tools read each one:
// "out/q.png" -> "out/q_0007_qs8x6a1.78.png" (also from "out/q_qs8x6a1.78.png").
std::filesystem::path quiltSequenceFileName(const std::filesystem::path& requested, const QuiltLayout& layout,
                                            uint32_t frame);
// The same name with a printf pattern ("%04d", a '%' in the name doubled) for ffmpeg.
std::filesystem::path quiltSequencePattern(const std::filesystem::path& requested, const QuiltLayout& layout);

} // namespace lfd::player
