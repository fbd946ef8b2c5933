// Texel values for a coarse cube level chosen for how GL reads it: bilinearly between
// texel centres. A level that stores its function's values at the centres reconstructs it
// between them with an error that grows with the texel size: the prefilter's wide level
// (prefilter.h), 4 x 4 faces of 22 degrees a texel, read between its centres is off by
// 6.9% on average under the sun and sky (2.4% on the neutral studio), most near the sun's
// terminator, where the lobe bends within a texel. Texel values that make the bilinear
// reads match the function densely, in the least-squares sense, bring that to 4.8% (1.2%)
// (prefilter_test), and a rough metal sphere under that sun from a worst pixel of 34 to 22
// levels (ibl_accuracy_test: white metal, roughness 1).
#pragma once

#include "cube_map.h"

#include <cstdint>

namespace lfd::lighting {

// The level of face `size` (1 .. 8: the normal equations are dense, 6 size^2 unknowns)
// whose seamless bilinear reads (sampleCubeBilinear) best match `target` at `target`'s texel
// centres: per channel, each sample weighted by 1 / target^2 (relative error, so dark
// regions next to a bright one count as much); negative results are clamped to 0. `target`
// should be finer than `size` (4 times: 16 samples per unknown).
CubeLevel leastSquaresCubeLevel(const CubeLevel& target, uint32_t size);

} // namespace lfd::lighting
