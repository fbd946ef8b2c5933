// 8-bit images on disk (PNG through image_file.h) and the image metrics the tests and the
// quality reports use. Pixels are always in image order (row 0 = top), channels
// interleaved. Writes are atomic: a temporary file in the target directory is renamed
// over the target, so a crash or a failed write never leaves a truncated image behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace lfd::player {

// One line naming the file and the problem.
class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

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

// Metrics over the colour channels (the first min(3, a.channels, b.channels); alpha is
// ignored). The images must have the same width and height (std::invalid_argument).
double rmse(const Image& a, const Image& b);        // root mean square error, 0..255
int maxAbsDiff(const Image& a, const Image& b);      // 0..255
double psnr(const Image& a, const Image& b);         // dB, +inf for identical images
// Mean SSIM (Wang, Bovik, Sheikh & Simoncelli 2004) on Rec. 601 luma, 11x11 Gaussian
// window with sigma 1.5, K1 = 0.01, K2 = 0.03, L = 255, over the window positions that
// fit inside the image (the window shrinks to the image for images smaller than 11).
double ssimLuma(const Image& a, const Image& b);

// Writes |a - b| per colour channel, multiplied by `gain` and clamped, as an RGB8 image
// (black = identical) for inspecting golden-image failures.
void writeDiffImage(const std::filesystem::path& path, const Image& a, const Image& b,
                    float gain = 8.0f);

} // namespace lfd::player
