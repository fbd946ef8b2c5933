// Atomic pack files: the pack is written to a temporary file next to `path`, flushed to
// disk and renamed over `path` (common/atomic_file.h, with syncToDisk), so readers see
// either the old file or the whole new one. On any failure the temporary is removed and
// `path` is not touched.
#include "pack_internal.h"

#include "atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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

} // namespace

} // namespace lfd::pack

namespace lfd {

void writePack(const std::filesystem::path& path, const Scene& scene, const TextureProducer& produce,
               const PackWriteOptions& options)
{
    const std::string name = path.string();
    const auto writeTemporary = [&](const std::filesystem::path& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file)
            pack::fail(name, "cannot create temporary file '" + temporary.string() + "': " + std::strerror(errno));
        const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(file, std::fclose);
        pack::FileSink sink(file, name);
        pack::emitPack(sink, scene, produce, options, name);
        if (std::fflush(file) != 0)
            pack::fail(name, std::string("cannot flush to disk: ") + std::strerror(errno));
    };
    try {
        replaceFileAtomically(path, writeTemporary, AtomicWriteOptions{.syncToDisk = true});
    } catch (const AtomicWriteError& e) {
        pack::fail(name, e.problem());
    }
}

} // namespace lfd
