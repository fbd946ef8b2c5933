// WebP decoding with libwebp (see texture_webp.h).
#include "texture_webp.h"

#include <webp/decode.h>

#include <cstring>

namespace lfd::bake {

bool isWebp(std::span<const uint8_t> bytes)
{
    return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

std::optional<WebpSize> webpSize(std::span<const uint8_t> bytes)
{
    WebpSize size;
    if (!isWebp(bytes) || !WebPGetInfo(bytes.data(), bytes.size(), &size.width, &size.height))
        return std::nullopt;
    return size;
}

std::string decodeWebp(std::span<const uint8_t> bytes, WebpSize size, uint8_t* out, size_t stride)
{
    WebPDecoderConfig config;
    if (!WebPInitDecoderConfig(&config))
        return "libwebp version mismatch";
    // The features first: an animated WebP has no single image to decode.
    if (WebPGetFeatures(bytes.data(), bytes.size(), &config.input) != VP8_STATUS_OK)
        return "not a valid WebP header";
    if (config.input.has_animation)
        return "an animated WebP (EXT_texture_webp images are still images)";
    if (config.input.width != size.width || config.input.height != size.height)
        return "the WebP header changed between reads";
    config.output.colorspace = MODE_RGBA; // straight alpha (MODE_rgbA would premultiply)
    config.output.is_external_memory = 1;
    config.output.u.RGBA.rgba = out;
    config.output.u.RGBA.stride = int(stride);
    config.output.u.RGBA.size = stride * size_t(size.height);
    const VP8StatusCode status = WebPDecode(bytes.data(), bytes.size(), &config);
    WebPFreeDecBuffer(&config.output); // external memory: frees nothing of ours
    switch (status) {
    case VP8_STATUS_OK: return {};
    case VP8_STATUS_NOT_ENOUGH_DATA: return "truncated WebP data";
    case VP8_STATUS_BITSTREAM_ERROR: return "corrupt WebP data";
    case VP8_STATUS_UNSUPPORTED_FEATURE: return "a WebP feature libwebp does not decode";
    case VP8_STATUS_OUT_OF_MEMORY: return "out of memory decoding WebP";
    default: return "WebP decoding failed (libwebp status " + std::to_string(int(status)) + ")";
    }
}

} // namespace lfd::bake
