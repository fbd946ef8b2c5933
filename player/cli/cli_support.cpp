#include "cli_support.h"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <sstream>

namespace lfd::cli {

std::string oneLine(std::string text)
{
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return text;
}

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const char* tool)
{
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: %s (see --help)\n", tool, oneLine(e.what()).c_str());
        return 2;
    }
    return std::nullopt;
}

std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

int runReportingErrors(const char* tool, const std::function<int()>& body)
{
    try {
        return body();
    } catch (const UsageError& e) {
        std::fprintf(stderr, "%s: %s\n", tool, oneLine(e.what()).c_str());
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "%s: out of memory\n", tool);
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", tool, oneLine(e.what()).c_str());
        return 1;
    }
}

std::pair<uint32_t, uint32_t> parseSize(const std::string& flag, const std::string& text)
{
    static const std::regex pattern(R"(^\s*(\d{1,6})\s*[xX]\s*(\d{1,6})\s*$)");
    std::smatch m;
    if (!std::regex_match(text, m, pattern) || std::stoul(m[1]) == 0 || std::stoul(m[2]) == 0)
        throw UsageError(flag + ": expected WIDTHxHEIGHT with positive integers (e.g. 480x360), got '" +
                         text + "'");
    return {uint32_t(std::stoul(m[1])), uint32_t(std::stoul(m[2]))};
}

std::vector<std::string> splitList(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (!item.empty() && std::find(items.begin(), items.end(), item) == items.end())
            items.push_back(item);
    }
    return items;
}

std::string joinNames(const std::vector<std::string>& names)
{
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

void checkOutputPath(const std::string& flag, const std::filesystem::path& path)
{
    if (path.empty())
        return;
    const std::filesystem::path dir = path.parent_path();
    if (!dir.empty() && !std::filesystem::is_directory(dir))
        throw UsageError(flag + ": directory '" + dir.string() + "' does not exist");
    if (std::filesystem::is_directory(path))
        throw UsageError(flag + ": '" + path.string() + "' is a directory, expected a file name");
}

} // namespace lfd::cli
