// WebP images (EXT_texture_webp), decoded with libwebp (Debian libwebp-dev) for the
// texture stage (internal to the baker). Not through OpenImageIO: Debian 12's OIIO 2.4
// reads WebP but premultiplies its alpha whatever "oiio:UnassociatedAlpha" asks, and glTF
// colours carry straight alpha (section 3.9.4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace lfd::bake {

// Whether `bytes` start with the WebP signature: "RIFF", a 4-byte size, "WEBP".
bool isWebp(std::span<const uint8_t> bytes);

struct WebpSize {
    int width = 0;
    int height = 0;
};

// The image size from the WebP header; nullopt when the header is not a valid one.
std::optional<WebpSize> webpSize(std::span<const uint8_t> bytes);

// Decodes to straight-alpha RGBA8 rows `stride` bytes apart at `out`, which holds
// `size.height` rows of at least 4 x `size.width` bytes (size: webpSize of the same bytes).
// Returns "" on success, otherwise why it failed (one line).
std::string decodeWebp(std::span<const uint8_t> bytes, WebpSize size, uint8_t* out, size_t stride);

} // namespace lfd::bake
