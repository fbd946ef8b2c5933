// The equirectangular environment resampled into a cube level (the prefilter's source and
// its roughness-0 level).
#pragma once

#include "cube_map.h"
#include "environment.h"

namespace lfd::lighting {

// A cube of face `size` whose texels each average 2 x 2 bilinear reads of the environment,
// taken from the box-halved image (halveEnvironment) whose texels are the largest still no
// wider than the cube's at a face centre (2 pi / width <= 2 / size): so a 4096-wide HDRI
// is averaged down before a 256 cube reads it, and the 2 x 2 reads, at most an image texel
// apart, see every texel. Rows run on every core; deterministic.
CubeLevel cubeFromEnvironment(const Environment& environment, uint32_t size);

} // namespace lfd::lighting
