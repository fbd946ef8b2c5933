// Equirectangular -> cube resampling; see cube_from_environment.h.
#include "cube_from_environment.h"

#include "parallel.h"

#include <numbers>

namespace lfd::lighting {

CubeLevel cubeFromEnvironment(const Environment& environment, uint32_t size)
{
    // The coarsest box-halved image whose texels (2 pi / width at the equator) are still
    // no wider than the cube's at a face centre (2 / size): halve while width / 2 >= pi size.
    const double narrowest = std::numbers::pi * double(size);
    Environment halved;
    const Environment* source = &environment;
    while (double(source->width / 2) >= narrowest && source->height >= 2) {
        halved = halveEnvironment(*source);
        source = &halved;
    }
    CubeLevel cube(size);
    const float texel = 1.0f / float(size);
    forEachBand(size_t(kCubeFaces) * size, 4, [&](size_t, size_t begin, size_t end) {
        for (size_t row = begin; row < end; ++row) {
            const uint32_t face = uint32_t(row / size), y = uint32_t(row % size);
            for (uint32_t x = 0; x < size; ++x) {
                glm::vec3 sum(0.0f);
                for (float dy : {0.25f, 0.75f})
                    for (float dx : {0.25f, 0.75f})
                        sum += sampleEnvironment(*source, cubeDirection(face, (float(x) + dx) * texel,
                                                                        (float(y) + dy) * texel));
                cube.setTexel(face, x, y, 0.25f * sum);
            }
        }
    });
    return cube;
}

} // namespace lfd::lighting
