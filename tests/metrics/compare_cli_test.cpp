// End-to-end tests of lfd-compare: text and JSON output on PNGs written here, the --diff
// heat map, and one-line errors with a non-zero exit.
#include "metric_test_images.h"
#include "tool_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lfd::metrics {
namespace {

using namespace lfd::metrics::test;
using lfd::test::lineCount;
using lfd::test::quoted;
using lfd::test::readBytes;

const std::string kCompare = std::string(LFD_BINARY_DIR) + "/player/metrics/lfd-compare";

struct RunResult {
    int exitCode = -1;
    std::string out; // stdout
    std::string err; // stderr
};

std::vector<uint8_t> toBytes(const RgbImage& image)
{
    std::vector<uint8_t> bytes;
    for (float v : image.rgb)
        bytes.push_back(uint8_t(std::lround(v)));
    return bytes;
}

class CompareCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("lfd_compare_cli_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        // Whole 8-bit values, so the images in memory are exactly the ones on disk.
        reference_ = rgbFromPixels8(toBytes(gradientImage(40, 30)).data(), 40, 30, 3);
        writeRgb8Image(dir_ / "ref.png", toBytes(reference_), 40, 30);
        writeRgb8Image(dir_ / "plus5.png", toBytes(offsetImage(reference_, 5.0f)), 40, 30);
        noisy_ = noisyImage(reference_, 12.0, 31, true);
        writeRgb8Image(dir_ / "noisy.png", toBytes(noisy_), 40, 30);
        writeRgb8Image(dir_ / "small.png", toBytes(greyImage(20, 30, 0.0f)), 20, 30);
    }
    void TearDown() override { fs::remove_all(dir_); }

    RunResult run(const std::string& arguments)
    {
        RunResult r;
        const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
        const int status = std::system((kCompare + " " + arguments + " >" + quoted(out) + " 2>" +
                                        quoted(err)).c_str());
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = readBytes(out);
        r.err = readBytes(err);
        fs::remove(out);
        fs::remove(err);
        return r;
    }

    fs::path dir_;
    RgbImage reference_, noisy_;
};

TEST_F(CompareCli, IdenticalImagesPrintZeroErrorsAndInfinitePsnr)
{
    const RunResult r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "ref.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "rmse: 0.0000\npsnr: inf\nssim: 1.000000\nflip: 0.000000\n");
    EXPECT_EQ(r.err, "");
}

TEST_F(CompareCli, TextOutputHasTheLibraryValues)
{
    // A constant offset of 5: rmse 5, psnr 20 log10(51) = 34.1514.
    RunResult r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "plus5.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.substr(0, r.out.find("ssim")), "rmse: 5.0000\npsnr: 34.1514\n");

    r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "noisy.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    double e = 0, p = 0, s = 0, f = 0;
    ASSERT_EQ(std::sscanf(r.out.c_str(), "rmse: %lf\npsnr: %lf\nssim: %lf\nflip: %lf\n", &e, &p, &s, &f), 4)
        << r.out;
    EXPECT_EQ(lineCount(r.out), 4u);
    EXPECT_NEAR(e, rmse(reference_, noisy_), 1e-4);
    EXPECT_NEAR(p, psnr(reference_, noisy_), 1e-4);
    EXPECT_NEAR(s, ssim(reference_, noisy_), 1e-6);
    EXPECT_NEAR(f, flip(reference_, noisy_), 1e-6);
    EXPECT_NEAR(e, 12.0, 1.0); // the noise's standard deviation
}

TEST_F(CompareCli, JsonOutputIsOneObjectWithTheFourKeys)
{
    RunResult r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "noisy.png") + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineCount(r.out), 1u);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j.size(), 4u);
    EXPECT_NEAR(j.at("rmse").get<double>(), rmse(reference_, noisy_), 1e-9);
    EXPECT_NEAR(j.at("psnr").get<double>(), psnr(reference_, noisy_), 1e-9);
    EXPECT_NEAR(j.at("ssim").get<double>(), ssim(reference_, noisy_), 1e-9);
    EXPECT_NEAR(j.at("flip").get<double>(), flip(reference_, noisy_), 1e-9);

    r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "ref.png") + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json same = nlohmann::json::parse(r.out);
    EXPECT_TRUE(same.at("psnr").is_null()); // infinite: JSON has no infinity
    EXPECT_EQ(same.at("rmse").get<double>(), 0.0);
    EXPECT_EQ(same.at("ssim").get<double>(), 1.0);
    EXPECT_EQ(same.at("flip").get<double>(), 0.0);
}

TEST_F(CompareCli, DiffWritesTheFlipHeatMapAtTheImageSize)
{
    const fs::path diff = dir_ / "diff.png";
    RunResult r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "noisy.png") + " --diff " + quoted(diff));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(fs::exists(diff));
    const RgbImage heat = readRgbImage(diff);
    EXPECT_EQ(heat.width, 40);
    EXPECT_EQ(heat.height, 30);
    // Pixel by pixel the magma colour of the library's FLIP error map.
    const std::vector<uint8_t> expected = heatMapRgb8(flipErrorMap(reference_, noisy_));
    ASSERT_EQ(heat.rgb.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i)
        ASSERT_NEAR(heat.rgb[i], float(expected[i]), 1.0f) << i;

    // Identical images: every pixel is magma(0).
    r = run(quoted(dir_ / "ref.png") + " " + quoted(dir_ / "ref.png") + " --diff " + quoted(diff));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const RgbImage zero = readRgbImage(diff);
    for (size_t i = 0; i < zero.pixelCount(); ++i)
        ASSERT_EQ((Rgb8{uint8_t(zero.rgb[i * 3]), uint8_t(zero.rgb[i * 3 + 1]), uint8_t(zero.rgb[i * 3 + 2])}),
                  magma(0.0));
}

TEST_F(CompareCli, ErrorsAreOneLineNamingTheFileWithNonZeroExit)
{
    struct Case {
        std::string arguments, file, problem;
    };
    std::ofstream(dir_ / "text.png") << "not a png\n";
    const std::vector<Case> cases = {
        {quoted(dir_ / "absent.png") + " " + quoted(dir_ / "ref.png"), "absent.png", "no such file"},
        {quoted(dir_ / "ref.png") + " " + quoted(dir_ / "absent.png"), "absent.png", "no such file"},
        {quoted(dir_ / "text.png") + " " + quoted(dir_ / "ref.png"), "text.png", "cannot read image"},
        {quoted(dir_ / "ref.png") + " " + quoted(dir_ / "small.png"), "small.png", "differs from the reference"},
        {quoted(dir_ / "ref.png") + " " + quoted(dir_ / "ref.png") + " --diff " +
             quoted(dir_ / "no_dir" / "d.png"),
         "d.png", "cannot"},
        // A diff name it cannot write fails before the images are read (even absent ones).
        {quoted(dir_ / "absent.png") + " " + quoted(dir_ / "ref.png") + " --diff " + quoted(dir_ / "d.gif"),
         "--diff: '" + (dir_ / "d.gif").string() + "'", "cannot write this image format '.gif'"},
        {quoted(dir_ / "ref.png") + " " + quoted(dir_ / "ref.png") + " --diff " + quoted(dir_ / "d"), "d'",
         "has no image extension"},
    };
    for (const Case& c : cases) {
        const RunResult r = run(c.arguments);
        EXPECT_NE(r.exitCode, 0) << c.arguments;
        EXPECT_EQ(r.out, "") << c.arguments;
        EXPECT_EQ(lineCount(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(c.file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
    }
    // Usage errors: a missing argument, an unknown flag.
    for (const std::string& arguments : {quoted(dir_ / "ref.png"), quoted(dir_ / "ref.png") + " x.png --bogus"}) {
        const RunResult r = run(arguments);
        EXPECT_EQ(r.exitCode, 2) << arguments;
        EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "no_dir"));
    EXPECT_FALSE(fs::exists(dir_ / "d.gif"));
    EXPECT_FALSE(fs::exists(dir_ / "d"));
}

} // namespace
} // namespace lfd::metrics
