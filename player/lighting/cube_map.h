// Cube maps exactly as OpenGL selects and samples them (OpenGL 4.5 core profile, section
// 8.13 "Cube Map Texture Selection", table 8.19), so the arrays here upload unchanged with
// glTextureSubImage3D (layer = face) or glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face):
//
//   face  major axis   sc     tc     ma
//   0 +X  rx > 0       -rz    -ry    rx
//   1 -X  rx < 0       +rz    -ry    rx
//   2 +Y  ry > 0       +rx    +rz    ry
//   3 -Y  ry < 0       +rx    -rz    ry
//   4 +Z  rz > 0       +rx    -ry    rz
//   5 -Z  rz < 0       -rx    -ry    rz
//   s = (sc / |ma| + 1) / 2,  t = (tc / |ma| + 1) / 2
//
// Texel (x, y) of a face of size n covers s in [x, x + 1) / n and t in [y, y + 1) / n; row
// y = 0 is t = 0, the first row glTexImage2D takes. Ties between axes of equal magnitude
// go to X over Y over Z, as GL's table order (implementations may differ on exact ties).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lfd::lighting {

constexpr uint32_t kCubeFaces = 6;

// A face and its (s, t) in [0, 1]^2.
struct CubeCoordinate {
    uint32_t face = 0;
    float s = 0.0f;
    float t = 0.0f;
};

// The unit direction of (face, s, t). s and t outside [0, 1] extend the face's plane
// (sc = 2 s - 1 beyond +-1), which is how seamless filtering finds a neighbour face's texel.
glm::vec3 cubeDirection(uint32_t face, float s, float t);
// The face and (s, t) a lookup in `direction` (any length but zero) reads.
CubeCoordinate cubeCoordinateFromDirection(glm::vec3 direction);

// One level of a cube map: 6 square faces in GL's face order, each `size` x `size` texels,
// rows from t = 0, 3 floats (linear RGB) per texel: 6 * size * size * 3 values.
struct CubeLevel {
    uint32_t size = 0;
    std::vector<float> rgb;

    CubeLevel() = default;
    explicit CubeLevel(uint32_t faceSize) : size(faceSize), rgb(size_t(kCubeFaces) * faceSize * faceSize * 3, 0.0f) {}

    size_t index(uint32_t face, uint32_t x, uint32_t y) const { return ((size_t(face) * size + y) * size + x) * 3; }
    glm::vec3 texel(uint32_t face, uint32_t x, uint32_t y) const
    {
        const float* p = rgb.data() + index(face, x, y);
        return {p[0], p[1], p[2]};
    }
    void setTexel(uint32_t face, uint32_t x, uint32_t y, glm::vec3 value)
    {
        float* p = rgb.data() + index(face, x, y);
        p[0] = value.r;
        p[1] = value.g;
        p[2] = value.b;
    }
};

// A mip chain: levels[l] has size levels[0].size >> l.
struct CubeMap {
    std::vector<CubeLevel> levels;
};

// The unit direction through the centre of texel (x, y) of a face of `size`.
glm::vec3 cubeTexelDirection(uint32_t face, uint32_t x, uint32_t y, uint32_t size);
// The exact solid angle of that texel (the 6 * size^2 texels sum to 4 pi).
double cubeTexelSolidAngle(uint32_t x, uint32_t y, uint32_t size);

// GL_LINEAR with GL_TEXTURE_CUBE_MAP_SEAMLESS on: the bilinear weights of the face the
// direction selects; a tap beyond the face's edge reads the texel of the neighbour face that
// holds the tap's texel centre continued across the edge (the spec's adjacent-face rule).
// At a cube corner, where GL leaves the fourth tap to the implementation (the spec allows
// the average of the three), this reads the texel of one of the neighbour faces.
glm::vec3 sampleCubeBilinear(const CubeLevel& level, glm::vec3 direction);
// textureLod with GL_LINEAR_MIPMAP_LINEAR: `lod` clamped to [0, levels - 1], the two
// nearest levels sampled with sampleCubeBilinear and mixed by lod's fraction.
glm::vec3 sampleCubeTrilinear(const CubeMap& cube, glm::vec3 direction, float lod);

// The 2x2 box average of each face (size halved, at least 1): the next mip level.
CubeLevel halveCubeLevel(const CubeLevel& level);

} // namespace lfd::lighting
