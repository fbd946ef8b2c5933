// LDR FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom & Fairchild 2020, "FLIP:
// A Difference Evaluator for Alternating Images", Proc. ACM CGIT 3(2)), implemented from
// the paper's description: a colour pipeline (contrast-sensitivity filtering in YCxCz,
// Hunt-adjusted CIELAB, HyAB distance, power compression) and a feature pipeline (edge and
// point detection on luminance), combined per pixel as colour ^ (1 - feature).
#include "colour_spaces.h"
#include "image_checks.h"
#include "parallel.h"
#include "separable_filter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace lfd::metrics {

namespace {

using detail::Plane;
using detail::Vec3;

// Colour-pipeline constants: the error compression exponent qc, and the mapping of the
// compressed error to [0, 1]: errors below pc * cmax take [0, pt], the rest (pt, 1].
constexpr double kQc = 0.7;
constexpr double kPc = 0.4;
constexpr double kPt = 0.95;
// Feature-pipeline constants: the detectors' Gaussian has a standard deviation of 0.5 * w
// degrees with w = 0.082 degrees, and the feature difference is raised to qf = 0.5.
constexpr double kFeatureWidthDegrees = 0.082;
constexpr double kQf = 0.5;
constexpr double kMaxPpd = 10000.0; // beyond any display; keeps the kernels finite

// The per-pixel steps run over the cores in bands of pixels (common/parallel.h); each
// pixel's value is computed as it would be in one loop.
constexpr size_t kBandPixels = size_t(1) << 16;
template <typename PerPixel>
void forEachPixel(size_t n, PerPixel perPixel)
{
    forEachBand(n, kBandPixels, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i)
            perPixel(i);
    });
}

// Contrast sensitivity functions as spatial filters: per YCxCz channel a sum of two
// Gaussians S(x) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i), x in degrees of visual
// angle.
struct CsfTerm {
    double a, b;
};
constexpr std::array<std::array<CsfTerm, 2>, 3> kCsf = {{
    {{{1.0, 0.0047}, {0.0, 1.0e-5}}},   // achromatic (Y)
    {{{1.0, 0.0053}, {0.0, 1.0e-5}}},   // red-green (Cx)
    {{{34.1, 0.04}, {13.5, 0.025}}},    // blue-yellow (Cz)
}};

// All three filters share one square support whose radius covers three standard deviations
// of the widest Gaussian: b = 0.04 has sigma = sqrt(b / (2 pi^2)) degrees.
int csfRadius(double ppd)
{
    double widest = 0.0;
    for (const auto& channel : kCsf)
        for (const CsfTerm& t : channel)
            widest = std::max(widest, t.b);
    const double sigmaDegrees = std::sqrt(widest / (2.0 * std::numbers::pi * std::numbers::pi));
    return int(std::ceil(3.0 * sigmaDegrees * ppd));
}

// One Gaussian term of a CSF filter as a normalised 1D kernel, with its share of the whole
// 2D kernel's weight. Each 2D term is separable, a_i sqrt(pi/b_i) k_i(x) k_i(y), so the
// (2r+1)^2 kernel normalised to sum 1 equals the weighted sum of the terms' normalised
// separable kernels, with weights a_i sqrt(pi/b_i) (sum k_i)^2 / total.
struct CsfComponent {
    std::vector<float> taps;
    double weight = 0.0;
};

std::vector<CsfComponent> csfComponents(const std::array<CsfTerm, 2>& terms, double ppd)
{
    const int r = csfRadius(ppd);
    const double pi = std::numbers::pi;
    std::vector<CsfComponent> components;
    std::vector<double> masses;
    double total = 0.0;
    for (const CsfTerm& t : terms) {
        if (t.a == 0.0)
            continue;
        std::vector<double> k(size_t(2 * r + 1));
        double sum = 0.0;
        for (int i = -r; i <= r; ++i) {
            const double x = double(i) / ppd; // degrees
            k[size_t(i + r)] = std::exp(-pi * pi * x * x / t.b);
            sum += k[size_t(i + r)];
        }
        CsfComponent c;
        for (double v : k)
            c.taps.push_back(float(v / sum));
        components.push_back(std::move(c));
        masses.push_back(t.a * std::sqrt(pi / t.b) * sum * sum);
        total += masses.back();
    }
    for (size_t i = 0; i < components.size(); ++i)
        components[i].weight = masses[i] / total;
    return components;
}

// Edge and point detectors: first and second derivatives of a Gaussian with sigma =
// 0.5 w ppd pixels, radius ceil(3 sigma). The 2D detector along x is d(x) g(y);
// its positive weights are normalised to sum 1 and its negative weights to sum -1. That
// normalisation factors into d with the same rule and g normalised to sum 1, so the
// detectors are applied separably. Along y the roles swap.
struct FeatureKernels {
    std::vector<float> gaussian, edge, point;
};

std::vector<float> normaliseSigned(const std::vector<double>& k)
{
    double positive = 0.0, negative = 0.0;
    for (double v : k)
        (v > 0.0 ? positive : negative) += std::abs(v);
    std::vector<float> out;
    for (double v : k) {
        const double sum = v > 0.0 ? positive : negative;
        out.push_back(sum > 0.0 ? float(v / sum) : 0.0f);
    }
    return out;
}

FeatureKernels featureKernels(double ppd)
{
    const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
    const int r = int(std::ceil(3.0 * sigma));
    std::vector<double> g, d1, d2;
    double gSum = 0.0;
    for (int i = -r; i <= r; ++i) {
        const double x = double(i);
        const double gauss = std::exp(-x * x / (2.0 * sigma * sigma));
        g.push_back(gauss);
        d1.push_back(-x * gauss);
        d2.push_back((x * x / (sigma * sigma) - 1.0) * gauss);
        gSum += gauss;
    }
    FeatureKernels kernels;
    for (double v : g)
        kernels.gaussian.push_back(float(v / gSum));
    kernels.edge = normaliseSigned(d1);
    kernels.point = normaliseSigned(d2);
    return kernels;
}

// sRGB decoding of a 0..255 value (clamped: LDR FLIP takes inputs in [0, 1]); 8-bit
// values come from a table.
double decodeSrgb(float value)
{
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (size_t i = 0; i < t.size(); ++i)
            t[i] = detail::srgbToLinear(double(i) / 255.0);
        return t;
    }();
    const float v = std::clamp(value, 0.0f, 255.0f);
    if (v == std::floor(v))
        return table[size_t(v)];
    return detail::srgbToLinear(double(v) / 255.0);
}

// What each image contributes: its filtered, Hunt-adjusted CIELAB and its edge and point
// feature magnitudes.
struct Preprocessed {
    std::array<Plane, 3> lab;
    Plane edges, points;
};

// sqrt(alongX^2 + alongY^2) of a detector applied along x (derivative across columns,
// Gaussian down rows) and along y (the transpose).
void featureMagnitude(const Plane& luminance, const std::vector<float>& derivative,
                      const std::vector<float>& gaussian, Plane& scratch, Plane& alongX,
                      Plane& alongY, Plane& out)
{
    detail::filterSeparable(luminance, derivative, gaussian, scratch, alongX);
    detail::filterSeparable(luminance, gaussian, derivative, scratch, alongY);
    out = Plane{luminance.width, luminance.height, std::vector<float>(luminance.values.size())};
    forEachPixel(out.values.size(), [&](size_t i) {
        out.values[i] = std::sqrt(alongX.values[i] * alongX.values[i] + alongY.values[i] * alongY.values[i]);
    });
}

// Planes reused by both images' filter passes (panel-size planes are 33 MB each).
struct Workspace {
    Plane luminance, scratch, first, second;
};

Preprocessed preprocess(const RgbImage& image, double ppd, const FeatureKernels& features,
                        Workspace& work)
{
    const int w = image.width, h = image.height;
    const size_t n = image.pixelCount();

    // Step 1: sRGB -> linear RGB -> XYZ -> YCxCz, one plane per channel.
    std::array<Plane, 3> ycxcz;
    for (Plane& p : ycxcz)
        p = Plane{w, h, std::vector<float>(n)};
    forEachPixel(n, [&](size_t i) {
        const Vec3 linear = {decodeSrgb(image.rgb[i * 3]), decodeSrgb(image.rgb[i * 3 + 1]),
                             decodeSrgb(image.rgb[i * 3 + 2])};
        const Vec3 v = detail::xyzToYcxcz(detail::linearRgbToXyz(linear));
        for (size_t c = 0; c < 3; ++c)
            ycxcz[c].values[i] = float(v[c]);
    });

    Preprocessed out;

    // Step 2 (feature pipeline): edges and points on the unfiltered luminance Y/Yn, which
    // is (Y + 16) / 116 of YCxCz and lies in [0, 1].
    Plane& luminance = work.luminance;
    Plane& scratch = work.scratch;
    Plane& first = work.first;
    Plane& second = work.second;
    luminance.width = w;
    luminance.height = h;
    luminance.values.resize(n);
    forEachPixel(n, [&](size_t i) { luminance.values[i] = (ycxcz[0].values[i] + 16.0f) / 116.0f; });
    featureMagnitude(luminance, features.edge, features.gaussian, scratch, first, second, out.edges);
    featureMagnitude(luminance, features.point, features.gaussian, scratch, first, second, out.points);

    // Step 3 (colour pipeline): CSF filtering of each opponent channel; a channel whose
    // filter has two Gaussian terms is the weighted sum of the two filtered copies.
    for (size_t c = 0; c < 3; ++c) {
        const std::vector<CsfComponent> components = csfComponents(kCsf[c], ppd);
        detail::filterSeparable(ycxcz[c], components[0].taps, components[0].taps, scratch, first);
        if (components.size() > 1) {
            forEachPixel(n, [&](size_t i) { first.values[i] *= float(components[0].weight); });
            for (size_t k = 1; k < components.size(); ++k) {
                detail::filterSeparable(ycxcz[c], components[k].taps, components[k].taps, scratch,
                                        second);
                forEachPixel(n, [&](size_t i) { first.values[i] += float(components[k].weight) * second.values[i]; });
            }
        }
        std::swap(ycxcz[c], first);
    }

    // Step 4: back to linear RGB, clamped to [0, 1] (filtering can leave the gamut), then
    // CIELAB with the Hunt adjustment, in place.
    forEachPixel(n, [&](size_t i) {
        Vec3 rgb = detail::xyzToLinearRgb(detail::ycxczToXyz(
            {ycxcz[0].values[i], ycxcz[1].values[i], ycxcz[2].values[i]}));
        for (double& v : rgb)
            v = std::clamp(v, 0.0, 1.0);
        const Vec3 lab = detail::huntAdjust(detail::xyzToLab(detail::linearRgbToXyz(rgb)));
        for (size_t c = 0; c < 3; ++c)
            ycxcz[c].values[i] = float(lab[c]);
    });
    out.lab = std::move(ycxcz);
    return out;
}

Vec3 huntLabOfLinearRgb(const Vec3& rgb)
{
    return detail::huntAdjust(detail::xyzToLab(detail::linearRgbToXyz(rgb)));
}

// Maps a HyAB distance to the colour error in [0, 1]: compress with qc, then
// map [0, pc cmax) linearly onto [0, pt) and [pc cmax, cmax] onto [pt, 1], where cmax is
// the compressed distance between Hunt-adjusted pure green and pure blue, the largest in
// the gamut.
double colourError(double hyabDistance)
{
    static const double cmax = std::pow(
        detail::hyab(huntLabOfLinearRgb({0.0, 1.0, 0.0}), huntLabOfLinearRgb({0.0, 0.0, 1.0})),
        kQc);
    const double e = std::pow(hyabDistance, kQc);
    const double knee = kPc * cmax;
    if (e < knee)
        return e * kPt / knee;
    return kPt + (e - knee) / (cmax - knee) * (1.0 - kPt);
}

} // namespace

double pixelsPerDegree(double distanceM, double screenWidthM, double screenPixelsX)
{
    return distanceM * (screenPixelsX / screenWidthM) * (std::numbers::pi / 180.0);
}

double defaultFlipPixelsPerDegree() { return pixelsPerDegree(0.7, 0.7, 3840.0); }

std::vector<float> flipErrorMap(const RgbImage& reference, const RgbImage& test, double ppd)
{
    detail::requireSameSize(reference, test, "flip");
    if (!(ppd > 0.0 && ppd <= kMaxPpd))
        throw std::invalid_argument("flip: pixels per degree must be in (0, " +
                                    std::to_string(int(kMaxPpd)) + "], got " +
                                    std::to_string(ppd));
    const FeatureKernels features = featureKernels(ppd);
    Workspace work;
    const Preprocessed ref = preprocess(reference, ppd, features, work);
    const Preprocessed tst = preprocess(test, ppd, features, work);
    work = Workspace{};

    std::vector<float> error(reference.pixelCount());
    forEachPixel(error.size(), [&](size_t i) {
        const Vec3 a = {ref.lab[0].values[i], ref.lab[1].values[i], ref.lab[2].values[i]};
        const Vec3 b = {tst.lab[0].values[i], tst.lab[1].values[i], tst.lab[2].values[i]};
        const double colour = colourError(detail::hyab(a, b));

        const double edgeDifference = std::abs(ref.edges.values[i] - tst.edges.values[i]);
        const double pointDifference = std::abs(ref.points.values[i] - tst.points.values[i]);
        const double feature =
            std::pow(std::max(edgeDifference, pointDifference) / std::numbers::sqrt2, kQf);

        error[i] = float(std::pow(colour, 1.0 - feature));
    });
    return error;
}

double flip(const RgbImage& reference, const RgbImage& test, double ppd)
{
    const std::vector<float> error = flipErrorMap(reference, test, ppd);
    double sum = 0.0;
    for (float e : error)
        sum += e;
    return sum / double(error.size());
}

} // namespace lfd::metrics
