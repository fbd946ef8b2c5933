// Disk cache of gstd's views (issue 8: "cached on disk per (pack content hash, frame,
// profile, settings) so benches do not re-render it"). The gold standard takes minutes per
// frame on a CPU while every other renderer takes milliseconds, so lfd-bench renders it
// once per (pack, frame, view geometry, gstd settings, GL driver) and reloads the N views
// afterwards; the EIA is still built from them by the EiaBuilder as for every method.
//
// gstd's panel model also stores its panel image (the EIA it integrates itself).
//
// One file per key, DIR/<XXH3-64 of the key, hex>.gstdviews:
//   "LFDGSTD2" | u32 key length | key text | u32 views, width, height |
//   views * height * width * 4 bytes RGBA8 (GL order: layer by layer, bottom row first) |
//   u32 panel width, height (0, 0 without a panel image) | width * height * 4 bytes RGBA8
//   (GL order) | u64 XXH3-64 of everything before it
// The full key is stored and compared, so a hash collision reads as a miss, and a file
// that is truncated or corrupted fails its checksum and is re-rendered. Writes go to a
// temporary file in DIR that is renamed over the entry, so readers never see a partial one.
#pragma once

#include "renderer_gstd.h"

#include "lfd/display_profile.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace lfd::player {

class ViewTargets;

// XXH3-64 of a file's bytes (streamed). Throws std::runtime_error naming the file.
uint64_t hashFileContents(const std::filesystem::path& path);

// Everything gstd's views depend on, as text: the pack's content hash, the frame time and
// turntable period (scene pose and animation), the view geometry of the profile (view
// count and size, cone, viewing distance, screen size: the panel and lenses only affect
// the EIA; the panel model adds the panel size and its subpixel mapping), gstd's settings,
// and the GL driver (rasterisation and filtering differ
// slightly between drivers).
std::string gstdCacheKey(uint64_t packHash, double time, double turntablePeriod,
                         const DisplayProfile& profile, const GstdOptions& options,
                         const std::string& glDriver);

// $XDG_CACHE_HOME/lfdpr/gstd, else $HOME/.cache/lfdpr/gstd, else an empty path (no cache).
std::filesystem::path defaultGstdCacheDir();

// The panel image of gstd's panel model: an RGBA8 2D texture (the pipeline's EIA).
struct GstdCachePanel {
    unsigned texture = 0;
    uint32_t width = 0, height = 0;
};

class GstdCache {
public:
    explicit GstdCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

    const std::filesystem::path& dir() const { return dir_; }
    std::filesystem::path entryPath(const std::string& key) const;

    // Uploads the cached views into `targets` (and the panel image into panel->texture)
    // and returns true when an intact entry for `key` with the targets' view count and
    // size (and a panel image of that size) exists; false otherwise (nothing changed).
    bool load(const std::string& key, ViewTargets& targets, const GstdCachePanel* panel = nullptr) const;
    // Reads the views (and the panel image) back and writes the entry atomically (creating
    // DIR). Throws std::runtime_error naming the file on failure, leaving nothing behind.
    void store(const std::string& key, const ViewTargets& targets, const GstdCachePanel* panel = nullptr) const;

private:
    std::filesystem::path dir_;
};

} // namespace lfd::player
