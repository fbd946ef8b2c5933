// Colour transforms for LDR FLIP; see colour_spaces.h.
#include "colour_spaces.h"

#include <algorithm>
#include <cmath>

namespace lfd::metrics::detail {

namespace {

using Mat3 = std::array<Vec3, 3>;

// Linear sRGB -> XYZ for D65 (IEC 61966-2-1 primaries and white).
constexpr Mat3 kRgbToXyz = {{{0.4124564, 0.3575761, 0.1804375},
                             {0.2126729, 0.7151522, 0.0721750},
                             {0.0193339, 0.1191920, 0.9503041}}};

Vec3 multiply(const Mat3& m, const Vec3& v)
{
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// The exact inverse of kRgbToXyz (adjugate / determinant), so the round trip through XYZ
// that FLIP makes after filtering adds no error of its own.
Mat3 inverse(const Mat3& m)
{
    const double a = m[0][0], b = m[0][1], c = m[0][2];
    const double d = m[1][0], e = m[1][1], f = m[1][2];
    const double g = m[2][0], h = m[2][1], i = m[2][2];
    const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    return {{{(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det},
             {(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det},
             {(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det}}};
}

const Mat3& xyzToRgbMatrix()
{
    static const Mat3 m = inverse(kRgbToXyz);
    return m;
}

// CIELAB's companding function f(t) (CIE 15:2004): cube root above (6/29)^3, linear below.
double labF(double t)
{
    constexpr double delta = 6.0 / 29.0;
    if (t > delta * delta * delta)
        return std::cbrt(t);
    return t / (3.0 * delta * delta) + 4.0 / 29.0;
}

} // namespace

double srgbToLinear(double encoded)
{
    if (encoded <= 0.04045)
        return encoded / 12.92;
    return std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear)
{
    const double c = linear > 0.0 ? std::min(linear, 1.0) : 0.0; // NaN fails the test: 0
    if (c <= 0.0031308)
        return c * 12.92;
    return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

Vec3 linearRgbToXyz(const Vec3& rgb) { return multiply(kRgbToXyz, rgb); }

Vec3 xyzToLinearRgb(const Vec3& xyz) { return multiply(xyzToRgbMatrix(), xyz); }

const Vec3& whitePointXyz()
{
    static const Vec3 white = linearRgbToXyz({1.0, 1.0, 1.0});
    return white;
}

Vec3 xyzToYcxcz(const Vec3& xyz)
{
    const Vec3& w = whitePointXyz();
    const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxczToXyz(const Vec3& ycxcz)
{
    const Vec3& w = whitePointXyz();
    const double y = (ycxcz[0] + 16.0) / 116.0;
    const double x = y + ycxcz[1] / 500.0;
    const double z = y - ycxcz[2] / 200.0;
    return {x * w[0], y * w[1], z * w[2]};
}

Vec3 xyzToLab(const Vec3& xyz)
{
    const Vec3& w = whitePointXyz();
    const double fx = labF(xyz[0] / w[0]), fy = labF(xyz[1] / w[1]), fz = labF(xyz[2] / w[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Vec3 huntAdjust(const Vec3& lab)
{
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

double hyab(const Vec3& a, const Vec3& b)
{
    const double da = a[1] - b[1], db = a[2] - b[2];
    return std::abs(a[0] - b[0]) + std::sqrt(da * da + db * db);
}

} // namespace lfd::metrics::detail
