// The environment that lights every material (image-based lighting): an equirectangular
// panorama of linear RGB radiance, as a Radiance .hdr file from Poly Haven, Blender or
// three.js holds it, and the one mapping between its pixels and scene directions.
//
// Axes are the scene's (glTF 2.0: right-handed, +Y up, an asset's front faces +Z). The
// mapping is the one Blender's environment texture (Cycles' direction_to_equirectangular,
// with glTF's axes: Blender's -Y is glTF's +Z), three.js (`equirectUv`) and the glTF Sample
// Viewer use, so an HDRI that looks right there looks right here:
//   u = 0.5 + atan2(d.z, d.x) / (2 pi)    column u * width, from the left edge
//   v = acos(d.y) / pi                     row v * height, from the top
// Row 0 is the zenith (+Y), the middle row the horizon, the last row the nadir (-Y). The
// centre column faces +X, the column at u = 0.25 faces -Z, the one at u = 0.75 faces +Z
// (where glTF's default camera stands) and the left and right edges face -X. Seen from
// inside the panorama is not mirrored: looking along +X with +Y up, +Z is to the right,
// and so is the image's u = 0.75 column.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lfd::lighting {

struct Environment {
    uint32_t width = 0;     // columns: 360 degrees of azimuth
    uint32_t height = 0;    // rows: 180 degrees of polar angle, from +Y down
    std::vector<float> rgb; // width * height * 3 linear radiance values, row 0 = top (+Y)

    glm::vec3 texel(uint32_t x, uint32_t y) const
    {
        const float* p = rgb.data() + (size_t(y) * width + x) * 3;
        return {p[0], p[1], p[2]};
    }
};

// (u, v) in [0, 1]^2 of a direction (any length but zero), as in the header comment; the
// poles give u = 0.5.
glm::vec2 equirectFromDirection(glm::vec3 direction);
// The unit direction of (u, v); the inverse of equirectFromDirection.
glm::vec3 directionFromEquirect(glm::vec2 uv);

// Bilinear radiance in `direction`, texel (x, y)'s centre at ((x + 0.5) / width,
// (y + 0.5) / height): columns wrap around (u = 0 meets u = 1), rows clamp at the poles.
glm::vec3 sampleEnvironment(const Environment& environment, glm::vec3 direction);
// The same at (u, v) = equirectFromDirection(direction).
glm::vec3 sampleEnvironmentUv(const Environment& environment, glm::vec2 uv);

// The 2x2 box average (each half rounded down, at least 1; an odd last column or row
// joins the box before it, so every texel counts): a mip level for resampling.
Environment halveEnvironment(const Environment& environment);

// `--environment-rotation DEG`: the environment turned by DEG about +Y (right-handed, so
// +90 moves what was at +X, the image centre, to -Z). Lookups in scene direction d read
// the environment at environmentFromScene(DEG) * d (the rotation by -DEG).
glm::mat3 environmentFromScene(float rotationDegrees);

// Throws std::invalid_argument naming `name` unless width >= 2, height >= 1, the pixel
// vector holds width * height * 3 values and every value is finite and >= 0.
void validateEnvironment(const Environment& environment, const std::string& name);

} // namespace lfd::lighting
