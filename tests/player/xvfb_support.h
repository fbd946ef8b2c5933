// Xvfb for the windowed tests: a virtual X server of a chosen screen size on a display
// number it picks itself, stopped (by its pid) when the object goes away. With a framebuffer directory
// (-fbdir) the server keeps its screen in an XWD file that readScreen() decodes - a
// capture of what the screen shows, independent of the program under test (so a window
// at the wrong place, scaled, or colour-converted shows up).
#pragma once

#include "image_metrics.h"

#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace lfd::test {

inline std::string findXvfb()
{
    for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"})
        if (std::filesystem::exists(std::filesystem::path(dir) / "Xvfb"))
            return (std::filesystem::path(dir) / "Xvfb").string();
    return {};
}

class XvfbServer {
public:
    // `screen`: "WxHxDEPTH"; `fbdir`: empty, or a directory for the screen's XWD file.
    // note: Xvfb picks a free display number itself and reports it through -displayfd:
    // choosing one by looking for free sockets races with other test runs on the machine
    // (two servers start on one number, one exits, and the loser's test talks to the
    // winner's server until that goes away).
    explicit XvfbServer(const std::string& binary, const std::string& screen = "1280x800x24",
                        const std::filesystem::path& fbdir = {})
        : fbdir_(fbdir)
    {
        int fds[2];
        if (pipe(fds) != 0)
            return;
        // The child inherits the write end under its own number (pipes are not close-on-exec).
        // note: -noreset. By default an X server resets itself whenever its last client
        // disconnects, and a client connecting during the reset is refused; tests that run
        // lfd-play several times in a row then saw "cannot connect to a display" at random.
        std::vector<std::string> args = {binary, "-displayfd", std::to_string(fds[1]), "-screen", "0", screen,
                                         "-nolisten", "tcp", "-noreset"};
        if (!fbdir.empty())
            args.insert(args.end(), {"-fbdir", fbdir.string()});
        std::vector<char*> argv;
        for (std::string& a : args)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addclose(&actions, fds[0]);
        pid_t pid = 0;
        const bool spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ) == 0;
        posix_spawn_file_actions_destroy(&actions);
        close(fds[1]);
        // The display number followed by a newline once the server accepts connections;
        // end of file if it failed.
        std::string number;
        char c = 0;
        while (spawned && read(fds[0], &c, 1) == 1 && c != '\n')
            number += c;
        close(fds[0]);
        if (!spawned)
            return;
        if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) {
            kill(pid, SIGTERM);
            waitpid(pid, nullptr, 0);
            return;
        }
        pid_ = pid;
        display_ = ":" + number;
    }
    ~XvfbServer()
    {
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    XvfbServer(const XvfbServer&) = delete;
    XvfbServer& operator=(const XvfbServer&) = delete;

    const std::string& display() const { return display_; }

    // The screen as RGB8 (image order), decoded from Xvfb's XWD framebuffer file: a
    // 100-byte big-endian header of 25 CARD32 (XWDFileHeader), the window name, ncolors
    // 12-byte colour entries, then the pixels (32 bits per pixel at depth 24).
    metrics::Image readScreen() const
    {
        std::ifstream in(fbdir_ / "Xvfb_screen0", std::ios::binary);
        const std::vector<uint8_t> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (b.size() < 100)
            throw std::runtime_error("Xvfb framebuffer file missing or short");
        auto field = [&](int i) {
            return uint32_t(b[4 * i]) << 24 | uint32_t(b[4 * i + 1]) << 16 | uint32_t(b[4 * i + 2]) << 8 | b[4 * i + 3];
        };
        const uint32_t headerSize = field(0), width = field(4), height = field(5), byteOrder = field(7);
        const uint32_t bitsPerPixel = field(11), bytesPerLine = field(12), redMask = field(14), ncolors = field(19);
        if (bitsPerPixel != 32 || redMask != 0xff0000u)
            throw std::runtime_error("unexpected Xvfb pixel format");
        const size_t offset = size_t(headerSize) + size_t(ncolors) * 12;
        if (b.size() < offset + size_t(bytesPerLine) * height)
            throw std::runtime_error("Xvfb framebuffer file truncated");
        metrics::Image image{width, height, 3, std::vector<uint8_t>(size_t(width) * height * 3)};
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x) {
                const uint8_t* p = &b[offset + size_t(y) * bytesPerLine + size_t(x) * 4];
                uint8_t* q = &image.pixels[(size_t(y) * width + x) * 3];
                // 0x00RRGGBB as a 32-bit word: LSBFirst stores B, G, R, X.
                q[0] = byteOrder == 0 ? p[2] : p[1];
                q[1] = byteOrder == 0 ? p[1] : p[2];
                q[2] = byteOrder == 0 ? p[0] : p[3];
            }
        return image;
    }

private:
    pid_t pid_ = -1;
    std::string display_;
    std::filesystem::path fbdir_;
};

// Output of a shell command (stdout), trailing newline removed.
inline std::string capture(const std::string& command)
{
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[512];
        while (fgets(buffer, sizeof(buffer), pipe))
            out += buffer;
        pclose(pipe);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    return out;
}

} // namespace lfd::test
