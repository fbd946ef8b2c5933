// Quilts made elsewhere (Blender, Unity, Looking Glass tools, or lfd-play --quilt) as
// input: the layout comes from the file name's `_qs{cols}x{rows}a{aspect}` (quilt.h), the
// views are cut from the tiles and go through the same EIA builder (and reconstruction
// modes) as rendered views. The EIA is built from the quilt's own views - its count and
// tile size - so a quilt of another layout (5x9 = 45 views) needs no resampling across
// views: each subpixel takes the view its lens phase selects among the 45.
#pragma once

#include "image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::player {

class ViewTargets;

// One line naming the file and the problem.
class QuiltInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct QuiltName {
    uint32_t cols = 0, rows = 0;
    double aspect = 0.0; // the aspect each view is shown at (width / height); 0: not given
};

// The last `_qs{cols}x{rows}[a{aspect}]` in the file name, e.g. "car_qs8x6a0.75.png",
// "clip_0003_qs5x9a0.75.jpg" or "old_qs4x3.png" (no aspect: the views are taken as made
// for the screen they are shown on). Throws QuiltInputError for a name without one, zero columns or rows, or an
// aspect that is not a positive number.
QuiltName parseQuiltName(const std::filesystem::path& file);
// The same layout as a flag value, "CxR" or "CxRaASPECT" (--quilt-layout). Throws
// QuiltInputError naming `flag`.
QuiltName parseQuiltLayout(const std::string& text, const std::string& flag);
// The layout a file is read with: `given` (--quilt-layout) when set - the name's aspect
// filling in an aspect it lacks, and the name need not carry a layout - else the name's.
QuiltName quiltNameOf(const std::filesystem::path& file, const std::optional<QuiltName>& given);

// A file: itself (its name must parse unless a layout is given). A directory: its image
// files (.png, .jpg, .jpeg, .webp, .bmp, .tif, .tiff, .exr) whose names parse (all of them
// with a given layout), sorted by name - a slideshow. Throws QuiltInputError when the
// path is missing or the directory holds no quilt.
std::vector<std::filesystem::path> listQuiltFiles(const std::filesystem::path& fileOrDirectory,
                                                  bool layoutGiven = false);

struct QuiltViews {
    uint32_t width = 0, height = 0;          // per view
    std::vector<std::vector<uint8_t>> views; // RGBA8, image order (row 0 = top), view 0 = leftmost
};

// Cuts `quilt` (RGBA8) into views. View v is tile (v % cols, v / cols counted from the
// bottom); tiles are W / cols x H / rows pixels (rounded down), and each view pixel is
// the quilt sampled bilinearly at its centre's position inside its tile, clamped to the
// tile - an exact copy when W and H are multiples of cols and rows. `viewCount` 0 means
// every tile (cols * rows); fewer skip the trailing (empty) tiles. When the views'
// aspect differs from `screenAspect` by more than 1%, each view is padded with black,
// centred and unscaled, to the screen's aspect, so nothing is stretched (Looking Glass
// players letterbox the same way). Throws QuiltInputError.
QuiltViews extractQuiltViews(const metrics::Image& quilt, const QuiltName& name, uint32_t viewCount, double screenAspect);

// Reads a quilt file (as RGBA8) and extracts its views; errors name the file.
QuiltViews loadQuiltViews(const std::filesystem::path& file, const QuiltName& name, uint32_t viewCount,
                          double screenAspect);

// Copies views (same count and size as the targets) into the view array (GL).
void uploadViews(ViewTargets& targets, const QuiltViews& views);

} // namespace lfd::player
