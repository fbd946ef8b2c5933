// gstd's panel model: the gold standard as the limit of the display (docs/player/gstd.md). Every
// panel subpixel integrates the scene over the light it sends out:
//  * angularly, over its own interval: the lenticular phase across its area (a trapezoid:
//    its width and, through the slant, its height each spread the phase). The sub-views
//    tile the cone's phases; each one's weight for a subpixel is the fraction of that
//    distribution inside the sub-view's interval, so no angular detail inside a view
//    interval is lost before the EIA is formed, and a method's angular reconstruction is
//    not counted as error merely because the reference skipped it;
//  * spatially, over one view pixel's area centred on the lens the subpixel lies under
//    (the light of a direction leaves through the whole lens; a view pixel is the finest
//    spatial sample the compared views carry - on the prototype exactly one lens by six
//    rows), so the reference converges as its sub-views' resolution grows.
#pragma once

#include "gl_handles.h"

#include "lfd/display_profile.h"

#include <cstdint>

namespace lfd::player {

class GpuTimer;

// A subpixel's footprint under the profile's lenses.
struct GstdPanelFootprint {
    // Phase spread over the subpixel's width and height: |perSubpixel|, |perRow|, each at
    // least the sub-view interval / 64 (a vertical lens, perRow = 0, is a plain box).
    double spreadColumn = 0.0, spreadRow = 0.0;
    // The spatial box in screen units (0..1): one view pixel, 1 / viewWidth by
    // 1 / viewHeight (centred on the subpixel's lens and row).
    double screenWidth = 0.0, screenHeight = 0.0;
};

// Throws std::invalid_argument when half the phase spread and half the sub-view interval
// together reach half the lens period (a lens of about one subpixel), where the circular
// weights would overlap themselves.
GstdPanelFootprint gstdPanelFootprint(const DisplayProfile& profile, uint32_t subViewsInCone);

// P(U <= x) for U = the phase offset of a point uniform on the subpixel from its centre
// (a trapezoid: boxes of widths spreadColumn and spreadRow convolved).
double gstdSpreadCdf(double x, const GstdPanelFootprint& footprint);

// The fraction of the subpixel at `phase` whose light belongs to the sub-view interval
// [t - h/2, t + h/2), circularly (the lens period). Summed over sub-views that tile [0, 1)
// it is 1 for every subpixel.
double gstdAngularWeight(double phase, double t, double h, const GstdPanelFootprint& footprint);

// The GPU side: a panel-size linear accumulator, one add() per view interval, then
// resolve() into the EIA texture.
class GstdPanelAccumulator {
public:
    GstdPanelAccumulator();
    // Clears the accumulator (made or remade at the profile's panel size; the subpixel
    // phases and lens centres are recomputed only when the panel or its mapping changes).
    void begin(const DisplayProfile& profile, uint32_t viewCount, uint32_t subViewsPerView);
    // Adds view intervals [firstView, firstView + views): their sub-views are the layers of
    // `subViews`, a 2D array texture of width x height with sRGB-encoded storage (linear
    // fetches), bilinear filtering, edges clamped; layer S (v - firstView) + s holds sub-view
    // s of view v, at phase (v + (s + 0.5) / S) / N.
    void add(unsigned subViews, uint32_t width, uint32_t height, uint32_t firstView, uint32_t views);
    // Writes the EIA (RGBA8 2D texture of the panel size).
    void resolve(unsigned eiaTexture);
    uint64_t bytes() const { return uint64_t(width_) * height_ * 16 * 3; }

private:
    gl::Program phases_, accumulate_, resolve_;
    gl::Texture accum_, phase_, lens_;
    uint32_t width_ = 0, height_ = 0, viewCount_ = 0, subViews_ = 0;
    DisplayProfile profile_;
    GstdPanelFootprint footprint_;
    void computePhases();
};

} // namespace lfd::player
