// Atomic pack files: the pack is written to `<path>.tmp.<pid>` next to `path`, flushed
// to disk and renamed over `path`, so readers see either the old file or the whole new
// one. On any failure the temporary is removed and `path` is not touched.
#include "pack_internal.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace lfd::pack {

namespace {

class FileSink final : public Sink {
public:
    FileSink(std::FILE* file, const std::string& name) : file_(file), name_(name) {}
    void write(const void* data, size_t size) override
    {
        if (size != 0 && std::fwrite(data, 1, size, file_) != size)
            fail(name_, std::string("write failed: ") + std::strerror(errno));
    }
    void writeAt(uint64_t offset, const void* data, size_t size) override
    {
        if (std::fflush(file_) != 0 || fseeko(file_, off_t(offset), SEEK_SET) != 0)
            fail(name_, std::string("seek failed: ") + std::strerror(errno));
        write(data, size);
    }

private:
    std::FILE* file_;
    const std::string& name_;
};

// Removes the temporary file unless the write committed.
class TempFile {
public:
    explicit TempFile(std::filesystem::path path) : path_(std::move(path)) {}
    ~TempFile()
    {
        if (file_)
            std::fclose(file_);
        if (!committed_) {
            std::error_code ignored;
            std::filesystem::remove(path_, ignored);
        }
    }
    std::FILE* open()
    {
        file_ = std::fopen(path_.c_str(), "wb");
        return file_;
    }
    // Flushes to stable storage and closes; false (errno set) on failure.
    bool flushAndClose()
    {
        const bool ok = std::fflush(file_) == 0 && ::fsync(fileno(file_)) == 0;
        const int savedErrno = errno;
        const bool closed = std::fclose(file_) == 0;
        file_ = nullptr;
        if (!ok)
            errno = savedErrno;
        return ok && closed;
    }
    void commit() { committed_ = true; }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::FILE* file_ = nullptr;
    bool committed_ = false;
};

// Makes the rename durable; best effort, a failure here cannot un-write the pack.
void syncDirectory(const std::filesystem::path& dir)
{
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

} // namespace

} // namespace lfd::pack

namespace lfd {

void writePack(const std::filesystem::path& path, const Scene& scene, const TextureProducer& produce,
               const PackWriteOptions& options)
{
    const std::string name = path.string();
    pack::TempFile temp(path.string() + ".tmp." + std::to_string(::getpid()));
    std::FILE* file = temp.open();
    if (!file)
        pack::fail(name, "cannot create temporary file '" + temp.path().string() + "': " + std::strerror(errno));

    pack::FileSink sink(file, name);
    pack::emitPack(sink, scene, produce, options, name);
    if (!temp.flushAndClose())
        pack::fail(name, std::string("cannot flush to disk: ") + std::strerror(errno));

    std::error_code ec;
    std::filesystem::rename(temp.path(), path, ec);
    if (ec)
        pack::fail(name, "cannot rename the temporary file into place: " + ec.message());
    temp.commit();
    pack::syncDirectory(path.parent_path());
}

} // namespace lfd
