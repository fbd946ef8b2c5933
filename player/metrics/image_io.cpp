// Reading images into RgbImage and writing RGB8 images atomically, through OpenImageIO.
#include "image_metrics.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <system_error>

#include <unistd.h>

namespace lfd::metrics {

namespace {

namespace fs = std::filesystem;

std::string oneLine(std::string text)
{
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

[[noreturn]] void fail(const fs::path& path, const std::string& problem)
{
    throw MetricsIoError(oneLine("'" + path.string() + "': " + problem));
}

// A temporary name beside the target (rename is atomic only within one file system) that
// keeps the extension, since OpenImageIO picks the format from it.
fs::path temporaryPathFor(const fs::path& path)
{
    static std::atomic<unsigned> counter{0};
    return path.parent_path() / ("." + path.stem().string() + ".tmp-" +
                                 std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                                 path.extension().string());
}

} // namespace

RgbImage readRgbImage(const fs::path& path)
{
    std::error_code ec;
    if (!fs::exists(path, ec))
        fail(path, "no such file");
    if (fs::is_directory(path, ec))
        fail(path, "is a directory, not an image");
    // Alpha is ignored, so colour is taken as stored, not premultiplied by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in)
        fail(path, "cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        fail(path, "image has no pixels");
    const int channels = std::min(spec.nchannels, 4);
    const size_t values = size_t(spec.width) * size_t(spec.height) * size_t(channels);

    // 8-bit files are read as bytes so their values convert exactly.
    if (spec.format == OIIO::TypeDesc::UINT8) {
        std::vector<uint8_t> pixels(values);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
            fail(path, "cannot read pixels: " + in->geterror());
        return rgbFromPixels8(pixels.data(), spec.width, spec.height, channels);
    }
    std::vector<float> pixels(values);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        fail(path, "cannot read pixels: " + in->geterror());
    return rgbFromPixelsFloat(pixels.data(), spec.width, spec.height, channels);
}

void writeRgb8Image(const fs::path& path, std::span<const uint8_t> rgb, int width, int height)
{
    if (width <= 0 || height <= 0)
        fail(path, "cannot write an empty image (" + std::to_string(width) + "x" +
                       std::to_string(height) + ")");
    if (rgb.size() != size_t(width) * size_t(height) * 3)
        fail(path, "pixel buffer does not hold " + std::to_string(width) + "x" +
                       std::to_string(height) + "x3 bytes");

    const fs::path temporary = temporaryPathFor(path);
    auto removeTemporary = [&] {
        std::error_code ignored;
        fs::remove(temporary, ignored);
    };

    // Step 1: everything goes to the temporary file.
    auto out = OIIO::ImageOutput::create(temporary.string());
    if (!out)
        fail(path, "cannot write this image format: " + OIIO::geterror());
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(temporary.string(), spec)) {
        const std::string error = out->geterror();
        removeTemporary();
        fail(path, "cannot open for writing: " + error);
    }
    const bool written = out->write_image(OIIO::TypeDesc::UINT8, rgb.data());
    const std::string writeError = written ? std::string() : out->geterror();
    const bool closed = out->close();
    const std::string closeError = closed ? std::string() : out->geterror();
    out.reset();
    if (!written || !closed) {
        removeTemporary();
        fail(path, "write failed: " + (written ? closeError : writeError));
    }

    // Step 2: moved into place in one step.
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        removeTemporary();
        fail(path, "cannot move the written image into place: " + ec.message());
    }
}

} // namespace lfd::metrics
