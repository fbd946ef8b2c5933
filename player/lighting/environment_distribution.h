// Directions drawn in proportion to an environment's luminance: the light-sampling
// strategy of the Monte Carlo reference (reference_ibl.h), so a small bright source (a sun
// disk) is found by a few samples instead of by luck. A piecewise-constant distribution
// over the equirectangular texels, each weighted by the largest Rec. 709 luminance in its
// 3 x 3 neighbourhood times sin(theta) of its centre (its solid angle up to a constant).
// note: the integrand reads the image bilinearly, which carries a bright texel half a texel
// into its neighbours; weighting a texel by its own luminance alone gave those fringes of a
// sun disk a tiny density and the estimate spikes (a 60% error at 512 samples per
// strategy). The distribution is sampled by inverting the row marginal
// and then the row's conditional (Pharr, Jakob & Humphreys, "Physically Based Rendering",
// 4th ed., sections A.5 and 12.5: PiecewiseConstant2D, ImageInfiniteLight). An environment
// that is black everywhere is sampled by solid angle instead.
#pragma once

#include "environment.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lfd::lighting {

class EnvironmentDistribution {
public:
    explicit EnvironmentDistribution(const Environment& environment);

    struct Sample {
        glm::vec2 uv;          // equirectangular coordinate (environment.h)
        glm::vec3 direction;   // unit
        float pdf = 0.0f;      // per steradian
    };
    // The sample for a point xi in [0, 1)^2.
    Sample sample(glm::vec2 xi) const;
    // The density per steradian at equirectangular coordinate uv (0 at the poles' rows'
    // zero-area ends).
    float pdf(glm::vec2 uv) const;

private:
    uint32_t width_ = 0;
    uint32_t height_ = 0;
    std::vector<double> rowCdf_;    // height + 1 running sums of the row weights
    std::vector<double> columnCdf_; // height rows of width + 1 running sums
};

} // namespace lfd::lighting
