// Reading images into RgbImage and writing RGB8 images atomically, through the player's
// one image codec (image_file.h: stb_image, stb_image_write).
#include "image_file.h"
#include "image_metrics.h"

#include <algorithm>
#include <string>

namespace lfd::metrics {

RgbImage readRgbImage(const std::filesystem::path& path)
{
    // 8-bit files are read as bytes so their values convert exactly; 16-bit and HDR files
    // keep their depth (scaled so 1.0 = 255).
    const DecodedImage image = decodeImageFile(path, true);
    const int channels = std::min(image.channels, 4);
    if (image.bitsPerChannel == 8)
        return rgbFromPixels8(image.u8.data(), image.width, image.height, channels);
    std::vector<float> pixels;
    if (image.bitsPerChannel == 16) {
        pixels.reserve(image.u16.size());
        for (const uint16_t v : image.u16)
            pixels.push_back(float(v) / 65535.0f);
    } else {
        pixels = image.f32;
    }
    return rgbFromPixelsFloat(pixels.data(), image.width, image.height, channels);
}

void writeRgb8Image(const std::filesystem::path& path, std::span<const uint8_t> rgb, int width, int height)
{
    if (width > 0 && height > 0 && rgb.size() != size_t(width) * size_t(height) * 3)
        throw ImageError("'" + path.string() + "': pixel buffer does not hold " + std::to_string(width) +
                             "x" + std::to_string(height) + "x3 bytes");
    encodeImageFile(path, rgb.data(), width, height, 3);
}

} // namespace lfd::metrics
