// Memory-mapped read: the structural pass and the decoder of readPack on a read-only
// mapping, with the TEXL checksum deferred to the texel reads (pack_mapped.h).
#include "lfd/pack_mapped.h"

#include "pack_internal.h"

#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lfd {

namespace {

// Hashing catches up in windows of this size, releasing each one afterwards, so verifying
// a gap never makes a whole texture resident.
constexpr uint64_t kHashWindow = 8u << 20;

size_t pageSize()
{
    static const size_t page = size_t(::sysconf(_SC_PAGESIZE));
    return page;
}

} // namespace

struct MappedPack::HashState {
    std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state{XXH3_createState(), &XXH3_freeState};
};

MappedPack::MappedPack(const std::filesystem::path& path) : name_(path.string()), hash_(std::make_unique<HashState>())
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        pack::fail(name_, std::string("cannot open: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        pack::fail(name_, std::string("cannot stat: ") + std::strerror(err));
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        pack::fail(name_, "not a regular file");
    }
    size_ = uint64_t(st.st_size);
    static const uint8_t kEmpty = 0;
    data_ = &kEmpty; // size 0: validateStructure reports the short file
    if (size_ != 0) {
        void* p = ::mmap(nullptr, size_t(size_), PROT_READ, MAP_PRIVATE, fd, 0);
        if (p == MAP_FAILED) {
            const int err = errno;
            ::close(fd);
            pack::fail(name_, std::string("cannot map: ") + std::strerror(err));
        }
        data_ = static_cast<const uint8_t*>(p);
        mapped_ = true;
        // Payloads are read front to back once; tell the kernel so it reads ahead.
        ::madvise(p, size_t(size_), MADV_SEQUENTIAL);
    }
    ::close(fd); // the mapping keeps the file

    try {
        pack::SectionTable table = pack::validateStructure(data_, size_t(size_), name_, pack::kTagTexels);
        std::vector<pack::StoredTexture> stored;
        scene_ = pack::decodeScene(data_, table, name_, pack::TexelMode::Skip, &stored);
        for (const pack::SectionEntry& e : table.entries) {
            const uint8_t* payload = table.payload(data_, e);
            if (payload) // zstd sections by their inflated content (kept in inflated_)
                sections_.emplace_back(e.tag, std::span<const uint8_t>(
                                                  payload, size_t(e.encoding == pack::kEncodingZstd ? e.count * e.stride
                                                                                                    : e.size)));
        }
        inflated_ = std::move(table.inflated);
        for (const pack::StoredTexture& t : stored) {
            levelsZstd_.push_back(t.zstd);
            storedLevels_.push_back(t.levels);
        }
        const pack::SectionEntry& texl = *table.find(pack::kTagTexels);
        texlOffset_ = texl.offset;
        texlSize_ = texl.size;
        texlChecksum_ = texl.checksum;
        info_ = std::move(table.info);
    } catch (...) {
        if (mapped_)
            ::munmap(const_cast<uint8_t*>(data_), size_t(size_));
        throw;
    }
    // decodeScene checked that the textures' chains are consecutive and cover TEXL.
    textures_ = scene_.textures;
    if (!hash_->state || XXH3_64bits_reset(hash_->state.get()) != XXH_OK)
        pack::fail(name_, "cannot allocate the checksum state");
    // Validation touched every non-texel page; streaming reads them again window by window.
    releaseAll();
}

MappedPack::~MappedPack()
{
    if (mapped_)
        ::munmap(const_cast<uint8_t*>(data_), size_t(size_));
}

std::span<const uint8_t> MappedPack::section(uint32_t tag) const
{
    for (const auto& [t, bytes] : sections_)
        if (t == tag)
            return bytes;
    return {};
}

uint64_t MappedPack::mipTexelOffset(uint32_t texture, uint32_t level) const
{
    return storedLevels_.at(texture).at(level).first;
}

std::span<const uint8_t> MappedPack::mipBytes(uint32_t texture, uint32_t level) const
{
    const auto [offset, size] = storedLevels_.at(texture).at(level);
    return {data_ + texlOffset_ + offset, size_t(size)};
}

void MappedPack::hashRange(uint64_t offset, uint64_t size)
{
    XXH3_64bits_update(hash_->state.get(), data_ + texlOffset_ + offset, size_t(size));
    hashedUpTo_ = offset + size;
}

void MappedPack::noteTexelsRead(uint64_t offset, uint64_t size)
{
    if (offset > texlSize_ || size > texlSize_ - offset)
        pack::fail(name_, "texel range [" + std::to_string(offset) + ", +" + std::to_string(size) +
                              ") is outside the " + std::to_string(texlSize_) + "-byte texel section");
    const uint64_t end = offset + size;
    if (end <= hashedUpTo_)
        return; // already counted
    // The gap before this range: read it window by window and let it go again.
    while (hashedUpTo_ < offset) {
        const uint64_t from = hashedUpTo_;
        const uint64_t n = std::min(kHashWindow, offset - from);
        hashRange(from, n);
        releasePages(data_ + texlOffset_ + from, size_t(n));
    }
    hashRange(hashedUpTo_, end - hashedUpTo_); // the caller still holds these pages
}

void MappedPack::finishTexelVerification()
{
    if (verified_)
        return;
    while (hashedUpTo_ < texlSize_) {
        const uint64_t from = hashedUpTo_;
        const uint64_t n = std::min(kHashWindow, texlSize_ - from);
        hashRange(from, n);
        releasePages(data_ + texlOffset_ + from, size_t(n));
    }
    if (XXH3_64bits_digest(hash_->state.get()) != texlChecksum_)
        pack::fail(name_, "section 'TEXL' checksum mismatch (corrupt texels)");
    verified_ = true;
}

void MappedPack::releasePages(const void* data, size_t size) const
{
    if (!mapped_ || size == 0)
        return;
    // Only whole pages inside the range: a partial page may hold bytes still in use.
    const size_t page = pageSize();
    const auto begin = reinterpret_cast<uintptr_t>(data);
    const uintptr_t first = (begin + page - 1) / page * page;
    const uintptr_t last = (begin + size) / page * page;
    if (last > first)
        ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
}

void MappedPack::releaseAll() const
{
    if (mapped_)
        ::madvise(const_cast<uint8_t*>(data_), size_t(size_), MADV_DONTNEED);
}

} // namespace lfd
