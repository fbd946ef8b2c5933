// Public read API: load the bytes, run the structural pass, decode and validate.
#include "pack_internal.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

namespace lfd::pack {

namespace {

// Whole file in one buffer of exactly its size: the reader needs the file's bytes plus
// the Scene, nothing proportional to counts claimed inside the file.
std::vector<uint8_t> loadFile(const std::filesystem::path& path, const std::string& name)
{
    std::unique_ptr<std::FILE, decltype(&std::fclose)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file)
        fail(name, std::string("cannot open: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fileno(file.get()), &st) != 0)
        fail(name, std::string("cannot stat: ") + std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        fail(name, "not a regular file");
    std::vector<uint8_t> bytes(size_t(st.st_size));
    if (!bytes.empty() && std::fread(bytes.data(), 1, bytes.size(), file.get()) != bytes.size())
        fail(name, std::string("read failed: ") + (std::ferror(file.get()) ? std::strerror(errno) : "file shrank"));
    return bytes;
}

} // namespace

} // namespace lfd::pack

namespace lfd {

Scene readPackFromMemory(const uint8_t* data, size_t size, const std::string& name)
{
    static const uint8_t kEmpty = 0;
    if (!data)
        data = &kEmpty; // size is 0 then; keeps pointer arithmetic defined
    const pack::SectionTable table = pack::validateStructure(data, size, name);
    return pack::decodeScene(data, table, name, pack::TexelMode::Copy);
}

Scene readPack(const std::filesystem::path& path, PackInfo* info)
{
    const std::string name = path.string();
    const std::vector<uint8_t> bytes = pack::loadFile(path, name);
    static const uint8_t kEmpty = 0;
    const uint8_t* data = bytes.empty() ? &kEmpty : bytes.data();
    pack::SectionTable table = pack::validateStructure(data, bytes.size(), name);
    Scene scene = pack::decodeScene(data, table, name, pack::TexelMode::Copy);
    if (info)
        *info = std::move(table.info);
    return scene;
}

PackInfo verifyPack(const std::filesystem::path& path)
{
    const std::string name = path.string();
    const std::vector<uint8_t> bytes = pack::loadFile(path, name);
    static const uint8_t kEmpty = 0;
    const uint8_t* data = bytes.empty() ? &kEmpty : bytes.data();
    pack::SectionTable table = pack::validateStructure(data, bytes.size(), name);
    pack::decodeScene(data, table, name, pack::TexelMode::Verify); // every rule and zstd level, no texel copy
    return std::move(table.info);
}

} // namespace lfd
