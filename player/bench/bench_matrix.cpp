#include "bench_matrix.h"

#include "bench_report.h"
#include "frame_stages.h"
#include "atomic_file.h"
#include "frame_stats.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace lfd::player {

namespace fs = std::filesystem;

namespace {

std::string fmt(const char* f, double v)
{
    char text[64];
    std::snprintf(text, sizeof(text), f, v);
    return text;
}

std::string num(double v)
{
    if (std::isnan(v))
        return "";
    if (std::isinf(v))
        return "inf";
    return fmt("%.6g", v);
}

double stageMs(const RendererResult& r, std::string_view name)
{
    const auto it = r.stages.find(std::string(name));
    return it == r.stages.end() ? std::nan("") : it->second.mean();
}

// 2290000 -> "2.29M", 812000 -> "812K".
std::string count(double n)
{
    if (n >= 1e6)
        return fmt("%.2fM", n / 1e6);
    if (n >= 1e3)
        return fmt("%.0fK", n / 1e3);
    return fmt("%.0f", n);
}

std::string sceneName(const BenchReport& r)
{
    std::string name = r.packName;
    if (const auto dot = name.rfind(".lfdpack"); dot != std::string::npos && dot + 8 == name.size())
        name.resize(dot);
    return name;
}

std::string shellQuote(const std::string& s)
{
    std::string out = "'";
    for (char c : s)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

} // namespace

std::vector<bool> paretoFront(const BenchReport& report)
{
    const auto& rs = report.results;
    std::vector<bool> front(rs.size(), false);
    for (size_t i = 0; i < rs.size(); ++i) {
        const double ti = rs[i].stageMean(std::string(stage::kTotal)), ei = rs[i].eia.rmse;
        if (!rs[i].timed || !(ti > 0.0))
            continue;
        bool dominated = false;
        for (size_t j = 0; j < rs.size() && !dominated; ++j) {
            const double tj = rs[j].stageMean(std::string(stage::kTotal)), ej = rs[j].eia.rmse;
            if (j == i || !rs[j].timed || !(tj > 0.0))
                continue;
            dominated = tj <= ti && ej <= ei && (tj < ti || ej < ei);
        }
        front[i] = !dominated;
    }
    return front;
}

std::string matrixCsv(const std::vector<BenchReport>& reports)
{
    std::ostringstream s;
    s << "scene,triangles,drawn_triangles,views,view_width,view_height,config,renderer,aa,ss,timed,frames,"
         "point_generation_ms,points,view_generation_ms,resolve_ms,downsample_ms,eia_ms,total_ms,total_median_ms,"
         "speedup_vs_mvr,mvr_baseline,eia_rmse,eia_psnr,eia_ssim,eia_flip,view_rmse,view_psnr,view_ssim,view_flip,"
         "views_rmse,views_ssim,lens_rmse,lens_psnr,lens_ssim,lens_flip,lens_sweep_positions,lens_sweep_rmse_mean,"
         "lens_sweep_rmse_worst,lens_sweep_ssim_mean,lens_sweep_ssim_worst,pareto,reference,seconds\n";
    for (const BenchReport& rep : reports) {
        const std::vector<bool> front = paretoFront(rep);
        for (size_t i = 0; i < rep.results.size(); ++i) {
            const RendererResult& r = rep.results[i];
            const RendererResult* base = rep.mvrBaseline(r);
            const double total = stageMs(r, stage::kTotal);
            const auto points = r.extraValue("points");
            const auto totalIt = r.stages.find(std::string(stage::kTotal));
            s << sceneName(rep) << ',' << rep.triangles << ',' << rep.drawnTriangles << ',' << rep.profile.viewCount
              << ',' << rep.profile.viewWidth << ',' << rep.profile.viewHeight << ',' << r.name << ',' << r.renderer
              << ',' << r.aa << ',' << r.ss << ',' << (r.timed ? 1 : 0) << ','
              << (r.timed ? rep.options.frames : 0u) << ',' << num(stageMs(r, stage::kPointGeneration)) << ','
              << (points ? num(*points) : "") << ',' << num(stageMs(r, stage::kViewGeneration)) << ','
              << num(stageMs(r, stage::kResolve)) << ',' << num(stageMs(r, stage::kDownsample)) << ','
              << num(stageMs(r, stage::kEia)) << ',' << num(total) << ','
              << (totalIt != r.stages.end() ? num(totalIt->second.median()) : "") << ','
              << (base && r.timed && total > 0.0 ? num(base->stageMean(std::string(stage::kTotal)) / total) : "")
              << ',' << (base ? base->name : "");
            for (const Quality* q : {&r.eia, &r.centreView})
                s << ',' << num(q->rmse) << ',' << num(q->psnr) << ',' << num(q->ssim) << ',' << num(q->flip);
            s << ',' << num(r.allViews.rmse) << ',' << num(r.allViews.ssim);
            s << ',' << num(r.lens.rmse) << ',' << num(r.lens.psnr) << ',' << num(r.lens.ssim) << ','
              << num(r.lens.flip) << ',' << r.lensSweep.positions.size() << ',' << num(r.lensSweep.rmseMean) << ','
              << num(r.lensSweep.rmseWorst) << ',' << num(r.lensSweep.ssimMean) << ','
              << num(r.lensSweep.ssimWorst);
            s << ',' << (front[i] ? 1 : 0) << ',' << rep.options.reference << ',' << num(r.seconds) << '\n';
        }
    }
    return s.str();
}

nlohmann::json matrixJson(const std::vector<BenchReport>& reports)
{
    nlohmann::json j;
    j["tool"] = "lfd-bench";
    j["version"] = LFD_VERSION;
    bool interrupted = false;
    nlohmann::json runs = nlohmann::json::array();
    for (const BenchReport& rep : reports) {
        nlohmann::json run = benchJson(rep);
        run["aa"] = nlohmann::json::array();
        for (const Reconstruction a : rep.options.aa)
            run["aa"].push_back(reconstructionName(a));
        run["ss"] = nlohmann::json::array();
        for (const Supersampling x : rep.options.ss)
            run["ss"].push_back(supersamplingName(x));
        run["interrupted"] = rep.interrupted;
        const std::vector<bool> front = paretoFront(rep);
        for (size_t i = 0; i < rep.results.size(); ++i) {
            const RendererResult& r = rep.results[i];
            nlohmann::json& e = run["renderers"][i];
            e["renderer"] = r.renderer;
            e["aa"] = r.aa;
            e["ss"] = r.ss;
            e["pareto"] = bool(front[i]);
            nlohmann::json positions = nlohmann::json::array();
            for (const Quality& q : r.lensSweep.positions)
                positions.push_back({{"rmse", q.rmse}, {"ssim", q.ssim}});
            e["quality"]["lens_sweep"] = {{"positions", r.lensSweep.positions.size()},
                                          {"rmse_mean", r.lensSweep.rmseMean},
                                          {"rmse_worst", r.lensSweep.rmseWorst},
                                          {"ssim_mean", r.lensSweep.ssimMean},
                                          {"ssim_worst", r.lensSweep.ssimWorst},
                                          {"per_position", positions}};
            e["quality"]["lens"] = {{"rmse", r.lens.rmse},
                                    {"psnr", std::isfinite(r.lens.psnr) ? nlohmann::json(r.lens.psnr) : nlohmann::json()},
                                    {"ssim", r.lens.ssim},
                                    {"flip", std::isfinite(r.lens.flip) ? nlohmann::json(r.lens.flip) : nlohmann::json()}};
        }
        interrupted = interrupted || rep.interrupted;
        runs.push_back(run);
    }
    j["interrupted"] = interrupted;
    j["runs"] = runs;
    return j;
}

namespace {

// The run's settings, from the first report (every report of a matrix shares them).
void tableHeader(std::ostringstream& s, const std::vector<BenchReport>& reports)
{
    s << "# lfd-bench matrix\n\n";
    if (reports.empty())
        return;
    const BenchReport& first = reports.front();
    s << "GL: " << first.gl << "  \n";
    s << "Frames: " << first.options.warmup << " warm-up + " << first.options.frames
      << " timed per configuration (frame k at k/" << first.options.fps << " s, turntable period "
      << first.options.turntablePeriod << " s); quality at frame " << first.options.qualityFrame << " against "
      << first.options.reference;
    if (first.options.reference == "gstd") {
        const GstdOptions& g = first.options.rendererOptions.gstd;
        s << " (" << gstdModelName(g.model) << " model, `--gstd-model`: " << g.subViewCount()
          << " sub-views per view at factor " << g.factor;
        if (g.model == GstdModel::Views)
            s << ", " << g.samples << " Gaussian samples";
        s << ")";
    }
    s << "; texture anisotropy " << first.textureAnisotropy << " (`--aniso`).\n\n";
}

// The timing cells of one result: point generation (points), view generation with the
// resolve, EIA with the downsample, total (ratio to mvr); "-" where untimed.
struct TimingCells {
    std::string pointGen = "-", viewGen = "-", eia = "-", total = "-";
};

TimingCells timingCells(const BenchReport& rep, const RendererResult& r)
{
    TimingCells c;
    if (!r.timed)
        return c;
    if (const double pg = stageMs(r, stage::kPointGeneration); !std::isnan(pg)) {
        c.pointGen = fmt("%.1f", pg);
        if (const auto points = r.extraValue("points"))
            c.pointGen += " (" + count(*points) + ")";
    }
    double vg = stageMs(r, stage::kViewGeneration);
    if (const double rs = stageMs(r, stage::kResolve); !std::isnan(rs))
        vg += rs;
    c.viewGen = fmt("%.1f", vg);
    double e = stageMs(r, stage::kEia);
    if (const double ds = stageMs(r, stage::kDownsample); !std::isnan(ds))
        e += ds;
    c.eia = fmt("%.1f", e);
    const double t = stageMs(r, stage::kTotal);
    c.total = fmt("%.1f", t);
    if (const double pose = stageMs(r, stage::kPose); !std::isnan(pose) && t > 0.0) // skinned scenes
        c.total += " [pose " + fmt("%.1f", pose) + ", " + fmt("%.1f", 100.0 * pose / t) + "%]";
    if (const RendererResult* base = rep.mvrBaseline(r); base && t > 0.0)
        c.total += " (" + fmt("%.2f", base->stageMean(std::string(stage::kTotal)) / t) + "x)";
    return c;
}

void tableRows(std::ostringstream& s, const BenchReport& rep)
{
    const std::vector<bool> front = paretoFront(rep);
    const std::string scene = sceneName(rep) + " (" + count(double(rep.drawnTriangles)) + ")";
    const std::string views = std::to_string(rep.profile.viewCount) + " x " + std::to_string(rep.profile.viewWidth) +
                              "x" + std::to_string(rep.profile.viewHeight);
    for (size_t i = 0; i < rep.results.size(); ++i) {
        const RendererResult& r = rep.results[i];
        const TimingCells c = timingCells(rep, r);
        const bool ref = r.name == rep.options.reference && !r.timed;
        std::string method = r.renderer + (ref ? " (reference)" : "");
        if (front[i])
            method = "**" + method + "**";
        s << "| " << scene << " | " << views << " | " << method << " | " << r.aa << " | " << r.ss << " | "
          << c.pointGen << " | " << c.viewGen << " | " << c.eia << " | " << c.total << " | ";
        if (ref) {
            s << "- | - | - | - | - |\n";
            continue;
        }
        s << fmt("%.2f", r.eia.rmse) << " (" << fmt("%.2f", r.centreView.rmse) << ") | "
          << fmt("%.4f", r.eia.flip) << " (" << fmt("%.4f", r.centreView.flip) << ") | "
          << fmt("%.4f", r.eia.ssim) << " (" << fmt("%.4f", r.centreView.ssim) << ") | "
          << fmt("%.2f", r.lens.rmse) << " / " << fmt("%.4f", r.lens.flip) << " / " << fmt("%.4f", r.lens.ssim)
          << " | " << fmt("%.2f", r.lensSweep.rmseMean) << " / " << fmt("%.2f", r.lensSweep.rmseWorst) << " / "
          << fmt("%.4f", r.lensSweep.ssimWorst) << " |\n";
    }
}

void paretoSection(std::ostringstream& s, const std::vector<BenchReport>& reports)
{
    s << "\n## Pareto front (total time against EIA RMSE)\n\n";
    for (const BenchReport& rep : reports) {
        const std::vector<bool> front = paretoFront(rep);
        s << "* " << sceneName(rep) << " (" << rep.profile.viewCount << " views): ";
        bool any = false;
        for (size_t i = 0; i < rep.results.size(); ++i)
            if (front[i]) {
                s << (any ? ", " : "") << "`" << rep.results[i].name << "` ("
                  << fmt("%.0f ms", rep.results[i].stageMean(std::string(stage::kTotal))) << ", RMSE "
                  << fmt("%.2f", rep.results[i].eia.rmse) << ")";
                any = true;
            }
        s << (any ? "" : "none timed") << (rep.interrupted ? " (run interrupted: partial)" : "") << "\n";
    }
}

} // namespace

std::string matrixTable(const std::vector<BenchReport>& reports)
{
    std::ostringstream s;
    tableHeader(s, reports);
    s << "Mean GPU ms per stage (on Mesa llvmpipe GPU time is CPU time). *view gen* includes lfdpr's "
         "per-pixel shading (resolve); *EIA* includes the supersampling downsample. *total* is followed by "
         "the ratio mvr total / this total (mvr with the same reconstruction and supersampling; > 1: faster). "
         "Error against the reference: EIA (centre view in parentheses); *lens* = the simulated viewer's "
         "image at the centre view position, through the lenses, against the reference's; *lens sweep* = the "
         "same at K positions across the viewing cone (`--lens-positions`): mean RMSE / worst RMSE / worst SSIM. "
         "RMSE 0..255, FLIP "
         "0..1 (lower is better), SSIM on luma (1 = identical). **Bold**: on the scene's Pareto front of "
         "total time against EIA RMSE.\n\n";
    s << "| scene (tris) | views | method | AA | SS | point gen ms (points) | view gen ms | EIA ms | total ms "
         "(vs mvr) | RMSE | FLIP | SSIM | lens RMSE / FLIP / SSIM | lens sweep RMSE mean / worst, SSIM worst |\n";
    s << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const BenchReport& rep : reports)
        tableRows(s, rep);
    paretoSection(s, reports);
    return s.str();
}

void writeMatrixTables(const fs::path& dir, const std::vector<BenchReport>& reports)
{
    fs::create_directories(dir);
    writeFileAtomically(dir / "results.csv", matrixCsv(reports));
    writeFileAtomically(dir / "results.json", matrixJson(reports).dump(2) + "\n");
    writeFileAtomically(dir / "table.md", matrixTable(reports));
}

fs::path chartScriptPath()
{
    if (const char* env = std::getenv("LFD_BENCH_CHART_SCRIPT"); env && *env)
        return env;
    return LFD_BENCH_CHART_SCRIPT;
}

bool drawMatrixChart(const fs::path& dir, std::string& why)
{
    const fs::path script = chartScriptPath();
    if (!fs::is_regular_file(script)) {
        why = "chart script " + script.string() + " not found";
        return false;
    }
    // note: the `python3` on PATH may be a pyenv shim without matplotlib; Debian's
    // python3-matplotlib lives with /usr/bin/python3.
    for (const char* python : {"python3", "/usr/bin/python3"}) {
        const std::string probe = std::string(python) + " -c 'import matplotlib' >/dev/null 2>&1";
        if (std::system(probe.c_str()) != 0)
            continue;
        const std::string command = std::string(python) + " " + shellQuote(script.string()) + " " +
                                    shellQuote((dir / "results.csv").string()) + " " + shellQuote(dir.string());
        if (std::system(command.c_str()) == 0)
            return true;
        why = std::string(python) + " " + script.filename().string() + " failed";
        return false;
    }
    why = "no python3 with matplotlib (Debian: apt-get install python3-matplotlib)";
    return false;
}

} // namespace lfd::player
