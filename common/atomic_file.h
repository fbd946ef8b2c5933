// Atomic file replacement, the one way every tool writes a file (packs, depfiles, images,
// stats, bench reports, gstd cache entries, quilt videos): the content goes to a uniquely
// named temporary file beside the target (rename is atomic only within one file system),
// which is renamed over the target, so a reader sees the old file or the whole new one and
// a failed or interrupted write leaves nothing at the target or beside it. With
// `syncToDisk` (the pack writer) the temporary is flushed to stable storage before the
// rename, and the directory after it, so the new file also survives a power cut.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lfd {

// One line: "'<target>': <problem>"; problem() is the part after the target.
class AtomicWriteError : public std::runtime_error {
public:
    AtomicWriteError(const std::filesystem::path& target, const std::string& problem)
        : std::runtime_error("'" + target.string() + "': " + problem), problem_(problem)
    {
    }
    const std::string& problem() const { return problem_; }

private:
    std::string problem_;
};

struct AtomicWriteOptions {
    // fsync the temporary before the rename and the target's directory after it.
    bool syncToDisk = false;
};

// Calls writeTemporary(temporary) with a fresh path beside `target`, then renames it over
// `target`. If writeTemporary throws, or the sync or rename fails (AtomicWriteError), the
// temporary is removed before the exception leaves.
void replaceFileAtomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temporary)>& writeTemporary,
                           const AtomicWriteOptions& options = {});

// Writes `bytes` (or `text`) to `target` through replaceFileAtomically. Throws
// AtomicWriteError when the temporary cannot be opened or written.
void writeFileAtomically(const std::filesystem::path& target, std::span<const uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& target, std::string_view text);

} // namespace lfd
