// Image files for the player's tools (lfd-play, lfd-bench, lfd-compare) and libraries: decoding
// with stb_image and encoding with stb_image_write (Debian's libstb-dev headers, compiled into
// image_file.cpp), so the player links no image library and runs on a machine that has a GL driver
// and nothing else (docs/player/another-machine.md; the baker keeps OpenImageIO for its textures).
//
// Read: PNG (8 and 16 bits), JPEG (baseline and progressive), BMP, TGA, GIF (first frame),
// PSD (composited), HDR and PNM. Write: PNG, JPEG (quality 95), BMP, TGA, by extension.
// Every error is one line naming the file and the problem (ImageError); writes are
// atomic (atomic_file.h), so a failed write leaves nothing at the target or beside it.
// A truncated Radiance .hdr file is an error, not a hang (stb_image 2.27's RLE decoder
// never advances on the zero bytes it reads past the end of its input, so the scanlines
// are walked first; see image_file.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace lfd::metrics {

struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0;       // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA, as stored
    int bitsPerChannel = 8; // 8 (u8), 16 (u16) or 32 (f32: HDR, 1.0 = full scale)
    std::vector<uint8_t> u8;
    std::vector<uint16_t> u16;
    std::vector<float> f32;
};

// Decodes `path`. keepDepth = false: every file as 8 bits per channel (16-bit samples
// rounded, HDR tone-mapped by stb's default gamma); true: 16-bit PNG as u16 and HDR as f32.
// Alpha stays as stored (straight, never premultiplied).
DecodedImage decodeImageFile(const std::filesystem::path& path, bool keepDepth = false);

// A Radiance .hdr (RGBE) image as linear float RGB, row 0 = top.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3 values, as stored (no scale, no clamp)
};

// Reads a Radiance .hdr file (the player's environment maps). Refuses any other format,
// an image of more than maxPixels pixels (checked on the header, before decoding), a
// truncated file and corrupt RLE data, each with one line (ImageError).
HdrImage readHdrImage(const std::filesystem::path& path, uint64_t maxPixels);

// Writes `image` as a Radiance .hdr (RLE-compressed RGBE, as stb_image_write encodes it),
// atomically: test environments for `--environment FILE.hdr`, and HDR outputs.
void writeHdrImage(const std::filesystem::path& path, const HdrImage& image);

// Empty when encodeImageFile can write `path`'s format (by its extension: .png, .jpg, .jpeg,
// .bmp, .tga, any case); else the reason, e.g. "cannot write this image format '.xyz'
// (write .png, .jpg, .bmp or .tga)". The tools ask it when they read their flags, so a
// wrong output name fails before anything is rendered.
std::string imageFormatProblem(const std::filesystem::path& path);

// Encodes 8-bit interleaved pixels (1..4 channels, row 0 = top) in the format the
// extension names, atomically.
void encodeImageFile(const std::filesystem::path& path, const uint8_t* pixels, int width, int height,
                     int channels);

} // namespace lfd::metrics
