#include "quilt_video.h"

#include "atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace lfd::player {

namespace {

namespace fs = std::filesystem;

std::string containerOf(const fs::path& video)
{
    const std::string ext = video.extension().string();
    if (ext == ".mp4")
        return "mp4";
    if (ext == ".webm")
        return "webm";
    return {};
}

// The last non-empty line of a text file (ffmpeg's final error message).
std::string lastLine(const fs::path& path)
{
    std::ifstream in(path);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            last = line;
    return last;
}

// Runs `program` with `args`, stdin from /dev/null, stdout and stderr into `log`; returns
// the exit status (-1 when it could not start or was killed).
int runProcess(const fs::path& program, const std::vector<std::string>& args, const fs::path& log)
{
    std::vector<char*> argv;
    const std::string argv0 = program.string();
    argv.push_back(const_cast<char*>(argv0.c_str()));
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv0.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

void checkVideoExtension(const fs::path& video)
{
    if (containerOf(video).empty())
        throw std::invalid_argument("'" + video.string() + "': expected a .mp4 (H.264) or .webm (VP9) file name");
}

fs::path findOnPath(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    size_t start = 0;
    while (start <= dirs.size()) {
        const size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(end > start ? dirs.substr(start, end - start) : ".") / name;
        if (access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate))
            return candidate;
        start = end + 1;
    }
    return {};
}

std::vector<std::string> ffmpegArguments(const fs::path& pattern, double fps, const fs::path& output,
                                         const std::string& container, uint32_t firstNumber)
{
    char rate[32];
    std::snprintf(rate, sizeof(rate), "%.6g", fps);
    std::vector<std::string> args = {"-hide_banner", "-loglevel", "error", "-nostdin", "-y", "-framerate", rate,
                                     "-start_number", std::to_string(firstNumber), "-i", pattern.string(),
                                     // 4:2:0 chroma needs even sizes: pad (never scale) a quilt with odd ones.
                                     "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"};
    // note: high quality settings - a quilt's tiles are small, and blur across the
    // lenticular views shows as ghosting on the display.
    if (container == "webm")
        args.insert(args.end(), {"-c:v", "libvpx-vp9", "-crf", "18", "-b:v", "0", "-f", "webm"});
    else
        args.insert(args.end(), {"-c:v", "libx264", "-preset", "medium", "-crf", "15", "-movflags", "+faststart",
                                 "-f", "mp4"});
    args.push_back(output.string());
    return args;
}

void encodeQuiltVideo(const fs::path& pattern, double fps, const fs::path& video, uint32_t firstNumber)
{
    const std::string container = containerOf(video);
    if (container.empty())
        throw VideoError(video.string() + ": expected a .mp4 or .webm file name");
    const fs::path ffmpeg = findOnPath("ffmpeg");
    if (ffmpeg.empty())
        throw VideoError("cannot write " + video.string() +
                         ": ffmpeg is missing (not on PATH; install the Debian package 'ffmpeg')");
    replaceFileAtomically(video, [&](const fs::path& temporary) {
        const fs::path log = temporary.string() + ".log";
        const int status = runProcess(ffmpeg, ffmpegArguments(pattern, fps, temporary, container, firstNumber), log);
        const std::string message = lastLine(log);
        std::error_code ec;
        fs::remove(log, ec);
        if (status != 0)
            throw VideoError("ffmpeg failed to write " + video.string() + " (exit " + std::to_string(status) + ")" +
                             (message.empty() ? "" : ": " + message));
    });
}

} // namespace lfd::player
