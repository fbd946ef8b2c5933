// Image files of the player's one image type through its image codec (image_file.h).
#include "image.h"

#include "image_file.h"

#include <algorithm>
#include <string>

namespace lfd::metrics {

namespace fs = std::filesystem;

void throwImageError(const fs::path& path, const std::string& problem)
{
    std::string line = "'" + path.string() + "': " + problem;
    std::replace_if(line.begin(), line.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw ImageError(line);
}

void writeImage(const fs::path& path, const uint8_t* pixels, uint32_t width, uint32_t height,
                uint32_t channels) {
    if (width == 0 || height == 0)
        throwImageError(path, "cannot write an empty image (" + std::to_string(width) + "x" +
                       std::to_string(height) + ")");
    if (channels < 1 || channels > 4)
        throwImageError(path, "cannot write " + std::to_string(channels) + " channels (1..4 supported)");
    if (pixels == nullptr)
        throwImageError(path, "no pixel data");
    encodeImageFile(path, pixels, int(width), int(height), int(channels));
}

void writeImage(const fs::path& path, const Image& image) {
    if (image.pixels.size() != size_t(image.width) * image.height * image.channels)
        throwImageError(path, "pixel buffer does not match " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + "x" + std::to_string(image.channels));
    writeImage(path, image.pixels.data(), image.width, image.height, image.channels);
}

Image readImage(const fs::path& path, uint32_t channels) {
    if (channels > 4 || channels == 1 || channels == 2)
        throwImageError(path, "can only convert to 3 or 4 channels (0 keeps the file's)");
    DecodedImage decoded = decodeImageFile(path); // 8 bits per channel, straight alpha
    const uint32_t fileChannels = uint32_t(std::min(decoded.channels, 4));
    Image file;
    file.width = uint32_t(decoded.width);
    file.height = uint32_t(decoded.height);
    file.channels = fileChannels;
    file.pixels = std::move(decoded.u8);
    if (channels == 0 || channels == fileChannels)
        return file;

    // Convert: grey -> RGB, add opaque alpha or drop it.
    Image converted;
    converted.width = file.width;
    converted.height = file.height;
    converted.channels = channels;
    converted.pixels.resize(size_t(file.width) * file.height * channels);
    for (size_t i = 0; i < size_t(file.width) * file.height; ++i) {
        const uint8_t* src = &file.pixels[i * fileChannels];
        uint8_t* dst = &converted.pixels[i * channels];
        const bool grey = fileChannels <= 2;
        for (uint32_t c = 0; c < 3; ++c)
            dst[c] = grey ? src[0] : src[c];
        if (channels == 4) {
            const bool hasAlpha = fileChannels == 2 || fileChannels == 4;
            dst[3] = hasAlpha ? src[fileChannels - 1] : 255;
        }
    }
    return converted;
}

} // namespace lfd::metrics
