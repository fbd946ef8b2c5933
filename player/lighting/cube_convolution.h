// Exact convolution of a cube level with a kernel that depends only on the angle between
// the output direction and the source direction: the diffuse irradiance (kernel max(cos, 0))
// and the rough GGX levels (at n = v the lobe D Vis (n.l) is a function of n.l alone), so
// a bright source smaller than a texel (a sun) is weighed exactly, where sampling would
// catch more or less of it depending on where its samples fall.
#pragma once

#include "cube_map.h"

#include <functional>

namespace lfd::lighting {

// A cube of face `size` whose texel centres n hold
//   sum_j L_j w(n.d_j) omega_j / sum_j w(n.d_j) omega_j
// over every texel j of `source` (direction d_j at its centre, exact solid angle omega_j).
// w is tabulated on cos in [0, 1] (4096 intervals, linear between) and 0 for cos <= 0.
// Costs 6 size^2 x 6 source.size^2 multiply-adds; rows run on every core; deterministic.
CubeLevel convolveCube(const CubeLevel& source, uint32_t size, const std::function<double(double cosine)>& kernel);

} // namespace lfd::lighting
