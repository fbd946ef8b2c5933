// lfd_image_metrics: CPU-only full-reference image metrics for comparing a test image with
// a reference of the same size (a renderer's view or EIA against another renderer's or the
// gold standard's): RMSE, PSNR, SSIM (Wang et al. 2004), LDR FLIP (Andersson et al. 2020),
// and a heat-map writer for FLIP error maps. Used by `lfd-compare` (docs/compare.md).
//
// Images are RGB, row 0 = top, channel values on the 8-bit scale 0..255 (stored as float so
// that 8-bit images convert exactly and float images keep their fractional values). Alpha
// is ignored (not composited), grey is replicated into R, G and B.
//
// Every metric takes (reference, test) and throws std::invalid_argument when the images
// differ in size or a mask does not match; masked metrics also throw when the mask selects
// nothing. File functions throw ImageError with one line naming the file and the problem.
//
// Every metric also takes the player's 8-bit Image (image.h: views, EIAs, image files),
// converted exactly to RgbImage: one implementation serves the player, lfd-bench, the
// tests and lfd-compare.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include "image.h"
#include <span>
#include <stdexcept>
#include <vector>

namespace lfd::metrics {

// ---- images -------------------------------------------------------------------------

struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3 values, 0..255 scale, row 0 = top

    size_t pixelCount() const { return size_t(width) * size_t(height); }
};

// From interleaved 8-bit pixels with 1..4 channels (1 = grey, 2 = grey + alpha, 3 = RGB,
// 4 = RGBA; alpha dropped). Throws std::invalid_argument for a bad size or channel count.
RgbImage rgbFromPixels8(const uint8_t* pixels, int width, int height, int channels);
// From the 8-bit Image (values exact); throws std::invalid_argument like rgbFromPixels8, and
// when the pixel buffer does not hold width x height x channels bytes.
RgbImage rgbFromImage(const Image& image);
// From interleaved float pixels with 1..4 channels where 1.0 is full scale (multiplied by
// 255; values outside 0..1 are kept, see each metric for how it treats them).
RgbImage rgbFromPixelsFloat(const float* pixels, int width, int height, int channels);

// Reads any image image_file.h decodes. 8-bit files convert exactly; 16-bit and HDR files are read
// as float with 1.0 = 255.
RgbImage readRgbImage(const std::filesystem::path& path);
// Writes interleaved RGB8 (width * height * 3 bytes); the format follows the extension.
// Atomic: written to a temporary file in the target directory and renamed over the target,
// so a failed write leaves nothing at `path` or beside it.
void writeRgb8Image(const std::filesystem::path& path, std::span<const uint8_t> rgb, int width,
                    int height);

// ---- RMSE and PSNR ------------------------------------------------------------------

// Root mean square error over all R, G and B values, on the 0..255 scale.
double rmse(const RgbImage& reference, const RgbImage& test);
// The same over the pixels whose mask byte is non-zero (mask: width * height bytes).
double rmse(const RgbImage& reference, const RgbImage& test, std::span<const uint8_t> mask);
// 20 log10(255 / rmse) in dB; +infinity for rmse 0 (identical images). JSON has no
// infinity: lfd-compare prints "inf" in text and null in JSON.
double psnrFromRmse(double rmse);
double psnr(const RgbImage& reference, const RgbImage& test);
double rmse(const Image& reference, const Image& test);
double psnr(const Image& reference, const Image& test);
// The largest difference of one colour value, 0..255.
int maxAbsDiff(const Image& reference, const Image& test);
// Writes |a - b| per colour value, multiplied by `gain` and clamped, as an RGB8 image
// (black = identical), for inspecting golden-image failures.
void writeDiffImage(const std::filesystem::path& path, const Image& a, const Image& b, float gain = 8.0f);

// ---- SSIM (Wang, Bovik, Sheikh & Simoncelli 2004, "Image quality assessment: from error
// visibility to structural similarity", IEEE TIP 13(4)) -------------------------------
//
// Mean SSIM index (their eq. 13) over the local windows:
//   SSIM = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))
// with an 11x11 circular-symmetric Gaussian weighting window of sigma 1.5 (normalised to
// sum 1), C1 = (K1 L)^2, C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, L = 255, as in the paper.
// Colour: computed on Rec. 601 luma Y' = 0.299 R + 0.587 G + 0.114 B of the stored values.
// Why luma and not an average over R, G, B: the paper defines and evaluates SSIM on
// greyscale images, and colour images are usually reduced to exactly this luma (MATLAB's
// rgb2gray) before applying it; luma also weights channels as the eye does.
// Windows: only positions where the whole window lies inside the image (no padding, as the
// paper's reference code), and no automatic downsampling; images smaller than 11 pixels
// use the largest odd window that fits (same sigma, renormalised).
double ssim(const RgbImage& reference, const RgbImage& test);
// Mean SSIM over the window positions whose centre pixel has a non-zero mask byte.
double ssim(const RgbImage& reference, const RgbImage& test, std::span<const uint8_t> mask);
double ssim(const Image& reference, const Image& test);

// ---- LDR FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom & Fairchild 2020,
// "FLIP: A Difference Evaluator for Alternating Images", Proc. ACM CGIT 3(2), HPG) ------
//
// Per-pixel perceived difference in 0..1 (0 = identical) for images viewed at `ppd` pixels
// per degree of visual angle. Inputs are sRGB-encoded; values are clamped to 0..255 first.
// Colour pipeline: sRGB -> linear RGB -> XYZ (D65) -> YCxCz; each channel filtered with the
// paper's contrast sensitivity functions (sums of Gaussians, constants in flip.cpp); back to
// linear RGB, clamped to [0,1], -> CIELAB with the Hunt adjustment (a*, b* scaled by
// 0.01 L*); HyAB distance; raised to qc = 0.7 and mapped to [0,1] with pc = 0.4, pt = 0.95
// relative to the HyAB^qc distance between Hunt-adjusted green and blue.
// Feature pipeline: on the unfiltered luminance Y/Yn, first (edge) and second (point)
// derivative-of-Gaussian filters of sigma 0.5 * 0.082 degrees; feature difference
// (max(|edge_ref - edge_test|, |point_ref - point_test|) / sqrt(2))^qf with qf = 0.5.
// Error = colour_error ^ (1 - feature_error). Borders replicate the edge pixels.
// ppd must lie in (0, 10000] (std::invalid_argument otherwise).
double defaultFlipPixelsPerDegree();
std::vector<float> flipErrorMap(const RgbImage& reference, const RgbImage& test,
                                double ppd = defaultFlipPixelsPerDegree());
// The mean of flipErrorMap over all pixels (the paper's pooled FLIP value).
double flip(const RgbImage& reference, const RgbImage& test,
            double ppd = defaultFlipPixelsPerDegree());

// Pixels per degree of a viewer at `distanceM` from a screen `screenWidthM` wide with
// `screenPixelsX` pixels across: distance * (pixels / width) * (pi / 180).
// defaultFlipPixelsPerDegree() is FLIP's default observer: 0.7 m from a 0.7 m wide
// 3840-pixel monitor, about 67.02 PPD.
double pixelsPerDegree(double distanceM, double screenWidthM, double screenPixelsX);

// ---- heat map -----------------------------------------------------------------------

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8&) const = default;
};

// The "magma" colour map (Smith & van der Walt, matplotlib, CC0), as the FLIP paper shows
// its error maps: 0 = near black (0, 0, 4), 1 = pale yellow (252, 253, 191). t is clamped
// to 0..1 (NaN counts as 1, so a broken value stands out).
Rgb8 magma(double t);
// One magma colour per value, interleaved RGB8 (3 bytes per value).
std::vector<uint8_t> heatMapRgb8(std::span<const float> values);
// Writes the heat map of a width x height map of 0..1 values (e.g. flipErrorMap), atomically.
void writeHeatMap(const std::filesystem::path& path, std::span<const float> values, int width,
                  int height);

} // namespace lfd::metrics
