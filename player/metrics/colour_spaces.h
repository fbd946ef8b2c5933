// The colour transforms LDR FLIP needs (Andersson et al. 2020, the colour
// pipeline): sRGB transfer function, linear sRGB <-> CIE XYZ (D65), XYZ <-> YCxCz (the
// opponent space FLIP filters in), XYZ -> CIELAB, the Hunt adjustment and the HyAB distance.
// Internal to lfd_image_metrics, except the sRGB transfer pair, which lfd_lighting's
// display levels use too (the C++ side of shaders/srgb.glsl).
#pragma once

#include <array>

namespace lfd::metrics::detail {

using Vec3 = std::array<double, 3>;

// IEC 61966-2-1 sRGB decoding of one channel in [0, 1].
double srgbToLinear(double encoded);
// IEC 61966-2-1 sRGB encoding of one channel, as shaders/srgb.glsl's linearToSrgb: the
// input clamped to [0, 1] first (NaN gives 0).
double linearToSrgb(double linear);

// Linear sRGB (Rec. 709 primaries, D65 white) to CIE XYZ and back. The white point used
// by the YCxCz and CIELAB conversions is linearRgbToXyz({1, 1, 1}), so sRGB white maps to
// exactly L* = 100, a* = b* = 0 and the two directions invert each other.
Vec3 linearRgbToXyz(const Vec3& rgb);
Vec3 xyzToLinearRgb(const Vec3& xyz);
const Vec3& whitePointXyz();

// YCxCz, the linearised CIELAB opponent space FLIP filters in:
// Y = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn).
Vec3 xyzToYcxcz(const Vec3& xyz);
Vec3 ycxczToXyz(const Vec3& ycxcz);

// CIE 1976 L*a*b* relative to whitePointXyz().
Vec3 xyzToLab(const Vec3& xyz);

// Hunt effect, as FLIP models it: chroma scaled by luminance, a* and b* times 0.01 L*.
Vec3 huntAdjust(const Vec3& lab);

// HyAB distance (Abasi et al. 2020, used by FLIP): |dL| + sqrt(da^2 + db^2).
double hyab(const Vec3& a, const Vec3& b);

} // namespace lfd::metrics::detail
