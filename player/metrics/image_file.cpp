#include "image_file.h"

#include "atomic_file.h"
#include "image.h" // ImageError

// stb's implementations, private to this file (STB_*_STATIC), from Debian's libstb-dev
// headers: the player's only image codec.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-qual"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>

namespace lfd::metrics {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& problem)
{
    std::string line = "'" + path.string() + "': " + problem;
    std::replace_if(line.begin(), line.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw ImageError(line);
}

std::string lowerExtension(const fs::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

struct FileCloser {
    void operator()(FILE* f) const { std::fclose(f); }
};

template <class T>
struct StbFree {
    void operator()(T* p) const { stbi_image_free(p); }
};

// stb_image_write's callback: appends to a byte vector.
void appendBytes(void* context, void* data, int size)
{
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

} // namespace

DecodedImage decodeImageFile(const fs::path& path, bool keepDepth)
{
    std::error_code ec;
    if (!fs::exists(path, ec))
        fail(path, "no such file");
    if (fs::is_directory(path, ec))
        fail(path, "is a directory, not an image");
    const std::unique_ptr<FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file)
        fail(path, "cannot open for reading");

    DecodedImage image;
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_file(file.get(), &w, &h, &n))
        fail(path, std::string("cannot read image: ") + stbi_failure_reason());
    const bool sixteen = keepDepth && stbi_is_16_bit_from_file(file.get());
    const bool hdr = keepDepth && stbi_is_hdr_from_file(file.get());
    if (hdr) {
        const std::unique_ptr<float, StbFree<float>> p(stbi_loadf_from_file(file.get(), &w, &h, &n, 0));
        if (!p)
            fail(path, std::string("cannot read pixels: ") + stbi_failure_reason());
        image.f32.assign(p.get(), p.get() + size_t(w) * size_t(h) * size_t(n));
        image.bitsPerChannel = 32;
    } else if (sixteen) {
        const std::unique_ptr<stbi_us, StbFree<stbi_us>> p(stbi_load_from_file_16(file.get(), &w, &h, &n, 0));
        if (!p)
            fail(path, std::string("cannot read pixels: ") + stbi_failure_reason());
        image.u16.assign(p.get(), p.get() + size_t(w) * size_t(h) * size_t(n));
        image.bitsPerChannel = 16;
    } else {
        const std::unique_ptr<stbi_uc, StbFree<stbi_uc>> p(stbi_load_from_file(file.get(), &w, &h, &n, 0));
        if (!p)
            fail(path, std::string("cannot read pixels: ") + stbi_failure_reason());
        image.u8.assign(p.get(), p.get() + size_t(w) * size_t(h) * size_t(n));
    }
    if (w <= 0 || h <= 0 || n <= 0)
        fail(path, "image has no pixels");
    image.width = w;
    image.height = h;
    image.channels = n;
    return image;
}

void encodeImageFile(const fs::path& path, const uint8_t* pixels, int width, int height, int channels)
{
    if (width <= 0 || height <= 0)
        fail(path, "cannot write an empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    if (channels < 1 || channels > 4)
        fail(path, "cannot write " + std::to_string(channels) + " channels (1 to 4)");
    if (!pixels)
        fail(path, "no pixel data");
    std::vector<uint8_t> bytes;
    const std::string ext = lowerExtension(path);
    int ok = 0;
    if (ext == ".png")
        ok = stbi_write_png_to_func(appendBytes, &bytes, width, height, channels, pixels, width * channels);
    else if (ext == ".jpg" || ext == ".jpeg")
        ok = stbi_write_jpg_to_func(appendBytes, &bytes, width, height, channels, pixels, 95);
    else if (ext == ".bmp")
        ok = stbi_write_bmp_to_func(appendBytes, &bytes, width, height, channels, pixels);
    else if (ext == ".tga")
        ok = stbi_write_tga_to_func(appendBytes, &bytes, width, height, channels, pixels);
    else
        fail(path, "cannot write this image format '" + ext + "' (write .png, .jpg, .bmp or .tga)");
    if (!ok)
        fail(path, "encoding failed");
    try {
        io::writeFileAtomically(path, bytes);
    } catch (const io::AtomicWriteError& e) {
        throw ImageError(e.what());
    }
}

} // namespace lfd::metrics
