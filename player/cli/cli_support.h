// Command-line scaffolding shared by lfd-play, lfd-bench and lfd-compare, so the three
// tools report errors the same way: one line on stderr prefixed by the tool's name, exit 2
// for a usage error (bad flag or value, checked before any file or GPU work), exit 1 for
// a failure while running (a missing or corrupt file, a GL error).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lfd::cli {

// A flag or value the user must fix; main() maps it to exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Exception text on one line (newlines become spaces).
std::string oneLine(std::string text);

// Parses argv. Returns the exit code when the run should end here (--help: 0, a parse
// error: 2 after printing "<tool>: <error> (see --help)"), or nullopt to go on.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const char* tool);

// Runs the tool's body: UsageError -> exit 2, any other std::exception -> exit 1, each
// printed as "<tool>: <message>" on one line.
int runReportingErrors(const char* tool, const std::function<int()>& body);

// A flag's number as the user would type it, for "got ..." in an error: "-1", "0.25",
// "inf", "nan" (%g: the shortest form that still tells the value).
std::string numberText(double value);

// "480x360" -> (480, 360), both 1..999999; UsageError naming `flag` otherwise.
std::pair<uint32_t, uint32_t> parseSize(const std::string& flag, const std::string& text);

// "a, b,,c" -> {"a", "b", "c"}: trimmed, empty items dropped, duplicates dropped, order kept.
std::vector<std::string> splitList(const std::string& text);

// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);

// An output file written only at the end of a run: its directory must exist and the path
// must not be a directory, checked up front so a typo fails before minutes of rendering.
void checkOutputPath(const std::string& flag, const std::filesystem::path& path);

} // namespace lfd::cli
