// lfd-compare: compares a test image with a reference image of the same size and prints RMSE, PSNR,
// SSIM and LDR FLIP (as text, or one JSON object with --json); --diff writes the per-pixel FLIP
// error as a magma heat map. See docs/compare.md, and image_metrics.h for each metric's definition.
#include "image_file.h"
#include "image_metrics.h"

#include "cli_support.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace {

using namespace lfd::metrics;

std::string sizeText(const RgbImage& image)
{
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

struct Scores {
    double rmse = 0.0, psnr = 0.0, ssim = 0.0, flip = 0.0;
};

void printText(const Scores& s)
{
    std::printf("rmse: %.4f\n", s.rmse);
    if (std::isinf(s.psnr))
        std::printf("psnr: inf\n");
    else
        std::printf("psnr: %.4f\n", s.psnr);
    std::printf("ssim: %.6f\n", s.ssim);
    std::printf("flip: %.6f\n", s.flip);
}

// JSON has no infinity: identical images give "psnr": null.
void printJson(const Scores& s)
{
    nlohmann::ordered_json j;
    j["rmse"] = s.rmse;
    j["psnr"] = std::isinf(s.psnr) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.psnr);
    j["ssim"] = s.ssim;
    j["flip"] = s.flip;
    std::cout << j.dump() << "\n";
}

} // namespace

int main(int argc, char** argv)
{
    std::string referencePath, testPath, diffPath;
    bool json = false;
    double ppd = defaultFlipPixelsPerDegree();

    CLI::App app{"lfd-compare: compare a test image with a reference image of the same size "
                 "(RMSE 0..255, PSNR dB, SSIM on luma, LDR FLIP)"};
    app.add_option("REFERENCE", referencePath, "reference image (PNG, JPEG, BMP, TGA, HDR, ...: image_file.h)")
        ->required();
    app.add_option("TEST", testPath, "test image, same width and height as the reference")->required();
    app.add_flag("--json", json, "print one JSON object {rmse, psnr, ssim, flip}; psnr is null for identical images");
    app.add_option("--diff", diffPath, "write the per-pixel FLIP error as a magma heat map (0 black .. 1 pale yellow)");
    app.add_option("--ppd", ppd, "FLIP observer's pixels per degree (default 67.02: 0.7 m from a 0.7 m wide 3840-pixel monitor)")
        ->check(CLI::Range(0.01, 10000.0));

    if (const auto exit = lfd::cli::parseCommandLine(app, argc, argv, "lfd-compare"))
        return *exit;

    return lfd::cli::runReportingErrors("lfd-compare", [&] {
        if (!diffPath.empty())
            if (const std::string problem = imageFormatProblem(diffPath); !problem.empty())
                throw lfd::cli::UsageError("--diff: '" + diffPath + "': " + problem);
        const RgbImage reference = readRgbImage(referencePath);
        const RgbImage test = readRgbImage(testPath);
        if (reference.width != test.width || reference.height != test.height)
            throw ImageError("'" + testPath + "': size " + sizeText(test) +
                                 " differs from the reference '" + referencePath + "' (" +
                                 sizeText(reference) + ")");

        Scores scores;
        scores.rmse = rmse(reference, test);
        scores.psnr = psnrFromRmse(scores.rmse);
        scores.ssim = ssim(reference, test);
        const std::vector<float> flipMap = flipErrorMap(reference, test, ppd);
        double sum = 0.0;
        for (float e : flipMap)
            sum += e;
        scores.flip = sum / double(flipMap.size());

        if (!diffPath.empty())
            writeHeatMap(diffPath, flipMap, reference.width, reference.height);
        if (json)
            printJson(scores);
        else
            printText(scores);
        return 0;
    });
}
