// Atomic file replacement for every file the player's tools write (images, stats, bench
// reports, gstd cache entries, quilt videos): the content goes to a uniquely named
// temporary file beside the target (rename is atomic only within one file system), which
// is renamed over the target, so a reader sees the old file or the whole new one and a
// failed or interrupted write leaves nothing at the target or beside it.
// note: formats/ (the pack writer) keeps its own temporary + fsync + rename for now.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <stdexcept>
#include <string_view>

namespace lfd::io {

// One line: "'<target>': <problem>".
class AtomicWriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Calls writeTemporary(temporary) with a fresh path beside `target`, then renames it over
// `target`. If writeTemporary throws, or the rename fails (AtomicWriteError), the
// temporary is removed before the exception leaves.
void replaceFileAtomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temporary)>& writeTemporary);

// Writes `bytes` (or `text`) to `target` through replaceFileAtomically. Throws
// AtomicWriteError when the temporary cannot be opened or written.
void writeFileAtomically(const std::filesystem::path& target, std::span<const uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& target, std::string_view text);

} // namespace lfd::io
