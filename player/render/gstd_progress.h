// Progress of a long gstd frame (issue 42): the gold standard renders S x N sub-views at
// `factor` times the view size, minutes on a CPU renderer (351 s for the car on llvmpipe,
// over 15 minutes for a million triangles), and a run that prints nothing for that long
// looks hung. The renderer reports each finished batch of sub-views (GstdOptions::progress);
// this file turns those reports into text: the plan before the first batch (the cost
// hint), and throttled lines with the elapsed time and an estimate of what remains.
// Pure CPU and clock-free (the caller passes the elapsed time), so it is unit-tested.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>

namespace lfd::player {

// One report from gstd's render(): `done` of `total` sub-views finished on the GPU, in
// `batchesDone` of `batches` batches. The first report of a frame has done == 0 (the
// plan, sent before any drawing); the last has done == total.
struct GstdProgress {
    uint32_t done = 0, total = 0;
    uint32_t batchesDone = 0, batches = 0;
    uint32_t subViewWidth = 0, subViewHeight = 0; // each sub-view's size in pixels
    bool panelModel = true;
};

// Called by gstd after each batch, once the GPU has finished it (so the times are real);
// empty = no reports and no waiting.
using GstdProgressCallback = std::function<void(const GstdProgress&)>;

// "0.4 s", "42 s", "5 min 51 s", "1 h 04 min": coarser as the time grows, so a line stays
// short; negative or non-finite times give "?".
std::string formatDuration(double seconds);

// Seconds left at the rate so far (elapsed / done per sub-view); nullopt before the first
// sub-view is done or when the elapsed time says nothing (0).
std::optional<double> remainingSeconds(const GstdProgress& progress, double elapsedSeconds);

// "96/192 sub-views (5/10 batches), 1 min 02 s elapsed, about 1 min 02 s left".
std::string formatGstdProgress(const GstdProgress& progress, double elapsedSeconds);

// The plan of a frame (from its done == 0 report): "gstd (panel model): 192 sub-views of
// 1920x1440 in 10 batches".
std::string formatGstdPlan(const GstdProgress& plan);

// When a progress line is worth printing: the first once `minInterval` seconds have
// passed (it carries the first estimate), then at most one every `minInterval` seconds, and
// only when another tenth of the work is done, but at least one every `maxInterval`
// seconds however slowly the tenths come; none for the last batch (the caller's own
// "rendered in ..." line says it finished) and none for a frame done within minInterval.
class GstdProgressThrottle {
public:
    explicit GstdProgressThrottle(double minInterval = 5.0, double maxInterval = 60.0)
        : minInterval_(minInterval), maxInterval_(maxInterval)
    {
    }
    // True when this report should be printed; remembers that it was.
    bool shouldPrint(const GstdProgress& progress, double elapsedSeconds);

private:
    double minInterval_, maxInterval_;
    double lastPrinted_ = 0.0;   // elapsed seconds at the last printed line (0: the start)
    uint32_t lastTenth_ = 0;     // tenths of the work done at the last printed line
    bool printed_ = false;
};

// A callback printing one frame's reports to `out` (lfd-bench: stderr), each line starting
// with `prefix`: at the plan, "<prefix>reference: <plan>; <hint>"; then the throttled
// progress lines, "<prefix>reference: gstd <progress>", timed from the plan's report.
GstdProgressCallback gstdProgressPrinter(std::ostream& out, std::string prefix, std::string hint);

} // namespace lfd::player
