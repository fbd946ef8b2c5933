#include "procedural_textures.h"

#include <OpenImageIO/imageio.h>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace lfd::samples {

namespace {

// ---- PNG streaming --------------------------------------------------------------

// Rows per strip: small enough to keep a 16384-wide strip at 1.5 MiB.
constexpr int kStripRows = 32;

std::string oneLine(std::string text)
{
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

// Fills one strip with all cores, row-interleaved so every thread gets similar work.
void fillStrip(const RowFiller& fill, int width, int y0, int rows, uint8_t* pixels)
{
    const int threads =
        std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::min(16, rows));
    const size_t rowBytes = size_t(width) * 3;
    auto work = [&](int first) {
        for (int r = first; r < rows; r += threads)
            fill(y0 + r, 1, pixels + size_t(r) * rowBytes);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(work, t);
    work(0);
    for (std::thread& thread : pool)
        thread.join();
}

// ---- procedural helpers ---------------------------------------------------------

uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed)
{
    // A small integer mix (lowbias32-style): good enough for visual noise.
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

float hashUnit(int x, int y, uint32_t seed)
{
    return float(hash3(uint32_t(x), uint32_t(y), seed) >> 8) * (1.0f / 16777216.0f);
}

// Value noise in [0, 1] on an integer lattice, smoothstep-interpolated.
float valueNoise(float x, float y, uint32_t seed)
{
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = int(fx), iy = int(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    const float a = hashUnit(ix, iy, seed), b = hashUnit(ix + 1, iy, seed);
    const float c = hashUnit(ix, iy + 1, seed), d = hashUnit(ix + 1, iy + 1, seed);
    return glm::mix(glm::mix(a, b, tx), glm::mix(c, d, tx), ty);
}

// Fractal sum of `octaves` value noises, normalised to [0, 1].
float fbm(float x, float y, int octaves, uint32_t seed)
{
    float sum = 0.0f, amplitude = 0.5f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        sum += amplitude * valueNoise(x, y, seed + uint32_t(o));
        norm += amplitude;
        x *= 2.03f;
        y *= 2.03f;
        amplitude *= 0.5f;
    }
    return sum / norm;
}

void storeRgb(uint8_t* pixel, glm::vec3 rgb)
{
    rgb = glm::clamp(rgb, 0.0f, 1.0f) * 255.0f + 0.5f;
    pixel[0] = uint8_t(rgb.r);
    pixel[1] = uint8_t(rgb.g);
    pixel[2] = uint8_t(rgb.b);
}

// ---- the painting ---------------------------------------------------------------

// 5x7 glyphs for the letters of kPaintingText; each row is 5 bits, MSB on the left.
struct Glyph {
    char letter;
    std::array<uint8_t, 7> rows;
};
constexpr std::array<Glyph, 15> kFont = {{
    {'A', {0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'D', {0x1E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1E}},
    {'E', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}},
    {'F', {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10}},
    {'G', {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}},
    {'H', {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11}},
    {'I', {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}},
    {'N', {0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x11}},
    {'O', {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}},
    {'P', {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10}},
    {'R', {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11}},
    {'S', {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}},
    {'T', {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'Y', {0x11, 0x11, 0x0A, 0x04, 0x04, 0x04, 0x04}},
}};
constexpr std::string_view kPaintingText = "LIGHT FIELD DISPLAY POINT RENDERING ";

bool glyphDot(char letter, int gx, int gy)
{
    for (const Glyph& glyph : kFont)
        if (glyph.letter == letter)
            return (glyph.rows[size_t(gy)] >> (4 - gx)) & 1u;
    return false; // space
}

constexpr std::array<glm::vec3, 7> kBandPalette = {{
    {0.10f, 0.18f, 0.45f}, // ultramarine
    {0.85f, 0.62f, 0.20f}, // ochre
    {0.70f, 0.12f, 0.15f}, // crimson
    {0.10f, 0.50f, 0.48f}, // teal
    {0.93f, 0.88f, 0.74f}, // cream
    {0.40f, 0.22f, 0.55f}, // violet
    {0.45f, 0.50f, 0.18f}, // olive
}};

glm::vec3 paintingPixel(int x, int y, int size)
{
    const float s = float(size);
    const float u = (float(x) + 0.5f) / s, v = (float(y) + 0.5f) / s;
    const float twoPi = 2.0f * glm::pi<float>();

    // Text panel: rows of 5x7 glyphs on paper. A glyph dot is max(1, size/2048) pixels,
    // so at 2048 and below the letters are pixel-sharp and alias when minified.
    if (u > 0.06f && u < 0.50f && v > 0.64f && v < 0.93f) {
        const int dot = std::max(1, size / 2048);
        const int x0 = int(0.08f * s), y0 = int(0.66f * s);
        const int px = x - x0, py = y - y0;
        const glm::vec3 paper(0.95f, 0.93f, 0.86f), ink(0.15f, 0.10f, 0.08f);
        // Only whole glyphs: lines and columns that fit inside the panel's margins.
        const int lines = (int(0.91f * s) - y0) / (10 * dot);
        const int columns = (int(0.48f * s) - x0) / (6 * dot);
        if (px < 0 || py < 0)
            return paper;
        const int line = py / (10 * dot), column = px / (6 * dot);
        if (line >= lines || column >= columns)
            return paper;
        const int gx = (px / dot) % 6, gy = (py / dot) % 10;
        if (gx >= 5 || gy >= 7)
            return paper;
        const size_t at = (size_t(line) * 7 + size_t(column)) % kPaintingText.size();
        return glyphDot(kPaintingText[at], gx, gy) ? ink : paper;
    }

    // Background: wavy colour bands with soft edges and horizontal brush strokes.
    const float t = v * 7.0f + 0.35f * std::sin(twoPi * (1.3f * u + 0.2f)) +
                    0.08f * std::sin(twoPi * (5.0f * u + 3.0f * v));
    const float bandF = std::floor(t);
    const int band = int(bandF) + 7; // t > -1, keep it non-negative
    const float edge = glm::smoothstep(0.97f, 1.0f, t - bandF);
    glm::vec3 colour = glm::mix(kBandPalette[size_t(band % 7)], kBandPalette[size_t((band + 1) % 7)],
                                edge);
    colour *= 0.82f + 0.3f * valueNoise(u * 48.0f, v * 6.0f, 11u);

    // Pixel-scale pattern per band: checker (4 px), diagonal stripes (3 px), hairlines.
    switch (band % 3) {
    case 0: colour *= ((x >> 1) ^ (y >> 1)) & 1 ? 1.12f : 0.82f; break;
    case 1: colour *= (x + 2 * y) % 3 == 0 ? 0.7f : 1.0f; break;
    default: colour *= x % 5 == 0 ? 0.75f : 1.0f; break;
    }

    // A soft sun disc.
    const float sun = glm::length(glm::vec2(u - 0.24f, v - 0.22f));
    colour = glm::mix(colour, glm::vec3(1.0f, 0.86f, 0.45f), 1.0f - glm::smoothstep(0.10f, 0.13f, sun));

    // Zone plate medallion: phase = pi r^2 / (2R), so the local frequency r / (2R)
    // cycles per pixel reaches Nyquist (0.5) at the rim r = R.
    const float radius = 0.2f * s;
    const float dx = float(x) + 0.5f - 0.72f * s, dy = float(y) + 0.5f - 0.30f * s;
    const float r2 = dx * dx + dy * dy;
    if (r2 < radius * radius) {
        const float value = 0.5f + 0.5f * std::cos(glm::pi<float>() * r2 / (2.0f * radius));
        colour = glm::mix(glm::vec3(0.05f, 0.05f, 0.12f), glm::vec3(0.95f, 0.80f, 0.40f), value);
    } else if (r2 < (radius * 1.04f) * (radius * 1.04f)) {
        colour = glm::vec3(0.08f, 0.06f, 0.05f);
    }

    // Hairline grid every 128 pixels.
    if (x % 128 == 0 || y % 128 == 0)
        colour *= 0.55f;
    return colour;
}

// ---- the floor ------------------------------------------------------------------

constexpr float kGroutHalfWidth = 0.006f; // metres
constexpr float kBevel = 0.012f;          // metres
constexpr float kTileRelief = 0.003f;     // metres

// Distance (m) from a floor point (X, Z in metres) to the nearest tile edge.
float distanceToGroutLine(float X, float Z)
{
    const float fx = X - std::floor(X), fz = Z - std::floor(Z);
    return std::min(std::min(fx, 1.0f - fx), std::min(fz, 1.0f - fz));
}

float floorHeight(float X, float Z)
{
    const float d = distanceToGroutLine(X, Z);
    return kTileRelief * glm::smoothstep(kGroutHalfWidth, kGroutHalfWidth + kBevel, d) +
           0.0002f * valueNoise(X * 40.0f, Z * 40.0f, 5u);
}

// Floor position in metres of pixel (x, y) of a size^2 floor texture.
glm::vec2 floorMetres(float x, float y, int size)
{
    return {x / float(size) * float(kFloorTilesU), y / float(size) * float(kFloorTilesV)};
}

glm::vec3 floorColour(float X, float Z)
{
    if (distanceToGroutLine(X, Z) < kGroutHalfWidth)
        return {0.42f, 0.40f, 0.37f};
    const int ix = int(std::floor(X)), iz = int(std::floor(Z));
    const bool light = ((ix + iz) & 1) == 0;
    // Marble veins: thin ridges of a turbulent sine.
    const float m = std::sin(6.0f * (0.7f * X + 0.4f * Z) + 5.0f * fbm(2.0f * X, 2.0f * Z, 4, 21u));
    const float vein = std::pow(1.0f - std::abs(m), 8.0f);
    const float jitter = 0.94f + 0.06f * hashUnit(ix, iz, 3u);
    const glm::vec3 colour = light ? glm::vec3(0.88f, 0.86f, 0.82f) - 0.35f * vein
                                   : glm::vec3(0.16f, 0.22f, 0.20f) + 0.40f * vein;
    return colour * jitter;
}

} // namespace

void writePngRgb8(const std::filesystem::path& path, int width, int height, const RowFiller& fill)
{
    if (width <= 0 || height <= 0)
        throw std::runtime_error(path.string() + ": invalid image size");
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out)
        throw std::runtime_error(path.string() + ": cannot create PNG writer: " +
                                 oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    // note: for big images zlib level 3 saves ~25% of the total time against the default
    // 6 for ~7% more bytes (measured on the 8192^2 painting).
    spec.attribute("png:compressionLevel", width * height > 4096 * 4096 ? 3 : 6);
    if (!out->open(path.string(), spec))
        throw std::runtime_error(path.string() + ": cannot open for writing: " +
                                 oneLine(out->geterror()));

    // Double-buffered: the next strip is computed while the current one is compressed.
    const size_t stripBytes = size_t(kStripRows) * size_t(width) * 3;
    std::vector<uint8_t> current(stripBytes), next(stripBytes);
    auto rowsAt = [&](int y0) { return std::min(kStripRows, height - y0); };
    fillStrip(fill, width, 0, rowsAt(0), current.data());
    for (int y0 = 0; y0 < height; y0 += kStripRows) {
        std::future<void> pending;
        const int nextY0 = y0 + kStripRows;
        if (nextY0 < height)
            pending = std::async(std::launch::async, [&, nextY0] {
                fillStrip(fill, width, nextY0, rowsAt(nextY0), next.data());
            });
        const bool ok = out->write_scanlines(y0, y0 + rowsAt(y0), 0, OIIO::TypeDesc::UINT8,
                                             current.data());
        if (pending.valid())
            pending.get();
        if (!ok)
            throw std::runtime_error(path.string() + ": cannot write: " + oneLine(out->geterror()));
        std::swap(current, next);
    }
    if (!out->close())
        throw std::runtime_error(path.string() + ": cannot finish: " + oneLine(out->geterror()));
}

void writePaintingTexture(const std::filesystem::path& path, int size)
{
    writePngRgb8(path, size, size, [size](int y0, int rowCount, uint8_t* pixels) {
        for (int y = y0; y < y0 + rowCount; ++y)
            for (int x = 0; x < size; ++x, pixels += 3)
                storeRgb(pixels, paintingPixel(x, y, size));
    });
}

void writeFloorBaseColor(const std::filesystem::path& path, int size)
{
    writePngRgb8(path, size, size, [size](int y0, int rowCount, uint8_t* pixels) {
        for (int y = y0; y < y0 + rowCount; ++y)
            for (int x = 0; x < size; ++x, pixels += 3) {
                const glm::vec2 m = floorMetres(float(x) + 0.5f, float(y) + 0.5f, size);
                storeRgb(pixels, floorColour(m.x, m.y));
            }
    });
}

void writeFloorNormal(const std::filesystem::path& path, int size)
{
    writePngRgb8(path, size, size, [size](int y0, int rowCount, uint8_t* pixels) {
        // One pixel in metres along u (+X) and v (+Z).
        const float stepX = float(kFloorTilesU) / float(size);
        const float stepZ = float(kFloorTilesV) / float(size);
        for (int y = y0; y < y0 + rowCount; ++y)
            for (int x = 0; x < size; ++x, pixels += 3) {
                const glm::vec2 m = floorMetres(float(x) + 0.5f, float(y) + 0.5f, size);
                // Central differences of the height field.
                const float dhdX = (floorHeight(m.x + stepX, m.y) - floorHeight(m.x - stepX, m.y)) /
                                   (2.0f * stepX);
                const float dhdZ = (floorHeight(m.x, m.y + stepZ) - floorHeight(m.x, m.y - stepZ)) /
                                   (2.0f * stepZ);
                // Tangent space: +X = +u, +Y = image-up = -v = -Z, so dh/dY = -dh/dZ and
                // n = normalize(-dh/dX, -dh/dY, 1).
                const glm::vec3 n = glm::normalize(glm::vec3(-dhdX, dhdZ, 1.0f));
                storeRgb(pixels, n * 0.5f + 0.5f);
            }
    });
}

void writeFloorMetallicRoughness(const std::filesystem::path& path, int size)
{
    writePngRgb8(path, size, size, [size](int y0, int rowCount, uint8_t* pixels) {
        for (int y = y0; y < y0 + rowCount; ++y)
            for (int x = 0; x < size; ++x, pixels += 3) {
                const glm::vec2 m = floorMetres(float(x) + 0.5f, float(y) + 0.5f, size);
                const bool grout = distanceToGroutLine(m.x, m.y) < kGroutHalfWidth;
                const bool light = ((int(std::floor(m.x)) + int(std::floor(m.y))) & 1) == 0;
                const float wear = valueNoise(m.x * 6.0f, m.y * 6.0f, 9u);
                const float roughness = grout ? 0.95f : (light ? 0.15f : 0.28f) + 0.15f * wear;
                const float occlusion = grout ? 0.55f : 1.0f;
                storeRgb(pixels, glm::vec3(occlusion, roughness, 0.0f)); // B: not metal
            }
    });
}

void writePlasterTexture(const std::filesystem::path& path, int size)
{
    writePngRgb8(path, size, size, [size](int y0, int rowCount, uint8_t* pixels) {
        const float s = float(size);
        for (int y = y0; y < y0 + rowCount; ++y)
            for (int x = 0; x < size; ++x, pixels += 3) {
                const float u = (float(x) + 0.5f) / s, v = (float(y) + 0.5f) / s;
                const float mottle = fbm(u * 24.0f, v * 24.0f, 5, 31u);
                const float streak = valueNoise(u * 5.0f, v * 70.0f, 41u);
                const glm::vec3 colour =
                    glm::vec3(0.80f, 0.76f, 0.68f) * (0.90f + 0.16f * mottle + 0.05f * streak);
                storeRgb(pixels, colour);
            }
    });
}

} // namespace lfd::samples
