// RgbImage construction from 8-bit and float pixel buffers, and the size checks every
// metric makes before touching pixels.
#include "image_checks.h"

#include <string>

namespace lfd::metrics {

namespace {

std::string sizeText(int width, int height)
{
    return std::to_string(width) + "x" + std::to_string(height);
}

void requireLayout(int width, int height, int channels, const void* pixels)
{
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("image size " + sizeText(width, height) + " is empty");
    if (channels < 1 || channels > 4)
        throw std::invalid_argument(std::to_string(channels) + " channels (1..4 supported)");
    if (pixels == nullptr)
        throw std::invalid_argument("no pixel data");
}

// Grey (1 or 2 channels) fills R, G and B; 3 or 4 channels give R, G, B (alpha dropped).
template <typename T, typename Scale>
RgbImage convert(const T* pixels, int width, int height, int channels, Scale scale)
{
    requireLayout(width, height, channels, pixels);
    RgbImage image;
    image.width = width;
    image.height = height;
    image.rgb.resize(image.pixelCount() * 3);
    const bool grey = channels <= 2;
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        const T* p = pixels + i * size_t(channels);
        for (int c = 0; c < 3; ++c)
            image.rgb[i * 3 + size_t(c)] = scale(grey ? p[0] : p[c]);
    }
    return image;
}

} // namespace

RgbImage rgbFromPixels8(const uint8_t* pixels, int width, int height, int channels)
{
    return convert(pixels, width, height, channels, [](uint8_t v) { return float(v); });
}

RgbImage rgbFromImage(const Image& image)
{
    if (image.pixels.size() != size_t(image.width) * image.height * image.channels)
        throw std::invalid_argument("pixel buffer does not match " + sizeText(int(image.width), int(image.height)) +
                                    "x" + std::to_string(image.channels));
    return rgbFromPixels8(image.pixels.data(), int(image.width), int(image.height), int(image.channels));
}

RgbImage rgbFromPixelsFloat(const float* pixels, int width, int height, int channels)
{
    return convert(pixels, width, height, channels, [](float v) { return v * 255.0f; });
}

namespace detail {

void requireSameSize(const RgbImage& reference, const RgbImage& test, const char* metric)
{
    const std::string name(metric);
    if (reference.width <= 0 || reference.height <= 0)
        throw std::invalid_argument(name + ": the reference image is empty");
    if (reference.width != test.width || reference.height != test.height)
        throw std::invalid_argument(name + ": image sizes differ (reference " +
                                    sizeText(reference.width, reference.height) + ", test " +
                                    sizeText(test.width, test.height) + ")");
    if (reference.rgb.size() != reference.pixelCount() * 3 ||
        test.rgb.size() != test.pixelCount() * 3)
        throw std::invalid_argument(name + ": pixel buffer does not hold width x height x 3 values");
}

void requireMaskSize(const RgbImage& image, std::span<const uint8_t> mask, const char* metric)
{
    if (mask.size() != image.pixelCount())
        throw std::invalid_argument(std::string(metric) + ": mask has " +
                                    std::to_string(mask.size()) + " bytes, the image " +
                                    std::to_string(image.pixelCount()) + " pixels");
}

} // namespace detail

} // namespace lfd::metrics
