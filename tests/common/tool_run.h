// Running the project's command-line tools from tests: the command's exit status and its
// stdout + stderr together, shell quoting for paths, and a file's bytes. Shared by the
// tests of every command-line tool (lfd-bake, lfd-make-samples, lfd-play, lfd-bench).
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace lfd::test {

struct RunResult {
    int exitCode = -1;
    std::string out; // stdout + stderr
};

// Runs `command` through the shell; exitCode is -1 when it did not exit normally.
inline RunResult run(const std::string& command)
{
    RunResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
        return r;
    std::array<char, 4096> buffer{};
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        r.out.append(buffer.data(), n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// Lines in a tool's output: its newline characters, since every line a tool prints, the
// last included, ends with one (a last line without it is not counted).
inline size_t lineCount(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

#ifdef LFD_BINARY_DIR
// The tools in this build tree (LFD_BINARY_DIR: its top folder, set by tests/CMakeLists.txt).
inline const std::string kBake = std::string(LFD_BINARY_DIR) + "/baker/lfd-bake";
inline const std::string kMakeSamples = std::string(LFD_BINARY_DIR) + "/samples/lfd-make-samples";
inline const std::filesystem::path kPlay = std::filesystem::path(LFD_BINARY_DIR) / "player" / "lfd-play";
inline const std::filesystem::path kBenchTool = std::filesystem::path(LFD_BINARY_DIR) / "player" / "lfd-bench";
#endif

inline std::string readBytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

} // namespace lfd::test
