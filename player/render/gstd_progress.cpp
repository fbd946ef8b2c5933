#include "gstd_progress.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>

namespace lfd::player {

std::string formatDuration(double seconds)
{
    if (!std::isfinite(seconds) || seconds < 0.0)
        return "?";
    char text[48];
    if (seconds < 9.95) {
        std::snprintf(text, sizeof(text), "%.1f s", seconds);
    } else if (seconds < 59.5) {
        std::snprintf(text, sizeof(text), "%.0f s", seconds);
    } else if (seconds < 3599.5) {
        const long total = std::lround(seconds);
        std::snprintf(text, sizeof(text), "%ld min %02ld s", total / 60, total % 60);
    } else {
        const long minutes = std::lround(seconds / 60.0);
        std::snprintf(text, sizeof(text), "%ld h %02ld min", minutes / 60, minutes % 60);
    }
    return text;
}

std::optional<double> remainingSeconds(const GstdProgress& progress, double elapsedSeconds)
{
    if (progress.done == 0 || progress.total == 0 || !(elapsedSeconds > 0.0) || !std::isfinite(elapsedSeconds))
        return std::nullopt;
    if (progress.done >= progress.total)
        return 0.0;
    // Sub-views of one frame cost about the same (same scene, same size), so the rate so
    // far is the estimate; batches may differ in size (the last is often smaller).
    return elapsedSeconds / progress.done * (progress.total - progress.done);
}

std::string formatGstdProgress(const GstdProgress& progress, double elapsedSeconds)
{
    std::string line = std::to_string(progress.done) + "/" + std::to_string(progress.total) + " sub-views (" +
                       std::to_string(progress.batchesDone) + "/" + std::to_string(progress.batches) + " batches), " +
                       formatDuration(elapsedSeconds) + " elapsed";
    if (const std::optional<double> left = remainingSeconds(progress, elapsedSeconds))
        line += ", about " + formatDuration(*left) + " left";
    return line;
}

std::string formatGstdPlan(const GstdProgress& plan)
{
    return std::string("gstd (") + (plan.panelModel ? "panel" : "views") + " model): " + std::to_string(plan.total) +
           " sub-views of " + std::to_string(plan.subViewWidth) + "x" + std::to_string(plan.subViewHeight) + " in " +
           std::to_string(plan.batches) + (plan.batches == 1 ? " batch" : " batches");
}

bool GstdProgressThrottle::shouldPrint(const GstdProgress& progress, double elapsedSeconds)
{
    if (progress.done == 0 || progress.total == 0 || progress.done >= progress.total)
        return false;
    const uint32_t tenth = uint32_t(uint64_t(progress.done) * 10 / progress.total);
    const double since = elapsedSeconds - lastPrinted_;
    // The first line comes as soon as minInterval has passed: it carries the first estimate.
    const bool due = since >= maxInterval_ || (since >= minInterval_ && (!printed_ || tenth > lastTenth_));
    if (due) {
        lastPrinted_ = elapsedSeconds;
        lastTenth_ = tenth;
        printed_ = true;
    }
    return due;
}

GstdProgressCallback gstdProgressPrinter(std::ostream& out, std::string prefix, std::string hint)
{
    using Clock = std::chrono::steady_clock;
    struct State {
        Clock::time_point start = Clock::now();
        GstdProgressThrottle throttle;
    };
    auto state = std::make_shared<State>(); // the callback is copied with the options
    return [&out, prefix = std::move(prefix), hint = std::move(hint), state](const GstdProgress& progress) {
        if (progress.done == 0) {
            state->start = Clock::now(); // a new frame: its own clock and throttle
            state->throttle = GstdProgressThrottle();
            out << prefix << "reference: " << formatGstdPlan(progress) << (hint.empty() ? "" : "; ") << hint
                << std::endl;
            return;
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - state->start).count();
        if (state->throttle.shouldPrint(progress, elapsed))
            out << prefix << "reference: gstd " << formatGstdProgress(progress, elapsed) << std::endl;
    };
}

} // namespace lfd::player
