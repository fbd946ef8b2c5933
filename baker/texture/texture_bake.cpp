// Texture stage: decode (OpenImageIO), convert to RGBA8, reduce oversized sources, build
// the mip chain.
//
// Memory plan (16K x 16K sources must bake in well under two full-size RGBA8 copies):
//   1. The header gives the source size, hence the stored size and the whole chain's
//      layout; the final texel buffer (level 0 + all mips, ~1.33x level 0) is allocated
//      once, up front.
//   2. The source is read in strips of scanlines into a small buffer and converted to
//      RGBA8 row by row. Without reduction each row lands directly in level 0; with
//      reduction the rows stream through a cascade of 2x RowDownsamplers (a few rows
//      each) and only the reduced rows are written, so the full-size source is never held.
//      The cascade keeps its intermediate levels in float, so level 0 is quantised once.
//   3. Each mip level is built from the level above inside the same buffer.
// Peak is therefore the final buffer plus a few rows. OIIO's ImageBuf/ImageCache are not
// used because they would hold (float) copies of the whole image.
#include "texture_bake.h"

#include "bake_log.h"
#include "mip_chain.h"
#include "texture_webp.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>

namespace lfd::bake {

namespace {

// Larger headers are treated as corrupt: the stored size could still be fine, but the
// per-row buffers of the reduction cascade scale with the source width.
constexpr int kMaxSourceDimension = 1 << 20;

std::string sourceLabel(const TextureSource& source)
{
    if (!source.file.empty())
        return source.file.string();
    if (!source.name.empty())
        return source.name;
    return "<embedded texture>";
}

// OIIO messages may span lines; errors must be one line.
std::string oneLine(const std::string& text)
{
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ')
                out += "; ";
        } else {
            out += c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';'))
        out.pop_back();
    return out.empty() ? std::string("unknown error") : out;
}

[[noreturn]] void fail(const TextureSource& source, const std::string& problem)
{
    throw BakeError(sourceLabel(source) + ": " + oneLine(problem));
}

// File name extension OIIO should pick the reader by, for embedded bytes: the content's
// signature first (glTF exporters get the mimeType wrong now and then), then mimeType.
std::string embeddedExtension(const TextureSource& source)
{
    const std::vector<uint8_t>& b = source.encoded;
    static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (b.size() >= 8 && std::memcmp(b.data(), kPng, 8) == 0)
        return "png";
    if (b.size() >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
        return "jpg";
    if (source.mimeType == "image/png")
        return "png";
    if (source.mimeType == "image/jpeg")
        return "jpg";
    return {};
}

// An opened image. The proxy (embedded bytes) must outlive the input: members are
// destroyed in reverse order, input first. A WebP image has no input: its bytes are
// decoded by libwebp (texture_webp.h), whole, when its rows are read.
struct OpenImage {
    std::unique_ptr<OIIO::Filesystem::IOMemReader> proxy;
    std::unique_ptr<OIIO::ImageInput> input;
    std::vector<uint8_t> webpFile;   // an image file's bytes, read whole when it is WebP
    std::span<const uint8_t> webp;   // the WebP bytes (embedded or webpFile); empty: not WebP
    int width = 0;
    int height = 0;
    int channels = 0; // channels read: min(nchannels, 4)
};

// Whether the file starts with the WebP signature.
bool isWebpFile(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::array<uint8_t, 12> head{};
    in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    return in.gcount() == std::streamsize(head.size()) && isWebp(head);
}

// The image's size, checked against what the baker can hold.
void checkSize(const TextureSource& source, int width, int height)
{
    if (width <= 0 || height <= 0)
        fail(source, "cannot decode: image has zero size (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    if (width > kMaxSourceDimension || height > kMaxSourceDimension)
        fail(source, "cannot decode: image too large (" + std::to_string(width) + "x" + std::to_string(height) + ")");
}

// A WebP source (embedded, or a file with the WebP signature whatever its name) opened
// for libwebp; false when the source is not WebP.
bool openWebp(const TextureSource& source, OpenImage& image)
{
    if (!source.encoded.empty() && isWebp(source.encoded)) {
        image.webp = source.encoded;
    } else if (source.encoded.empty() && !source.file.empty() && isWebpFile(source.file)) {
        std::ifstream in(source.file, std::ios::binary);
        image.webpFile.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        image.webp = image.webpFile;
    } else {
        return false;
    }
    const std::optional<WebpSize> size = webpSize(image.webp);
    if (!size)
        fail(source, "cannot decode: not a valid WebP header");
    checkSize(source, size->width, size->height);
    image.width = size->width;
    image.height = size->height;
    image.channels = 4;
    return true;
}

// Opens the source and reads its header only; validates what the header says.
OpenImage openImage(const TextureSource& source)
{
    OpenImage image;
    if (openWebp(source, image))
        return image;
    OIIO::ImageSpec config;
    // note: PNG alpha is associated (premultiplied) by OIIO by default; glTF textures
    // carry straight alpha, so ask for the stored values.
    config.attribute("oiio:UnassociatedAlpha", 1);

    if (!source.encoded.empty()) {
        const std::string ext = embeddedExtension(source);
        if (ext.empty())
            fail(source, "unsupported embedded image type '" + source.mimeType + "'");
        image.proxy = std::make_unique<OIIO::Filesystem::IOMemReader>(source.encoded.data(),
                                                                      source.encoded.size());
        // note: with a config, the readers take the proxy from the "oiio:ioproxy" hint
        // (the ioproxy argument alone is dropped when the config is applied).
        void* proxy = image.proxy.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        image.input = OIIO::ImageInput::open("embedded." + ext, &config, image.proxy.get());
    } else if (!source.file.empty()) {
        std::error_code ec;
        if (!std::filesystem::exists(source.file, ec))
            fail(source, "cannot open: file not found");
        if (!std::filesystem::is_regular_file(source.file, ec))
            fail(source, "cannot open: not a regular file");
        image.input = OIIO::ImageInput::open(source.file.string(), &config);
    } else {
        fail(source, "no image data (neither a file nor embedded bytes)");
    }
    if (!image.input)
        fail(source, "cannot decode: " + OIIO::geterror());
    // note: single-threaded reads; rows are converted here, and the bake may run in a
    // forked process where OIIO's thread pool would not exist.
    image.input->threads(1);

    const OIIO::ImageSpec& spec = image.input->spec();
    checkSize(source, spec.width, spec.height);
    if (spec.nchannels <= 0)
        fail(source, "cannot decode: image has no channels");
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(spec.nchannels, 4);
    return image;
}

// One channel value to a byte: 8-bit as is; anything else (read as float) clamped to
// [0,1] and rounded.
inline uint8_t toByte(uint8_t v) { return v; }
inline uint8_t toByte(float v)
{
    const float x = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; // NaN -> 0
    return uint8_t(x * 255.0f + 0.5f);
}

// 1 channel: grey (replicated to RGB, colour and data alike), A = 255; 2: grey + alpha;
// 3: RGB, A = 255; 4: RGBA.
template <typename T>
void toRgba8(const T* in, int channels, uint32_t width, uint8_t* out)
{
    for (uint32_t x = 0; x < width; ++x, in += channels, out += 4) {
        switch (channels) {
        case 1:
            out[0] = out[1] = out[2] = toByte(in[0]);
            out[3] = 255;
            break;
        case 2:
            out[0] = out[1] = out[2] = toByte(in[0]);
            out[3] = toByte(in[1]);
            break;
        case 3:
            out[0] = toByte(in[0]);
            out[1] = toByte(in[1]);
            out[2] = toByte(in[2]);
            out[3] = 255;
            break;
        default:
            out[0] = toByte(in[0]);
            out[1] = toByte(in[1]);
            out[2] = toByte(in[2]);
            out[3] = toByte(in[3]);
            break;
        }
    }
}

// Decodes a WebP image's RGBA8 rows `stride` bytes apart into `out`.
void decodeWebpInto(const OpenImage& image, const TextureSource& source, uint8_t* out, size_t stride)
{
    if (const std::string why = decodeWebp(image.webp, {image.width, image.height}, out, stride); !why.empty())
        fail(source, "cannot decode: " + why);
}

// Reads the image top to bottom in strips and hands each row, converted to RGBA8, to
// `sink(row, y)`. (A WebP image is decoded whole first: libwebp has no row-by-row output.)
template <typename Sink>
void readRows(OpenImage& image, const TextureSource& source, Sink&& sink)
{
    if (!image.webp.empty()) {
        const size_t stride = size_t(image.width) * 4;
        std::vector<uint8_t> rgba(stride * size_t(image.height));
        decodeWebpInto(image, source, rgba.data(), stride);
        for (uint32_t y = 0; y < uint32_t(image.height); ++y)
            sink(rgba.data() + y * stride, y);
        return;
    }
    const OIIO::ImageSpec& spec = image.input->spec();
    const bool bytes = spec.format == OIIO::TypeDesc::UINT8 && spec.channelformats.empty();
    const OIIO::TypeDesc format = bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    const size_t valueSize = bytes ? 1 : sizeof(float);
    const uint32_t width = uint32_t(image.width), height = uint32_t(image.height);
    // note: tiled files are read a whole tile row at a time so no tile is decoded twice.
    const uint32_t stripRows =
        std::min(height, uint32_t(spec.tile_height > 0 ? std::max(spec.tile_height, 16) : 32));
    const size_t rowBytes = size_t(width) * size_t(image.channels) * valueSize;
    std::vector<unsigned char> strip(rowBytes * stripRows);
    std::vector<uint8_t> rgba(size_t(width) * 4);

    for (uint32_t y0 = 0; y0 < height; y0 += stripRows) {
        const uint32_t rows = std::min(stripRows, height - y0);
        if (!image.input->read_scanlines(0, 0, spec.y + int(y0), spec.y + int(y0 + rows), spec.z,
                                         0, image.channels, format, strip.data()))
            fail(source, "cannot decode: " + image.input->geterror());
        for (uint32_t r = 0; r < rows; ++r) {
            const unsigned char* row = strip.data() + r * rowBytes;
            if (bytes)
                toRgba8(row, image.channels, width, rgba.data());
            else
                toRgba8(reinterpret_cast<const float*>(row), image.channels, width, rgba.data());
            sink(rgba.data(), y0 + r);
        }
    }
}

} // namespace

glm::uvec2 probeTextureSize(const TextureSource& source)
{
    OpenImage image = openImage(source);
    return {uint32_t(image.width), uint32_t(image.height)};
}

glm::uvec2 storedTextureSize(glm::uvec2 sourceSize, const TextureBakeOptions& options)
{
    const uint32_t maxSize = std::max(options.maxSize, 1u);
    glm::uvec2 size = glm::max(sourceSize, glm::uvec2(1));
    // Both dimensions are halved together to keep the aspect ratio (each >= 1): the
    // stored texture is exactly mip level k of the source.
    while (std::max(size.x, size.y) > maxSize)
        size = glm::max(size / 2u, glm::uvec2(1));
    return size;
}

Texture bakeTexture(const TextureSource& source, const TextureBakeOptions& options)
{
    OpenImage image = openImage(source);
    const glm::uvec2 sourceSize(uint32_t(image.width), uint32_t(image.height));
    const glm::uvec2 storedSize = storedTextureSize(sourceSize, options);

    Texture texture;
    texture.name = source.name;
    texture.srgb = source.srgb;
    texture.sourceWidth = sourceSize.x;
    texture.sourceHeight = sourceSize.y;
    texture.width = storedSize.x;
    texture.height = storedSize.y;
    texture.mips = mip::chainLayout(storedSize.x, storedSize.y);

    try {
        // Allocate the final buffer first: level 0 is decoded straight into it.
        texture.texels.resize(mip::chainBytes(texture.mips));
        uint8_t* level0 = texture.texels.data();
        const size_t storedStride = size_t(storedSize.x) * 4;

        // Build the reduction cascade: one 2x stage per halving (none when kept as is).
        std::vector<mip::RowDownsampler> stages;
        for (glm::uvec2 s = sourceSize; s != storedSize; s = glm::max(s / 2u, glm::uvec2(1)))
            stages.emplace_back(s.x, s.y);

        if (stages.empty() && !image.webp.empty()) {
            decodeWebpInto(image, source, level0, storedStride); // straight into level 0, no copy
        } else if (stages.empty()) {
            readRows(image, source, [&](const uint8_t* row, uint32_t y) {
                std::memcpy(level0 + y * storedStride, row, storedStride);
            });
        } else {
            std::vector<float> linear(size_t(sourceSize.x) * 4);
            readRows(image, source, [&](const uint8_t* row, uint32_t) {
                mip::decodeRow(row, sourceSize.x, texture.srgb, linear.data());
                const float* out = linear.data();
                for (mip::RowDownsampler& stage : stages) {
                    out = stage.push(out);
                    if (!out)
                        return;
                }
                mip::encodeRow(out, storedSize.x, texture.srgb,
                               level0 + stages.back().lastOutputRow() * storedStride);
            });
        }
        if (image.input)
            image.input->close();

        if (options.pool)
            mip::buildChain(texture.texels.data(), texture.mips, texture.srgb, *options.pool);
        else
            mip::buildChain(texture.texels.data(), texture.mips, texture.srgb, options.threads);
    } catch (const std::bad_alloc&) {
        fail(source, "out of memory baking " + std::to_string(sourceSize.x) + "x" +
                         std::to_string(sourceSize.y) + " texture");
    }
    return texture;
}

} // namespace lfd::bake
