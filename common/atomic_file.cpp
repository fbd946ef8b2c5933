#include "atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace lfd {

namespace fs = std::filesystem;

namespace {

std::string lastError()
{
    return std::error_code(errno, std::generic_category()).message();
}

// Hidden, and unique per process and call, so concurrent writers of one target (two
// processes filling one gstd cache) never share a temporary.
fs::path temporaryBeside(const fs::path& target)
{
    static std::atomic<unsigned> counter{0};
    return target.parent_path() /
           ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

struct FileCloser {
    void operator()(FILE* file) const { std::fclose(file); }
};

void writeBytes(const fs::path& target, const fs::path& temporary, const void* data, size_t size)
{
    const std::unique_ptr<FILE, FileCloser> out(std::fopen(temporary.c_str(), "wb"));
    if (!out)
        throw AtomicWriteError(target, "cannot open for writing (" + lastError() + ")");
    const bool written = size == 0 || std::fwrite(data, 1, size, out.get()) == size;
    if (!written || std::fflush(out.get()) != 0)
        throw AtomicWriteError(target, "write failed (" + lastError() + ")");
}

// Flushes the written temporary to stable storage (fsync reaches the file's data through
// any descriptor of it).
void syncFile(const fs::path& target, const fs::path& temporary)
{
    const int fd = ::open(temporary.c_str(), O_RDONLY);
    const bool ok = fd >= 0 && ::fsync(fd) == 0;
    const int savedErrno = errno;
    if (fd >= 0)
        ::close(fd);
    if (!ok) {
        errno = savedErrno;
        throw AtomicWriteError(target, "cannot flush to disk (" + lastError() + ")");
    }
}

// Makes the rename durable; best effort, a failure here cannot un-write the file.
void syncDirectory(const fs::path& dir)
{
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

} // namespace

void replaceFileAtomically(const fs::path& target, const std::function<void(const fs::path& temporary)>& writeTemporary,
                           const AtomicWriteOptions& options)
{
    const fs::path temporary = temporaryBeside(target);
    auto removeTemporary = [&] {
        std::error_code ignored;
        fs::remove(temporary, ignored);
    };
    try {
        writeTemporary(temporary);
        if (options.syncToDisk)
            syncFile(target, temporary);
    } catch (...) {
        removeTemporary();
        throw;
    }
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        removeTemporary();
        throw AtomicWriteError(target, "cannot move the written file into place: " + ec.message());
    }
    if (options.syncToDisk)
        syncDirectory(target.parent_path());
}

void writeFileAtomically(const fs::path& target, std::span<const uint8_t> bytes)
{
    replaceFileAtomically(target, [&](const fs::path& temporary) {
        writeBytes(target, temporary, bytes.data(), bytes.size());
    });
}

void writeFileAtomically(const fs::path& target, std::string_view text)
{
    replaceFileAtomically(target, [&](const fs::path& temporary) {
        writeBytes(target, temporary, text.data(), text.size());
    });
}

} // namespace lfd
