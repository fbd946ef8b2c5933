#include "bake_outputs.h"

#include "atomic_file.h"
#include "bake_log.h"

#include <set>
#include <string>
#include <system_error>

namespace lfd::bake {

std::filesystem::path resolveOutputPath(const std::filesystem::path& input, const std::filesystem::path& output,
                                        const char* extension)
{
    std::error_code ec;
    std::filesystem::path file = output;
    const std::string text = output.string();
    const bool namesFolder = !text.empty() && (text.back() == '/' || std::filesystem::is_directory(output, ec));
    if (namesFolder)
        file = output / (input.stem().string() + extension);
    const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
    if (!std::filesystem::exists(folder, ec))
        throw BakeError(file.string() + ": cannot write: folder '" + folder.string() + "' does not exist");
    if (!std::filesystem::is_directory(folder, ec))
        throw BakeError(file.string() + ": cannot write: '" + folder.string() + "' is not a folder");
    return file;
}

namespace {

// Make's and Ninja's depfile escapes: a space or '#' after a backslash, '$' doubled.
std::string escapeDepfilePath(const std::string& path)
{
    std::string out;
    for (char c : path) {
        if (c == ' ' || c == '#' || c == '\\')
            out += '\\';
        if (c == '$')
            out += '$';
        out += c;
    }
    return out;
}

} // namespace

std::string depfileText(const std::filesystem::path& target, const std::vector<std::filesystem::path>& inputs)
{
    std::string text = escapeDepfilePath(target.string()) + ":";
    std::set<std::string> seen;
    for (const std::filesystem::path& input : inputs) {
        std::error_code ec;
        std::filesystem::path absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(input), ec);
        if (ec)
            absolute = std::filesystem::absolute(input).lexically_normal();
        if (seen.insert(absolute.string()).second)
            text += " \\\n  " + escapeDepfilePath(absolute.string());
    }
    return text + "\n";
}

void writeDepfile(const std::filesystem::path& depfile, const std::filesystem::path& target,
                  const std::vector<std::filesystem::path>& inputs)
{
    try {
        writeFileAtomically(depfile, depfileText(target, inputs));
    } catch (const AtomicWriteError& e) {
        throw BakeError(std::string("--depfile ") + e.what());
    }
}

} // namespace lfd::bake
