// The player's one image type: 8-bit pixels, 1..4 interleaved channels, row 0 = top, as
// views, EIAs, quilts and image files hold them; read and written through the player's one
// image codec (image_file.h). Its metrics (RMSE, PSNR, SSIM, ...) are the ones in
// image_metrics.h, for this type and for RgbImage alike. Writes are atomic (atomic_file.h):
// a crash or a failed write never leaves a truncated image behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd::metrics {

// One line naming the file and the problem.
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws ImageError("'<path>': <problem>"), folded onto one line: the one form of every
// error the image library reports.
[[noreturn]] void throwImageError(const std::filesystem::path& path, const std::string& problem);

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 0; // 1..4
    std::vector<uint8_t> pixels; // width * height * channels bytes, row 0 = top
};

// Writes 1..4 channel 8-bit pixels; the format follows the extension (.png expected).
// Throws ImageError; on failure nothing is left at `path` or next to it.
void writeImage(const std::filesystem::path& path, const uint8_t* pixels, uint32_t width,
                uint32_t height, uint32_t channels);
void writeImage(const std::filesystem::path& path, const Image& image);

// Reads an image as 8-bit. channels = 0 keeps the file's channel count (at most 4);
// 3 or 4 converts (grey is replicated, a missing alpha is 255, an extra alpha dropped).
Image readImage(const std::filesystem::path& path, uint32_t channels = 0);

} // namespace lfd::metrics
