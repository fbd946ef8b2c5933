#include "bench_report.h"

#include "bench_work.h"

#include "frame_stages.h"
#include "atomic_file.h"
#include "frame_stats.h"
#include "image_metrics.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace lfd::player {

namespace fs = std::filesystem;

namespace {

// Every stage of frame_stages.h has a column; any other stage a renderer times is listed
// below the table.
std::string stageKey(std::string_view stage) { return std::string(stage); }

std::string format(const char* fmt, double value)
{
    char text[64];
    std::snprintf(text, sizeof(text), fmt, value);
    return text;
}

std::string ratioText(const std::optional<double>& r)
{
    return r ? format("%.2fx", *r) : std::string("-");
}

// 2290000 -> "2.29M", 812000 -> "812K".
std::string countText(double n)
{
    if (n >= 1e6)
        return format("%.2fM", n / 1e6);
    if (n >= 1e3)
        return format("%.0fK", n / 1e3);
    return format("%.0f", n);
}

// JSON numbers: nlohmann writes non-finite values as null; say so explicitly.
nlohmann::json number(double v)
{
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json optionalNumber(const std::optional<double>& v)
{
    return v ? number(*v) : nlohmann::json(nullptr);
}

nlohmann::json qualityJson(const Quality& q)
{
    return {{"rmse", q.rmse}, {"psnr", number(q.psnr)}, {"ssim", q.ssim}, {"flip", number(q.flip)}};
}

std::string csvNumber(double v)
{
    if (std::isinf(v))
        return "inf";
    return format("%.6g", v);
}

std::string xmlEscape(const std::string& s)
{
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

// Tick values 1-2-5 x 10^k inside [lo, hi] (log axis).
std::vector<double> logTicks(double lo, double hi)
{
    std::vector<double> ticks;
    for (int e = int(std::floor(std::log10(lo))); e <= int(std::ceil(std::log10(hi))); ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            const double t = m * std::pow(10.0, e);
            if (t >= lo && t <= hi)
                ticks.push_back(t);
        }
    return ticks;
}

// A "nice" step (1, 2 or 5 x 10^k) giving about `count` intervals over [0, hi].
double niceStep(double hi, int count)
{
    const double raw = hi / count;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= raw)
            return m * p;
    return 10.0 * p;
}

std::string tickLabel(double v)
{
    return v >= 100.0 || v == std::floor(v) ? format("%.0f", v) : format("%.3g", v);
}

// The stages inside "total" the table has no column for (the downsample, the pose pass
// with its share of the frame, any other), as "config stage ms" texts.
void addOtherStages(const RendererResult& r, std::vector<std::string>& out)
{
    for (const auto& [name, times] : r.stages)
        if (name == stage::kDownsample ||
            std::find(stage::kAll.begin(), stage::kAll.end(), name) == stage::kAll.end())
            out.push_back(r.name + " " + name + " " + format("%.2f ms", times.mean()));
    // Skinned and morphed scenes: the pose pass, with its share of the frame.
    if (r.stages.count(stageKey(stage::kPose))) {
        const double pose = r.stageMean(stageKey(stage::kPose));
        const double share = 100.0 * pose / std::max(r.stageMean(stageKey(stage::kTotal)), 1e-9);
        out.push_back(r.name + " pose " + format("%.2f ms", pose) + " (" + format("%.1f", share) + "% of total)");
    }
}

} // namespace

std::string benchTable(const BenchReport& report)
{
    const BenchOptions& o = report.options;
    const DisplayProfile& p = report.profile;
    std::ostringstream s;
    s << "GL: " << report.gl << "\n";
    s << "pack: " << report.packName << ", " << report.triangles << " triangles (" << report.drawnTriangles
      << " drawn per frame); display: " << p.name
      << ", " << p.viewCount << " views of " << p.viewWidth << "x" << p.viewHeight << ", panel "
      << p.panelWidth << "x" << p.panelHeight << "\n";
    s << "frames: " << o.warmup << " warm-up + " << o.frames << " timed (frame k at k/" << o.fps
      << " s, turntable period " << o.turntablePeriod << " s); quality at frame " << o.qualityFrame
      << " against " << o.reference
      << (o.reference == "gstd" ? " (" + gstdModelName(o.rendererOptions.gstd.model) + " model)" : std::string())
      << "; GPU times are means over the timed frames\n\n";

    char line[512];
    const char* rowFormat = "%-28s %22s %12s %11s %9s %11s %9s %8s %15s %9s %9s %9s %10s %10s %10s %11s %11s\n";
    std::snprintf(line, sizeof(line), rowFormat, "renderer", "point_gen ms (points)", "view_gen ms",
                  "resolve ms", "eia ms", "total ms", "wall ms", "vs mvr", "vs mvr-layered", "EIA RMSE", "EIA SSIM", "EIA FLIP",
                  "view RMSE", "view SSIM", "view FLIP", "views RMSE", "views SSIM");
    s << line;
    std::vector<std::string> otherStages;
    for (const RendererResult& r : report.results) {
        std::string pointGen = "-", viewGen = "-", resolve = "-", eia = "-", total = "-", wall = "-";
        if (r.timed) {
            if (r.stages.count(stageKey(stage::kPointGeneration))) {
                pointGen = format("%.2f", r.stageMean(stageKey(stage::kPointGeneration)));
                if (const auto points = r.extraValue("points"))
                    pointGen += " (" + countText(*points) + ")";
            }
            if (r.stages.count(stageKey(stage::kResolve)))
                resolve = format("%.2f", r.stageMean(stageKey(stage::kResolve)));
            viewGen = format("%.2f", r.stageMean(stageKey(stage::kViewGeneration)));
            eia = format("%.2f", r.stageMean(stageKey(stage::kEia)));
            total = format("%.2f", r.stageMean(stageKey(stage::kTotal)));
            wall = format("%.2f", r.wallMsPerFrame);
            addOtherStages(r, otherStages);
        }
        const std::string name = r.timed ? r.name : r.name + " (ref, untimed)";
        std::snprintf(line, sizeof(line), rowFormat, name.c_str(), pointGen.c_str(), viewGen.c_str(),
                      resolve.c_str(), eia.c_str(), total.c_str(), wall.c_str(), ratioText(report.speedUp(r.name, "mvr")).c_str(),
                      ratioText(report.speedUp(r.name, "mvr-layered")).c_str(),
                      format("%.2f", r.eia.rmse).c_str(), format("%.4f", r.eia.ssim).c_str(),
                      format("%.4f", r.eia.flip).c_str(), format("%.2f", r.centreView.rmse).c_str(),
                      format("%.4f", r.centreView.ssim).c_str(), format("%.4f", r.centreView.flip).c_str(),
                      format("%.2f", r.allViews.rmse).c_str(), format("%.4f", r.allViews.ssim).c_str());
        s << line;
    }
    s << "(vs X = X's total / this total, > 1: faster than X; wall = wall-clock ms per frame over the timed "
         "frames run back to back; view = centre view, views = mean over all views; RMSE 0..255, SSIM (luma) and "
         "FLIP (0..1, lower is better) against "
      << o.reference << ")\n";
    s << "per frame:";
    for (const RendererResult& r : report.results)
        if (r.timed)
            s << " " << r.name << " " << format("%.1f", r.callsPerFrame.dispatches) << " dispatches, "
              << format("%.1f", r.callsPerFrame.draws) << " draws, " << format("%.1f", r.callsPerFrame.barriers)
              << " barriers, " << format("%.1f", r.callsPerFrame.syncs) << " waits, "
              << format("%.1f", double(r.frameGpuBytes) / (1024.0 * 1024.0)) << " MiB;";
    s << "\n";
    if (!otherStages.empty()) {
        s << "stages inside total not shown above:";
        for (const std::string& t : otherStages)
            s << " " << t << ";";
        s << "\n";
    }
    s << "\n";
    const auto vsMvr = report.speedUp("lfdpr", "mvr");
    const auto vsLayered = report.speedUp("lfdpr", "mvr-layered");
    s << "lfdpr/mvr total-time ratio: " << (vsMvr ? format("%.2fx", *vsMvr) : "n/a (lfdpr or mvr not run)")
      << (vsMvr ? " (mvr total / lfdpr total; > 1: lfdpr is faster)" : "") << "\n";
    s << "lfdpr/mvr-layered: "
      << (vsLayered ? format("%.2fx", *vsLayered) : "n/a (lfdpr or mvr-layered not run)") << "\n";
    if (const std::string work = benchWorkTable(report); !work.empty())
        s << "\n" << work;
    return s.str();
}

nlohmann::json benchJson(const BenchReport& report)
{
    const BenchOptions& o = report.options;
    const DisplayProfile& p = report.profile;
    nlohmann::json j;
    j["tool"] = "lfd-bench";
    j["version"] = LFD_VERSION;
    j["gl"] = report.gl;
    j["pack"] = report.packName;
    j["triangles"] = report.triangles;
    j["drawn_triangles"] = report.drawnTriangles;
    j["scene_gpu_bytes"] = report.sceneGpuBytes;
    j["texture_anisotropy"] = report.textureAnisotropy;
    j["profile"] = {{"name", p.name},           {"views", p.viewCount},
                    {"view_width", p.viewWidth}, {"view_height", p.viewHeight},
                    {"panel_width", p.panelWidth}, {"panel_height", p.panelHeight}};
    j["options"] = {{"renderers", o.renderers},        {"reference", o.reference},
                    {"frames", o.frames},              {"warmup", o.warmup},
                    {"fps", o.fps},                    {"turntable_period", o.turntablePeriod},
                    {"quality_frame", o.qualityFrame},
                    {"gstd", {{"factor", o.rendererOptions.gstd.factor},
                              {"samples", o.rendererOptions.gstd.samples},
                              {"seed", o.rendererOptions.gstd.seed},
                              {"filter_diameter", o.rendererOptions.gstd.filterDiameter},
                              {"max_anisotropy", o.rendererOptions.gstd.maxAnisotropy},
                              {"sub_views", o.rendererOptions.gstd.subViewCount()},
                              {"model", gstdModelName(o.rendererOptions.gstd.model)}}}};
    nlohmann::json renderers = nlohmann::json::array();
    for (const RendererResult& r : report.results) {
        nlohmann::json e;
        e["name"] = r.name;
        e["timed"] = r.timed;
        e["seconds"] = r.seconds;
        e["from_cache"] = r.fromCache;
        nlohmann::json stages = nlohmann::json::object();
        for (const auto& [name, t] : r.stages) {
            e[name + "_ms"] = t.mean();
            stages[name] = {{"mean", t.mean()}, {"median", t.median()}, {"min", t.min()},
                            {"max", t.max()},   {"samples", t.ms.size()}, {"ms", t.ms}};
        }
        e["stages"] = stages;
        nlohmann::json extra = nlohmann::json::object();
        for (const auto& [key, value] : r.extra)
            extra[key] = number(value);
        e["extra"] = extra;
        e["wall_ms_per_frame"] = r.timed ? nlohmann::json(r.wallMsPerFrame) : nlohmann::json(nullptr);
        e["gl_calls_per_frame"] = {{"dispatches", r.callsPerFrame.dispatches},
                                   {"draws", r.callsPerFrame.draws},
                                   {"barriers", r.callsPerFrame.barriers},
                                   {"waits", r.callsPerFrame.syncs}};
        e["frame_gpu_bytes"] = r.frameGpuBytes;
        e["speedup_vs_mvr"] = optionalNumber(report.speedUp(r.name, "mvr"));
        e["speedup_vs_mvr_layered"] = optionalNumber(report.speedUp(r.name, "mvr-layered"));
        e["quality"] = {{"reference", o.reference},
                        {"eia", qualityJson(r.eia)},
                        {"centre_view", qualityJson(r.centreView)},
                        {"all_views", qualityJson(r.allViews)}};
        renderers.push_back(e);
    }
    j["renderers"] = renderers;
    j["ratios"] = {{"lfdpr_vs_mvr", optionalNumber(report.speedUp("lfdpr", "mvr"))},
                   {"lfdpr_vs_mvr_layered", optionalNumber(report.speedUp("lfdpr", "mvr-layered"))}};
    return j;
}

std::string benchCsv(const BenchReport& report)
{
    std::ostringstream s;
    s << "renderer,timed,frames,point_generation_ms,view_generation_ms,eia_ms,total_ms,total_median_ms,"
         "total_min_ms,total_max_ms,points,speedup_vs_mvr,speedup_vs_mvr_layered,eia_rmse,eia_psnr,eia_ssim,"
         "view_rmse,view_psnr,view_ssim,views_rmse,views_psnr,views_ssim,eia_flip,view_flip,resolve_ms,"
         "wall_ms_per_frame,dispatches_per_frame,draws_per_frame,barriers_per_frame,waits_per_frame,"
         "frame_gpu_bytes"
      << benchWorkCsvHeader() << "\n";
    auto opt = [](const std::optional<double>& v) { return v ? csvNumber(*v) : std::string(); };
    for (const RendererResult& r : report.results) {
        s << r.name << ',' << (r.timed ? 1 : 0) << ',' << (r.timed ? report.options.frames : 0u);
        for (const std::string_view stage : {stage::kPointGeneration, stage::kViewGeneration, stage::kEia, stage::kTotal})
            s << ',' << (r.stages.count(stageKey(stage)) ? csvNumber(r.stageMean(stageKey(stage))) : std::string());
        const auto total = r.stages.find(stageKey(stage::kTotal));
        if (total != r.stages.end())
            s << ',' << csvNumber(total->second.median()) << ',' << csvNumber(total->second.min()) << ','
              << csvNumber(total->second.max());
        else
            s << ",,,";
        s << ',' << opt(r.extraValue("points")) << ',' << opt(report.speedUp(r.name, "mvr")) << ','
          << opt(report.speedUp(r.name, "mvr-layered"));
        for (const Quality* q : {&r.eia, &r.centreView, &r.allViews})
            s << ',' << csvNumber(q->rmse) << ',' << csvNumber(q->psnr) << ',' << csvNumber(q->ssim);
        // Columns added later go last, so earlier ones keep their positions for existing readers.
        s << ',' << csvNumber(r.eia.flip) << ',' << csvNumber(r.centreView.flip) << ','
          << (r.stages.count(stageKey(stage::kResolve)) ? csvNumber(r.stageMean(stageKey(stage::kResolve))) : std::string());
        if (r.timed)
            s << ',' << csvNumber(r.wallMsPerFrame) << ',' << csvNumber(r.callsPerFrame.dispatches) << ','
              << csvNumber(r.callsPerFrame.draws) << ',' << csvNumber(r.callsPerFrame.barriers) << ','
              << csvNumber(r.callsPerFrame.syncs) << ',' << r.frameGpuBytes;
        else
            s << ",,,,,,";
        s << benchWorkCsvRow(r) << '\n';
    }
    return s.str();
}

namespace {

// The speed-vs-error plot: its points (timed renderers; x is total GPU ms on a log scale,
// since renderers differ by factors, y is EIA RMSE against the reference) and its axes.
struct SpeedErrorPlot {
    struct Point {
        std::string name;
        double ms, rmse;
    };
    static constexpr double W = 720, H = 460, left = 80, right = 40, top = 56, bottom = 64;
    static constexpr double plotW = W - left - right, plotH = H - top - bottom;
    std::vector<Point> points;
    double msLo = 1.0, msHi = 10.0, yStep = 1.0, yHi = 1.0;

    double xOf(double ms) const { return left + plotW * std::log(ms / msLo) / std::log(msHi / msLo); }
    double yOf(double e) const { return top + plotH * (1.0 - e / yHi); }
};

SpeedErrorPlot speedErrorPlot(const BenchReport& report)
{
    SpeedErrorPlot plot;
    for (const RendererResult& r : report.results)
        if (r.timed && r.stageMean(stageKey(stage::kTotal)) > 0.0)
            plot.points.push_back({r.name, r.stageMean(stageKey(stage::kTotal)), r.eia.rmse});
    double rmseHi = 1.0;
    if (!plot.points.empty()) {
        plot.msLo = plot.msHi = plot.points.front().ms;
        for (const SpeedErrorPlot::Point& pt : plot.points) {
            plot.msLo = std::min(plot.msLo, pt.ms);
            plot.msHi = std::max(plot.msHi, pt.ms);
            rmseHi = std::max(rmseHi, pt.rmse);
        }
    }
    // Pad the x range by a factor of 1.5 each way (at least one decade shown).
    plot.msLo /= 1.5;
    plot.msHi *= 1.5;
    if (plot.msHi / plot.msLo < 10.0) {
        const double grow = std::sqrt(10.0 / (plot.msHi / plot.msLo));
        plot.msLo /= grow;
        plot.msHi *= grow;
    }
    plot.yStep = niceStep(rmseHi * 1.1, 5);
    plot.yHi = std::ceil(rmseHi * 1.1 / plot.yStep) * plot.yStep;
    return plot;
}

void svgTitle(std::ostringstream& s, const BenchReport& report)
{
    using P = SpeedErrorPlot;
    char buf[512];
    std::snprintf(buf, sizeof(buf),
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
                  "font-family=\"sans-serif\" font-size=\"12\">\n",
                  P::W, P::H, P::W, P::H);
    s << buf << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const DisplayProfile& p = report.profile;
    s << "<text x=\"" << P::W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
      << xmlEscape(report.packName) << ": speed vs error</text>\n";
    s << "<text x=\"" << P::W / 2 << "\" y=\"40\" text-anchor=\"middle\" fill=\"#555\">"
      << xmlEscape(std::to_string(p.viewCount) + " views of " + std::to_string(p.viewWidth) + "x" +
                   std::to_string(p.viewHeight) + ", " + std::to_string(report.options.frames) +
                   " timed frames, error against " + report.options.reference)
      << "</text>\n";
}

void svgGrid(std::ostringstream& s, const SpeedErrorPlot& plot)
{
    using P = SpeedErrorPlot;
    char buf[512];
    for (double t : logTicks(plot.msLo, plot.msHi)) {
        std::snprintf(buf, sizeof(buf),
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n",
                      plot.xOf(t), P::top, plot.xOf(t), P::top + P::plotH, plot.xOf(t), P::top + P::plotH + 18,
                      tickLabel(t).c_str());
        s << buf;
    }
    for (double e = 0.0; e <= plot.yHi + 1e-9; e += plot.yStep) {
        std::snprintf(buf, sizeof(buf),
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n",
                      P::left, plot.yOf(e), P::left + P::plotW, plot.yOf(e), P::left - 8, plot.yOf(e) + 4,
                      tickLabel(e).c_str());
        s << buf;
    }
    std::snprintf(buf, sizeof(buf),
                  "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#333\"/>\n"
                  "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">total GPU time per frame, ms (log scale)</text>\n"
                  "<text transform=\"translate(%.1f %.1f) rotate(-90)\" text-anchor=\"middle\">EIA RMSE (0..255)</text>\n",
                  P::left, P::top, P::plotW, P::plotH, P::left + P::plotW / 2, P::H - 18, 22.0, P::top + P::plotH / 2);
    s << buf;
}

// One labelled point per renderer. Labels sit above their point, every second one a line
// higher so close points stay readable, below it near the top edge, and left of it near
// the right edge (about 6.5 px per character at 12 px).
void svgPoints(std::ostringstream& s, const SpeedErrorPlot& plot)
{
    using P = SpeedErrorPlot;
    char buf[512];
    const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2"};
    for (size_t i = 0; i < plot.points.size(); ++i) {
        const P::Point& pt = plot.points[i];
        const double x = plot.xOf(pt.ms), y = plot.yOf(pt.rmse);
        const std::string label = pt.name + format(" (%.1f ms, ", pt.ms) + format("%.2f)", pt.rmse);
        double labelY = y - 8.0 - 14.0 * double(i % 2);
        if (labelY < P::top + 12.0)
            labelY = y + 16.0 + 14.0 * double(i % 2);
        const bool leftOfPoint = x + 8.0 + 6.5 * double(label.size()) > P::W - 4.0;
        std::snprintf(buf, sizeof(buf),
                      "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"%s\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\" fill=\"%s\">",
                      x, y, colours[i % 7], leftOfPoint ? x - 8.0 : x + 8.0, labelY,
                      leftOfPoint ? "end" : "start", colours[i % 7]);
        s << buf << xmlEscape(label) << "</text>\n";
    }
    if (plot.points.empty())
        s << "<text x=\"" << P::W / 2 << "\" y=\"" << P::H / 2 << "\" text-anchor=\"middle\">no timed renderers</text>\n";
}

} // namespace

std::string speedErrorSvg(const BenchReport& report)
{
    const SpeedErrorPlot plot = speedErrorPlot(report);
    std::ostringstream s;
    svgTitle(s, report);
    svgGrid(s, plot);
    svgPoints(s, plot);
    s << "</svg>\n";
    return s.str();
}

std::vector<fs::path> writeBenchOutputs(const fs::path& dir, const BenchReport& report,
                                        const std::map<std::string, FrameImages>& images)
{
    std::vector<fs::path> written;
    // Each configuration's PNGs (a panel-size EIA compresses in about a second) on a core of
    // their own (common/parallel.h), listed per configuration and then in result order.
    std::vector<std::vector<fs::path>> pngs(report.results.size());
    auto collect = [&] {
        for (std::vector<fs::path>& list : pngs)
            written.insert(written.end(), list.begin(), list.end());
        pngs.clear();
    };
    try {
        fs::create_directories(dir);
        const DisplayProfile& p = report.profile;
        const FrameImages* reference = nullptr;
        if (auto it = images.find(report.options.reference); it != images.end())
            reference = &it->second;
        forEachBand(report.results.size(), 1, [&](size_t i, size_t, size_t) {
            const RendererResult& r = report.results[i];
            const auto it = images.find(r.name);
            if (it == images.end())
                return;
            const FrameImages& img = it->second;
            std::vector<fs::path>& list = pngs[i];
            metrics::writeImage(dir / (r.name + "_eia.png"), img.eia.data(), p.panelWidth, p.panelHeight, 4);
            list.push_back(dir / (r.name + "_eia.png"));
            metrics::writeImage(dir / (r.name + "_view_centre.png"), img.centre.data(), p.viewWidth, p.viewHeight, 4);
            list.push_back(dir / (r.name + "_view_centre.png"));
            if (reference && r.name != report.options.reference) {
                const metrics::Image a{p.panelWidth, p.panelHeight, 4, img.eia};
                const metrics::Image b{p.panelWidth, p.panelHeight, 4, reference->eia};
                metrics::writeDiffImage(dir / (r.name + "_diff_eia.png"), a, b, 4.0f);
                list.push_back(dir / (r.name + "_diff_eia.png"));
            }
        });
        collect();
        writeFileAtomically(dir / "bench.csv", benchCsv(report));
        written.push_back(dir / "bench.csv");
        writeFileAtomically(dir / "speed_vs_error.svg", speedErrorSvg(report));
        written.push_back(dir / "speed_vs_error.svg");
        writeFileAtomically(dir / "bench.json", benchJson(report).dump(2) + "\n");
        written.push_back(dir / "bench.json");
    } catch (...) {
        collect(); // what the other configurations wrote before the failure stopped them
        for (const fs::path& path : written) {
            std::error_code ec;
            fs::remove(path, ec);
        }
        throw;
    }
    return written;
}

} // namespace lfd::player
