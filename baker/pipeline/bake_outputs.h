// Where the bake writes and what it tells a build system: the output path as the user
// meant it (a folder names "<input stem>.lfdpack" inside it), checked before the import
// so a wrong path costs a moment, not a bake; and the depfile (--depfile) that lets Make,
// Ninja or CMake rebake only the packs whose inputs changed (docs/baker/batch-baking.md).
#pragma once

#include <filesystem>
#include <vector>

namespace lfd::bake {

// `output` as a file path: an existing folder, or a path ending in a separator, gets
// "<input stem><extension>" appended. Throws BakeError with one line when the folder the
// file would go in does not exist or is not a folder.
std::filesystem::path resolveOutputPath(const std::filesystem::path& input, const std::filesystem::path& output,
                                        const char* extension = ".lfdpack");

// The depfile line "TARGET: DEP DEP ..." in the syntax Make and Ninja read (spaces, '#'
// and '\' escaped with a backslash, '$' doubled); every dependency once, absolute.
std::string depfileText(const std::filesystem::path& target, const std::vector<std::filesystem::path>& inputs);
// Writes depfileText atomically (temporary beside `depfile`, renamed over it).
void writeDepfile(const std::filesystem::path& depfile, const std::filesystem::path& target,
                  const std::vector<std::filesystem::path>& inputs);

} // namespace lfd::bake
