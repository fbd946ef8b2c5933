// The issue-code catalogue (gltf_issue_codes.h) as data and as a Markdown table.
#include "gltf_issue_codes.h"

#include <array>

namespace lfd::bake::gltf {
namespace {

constexpr std::array kCodes = {
#define LFD_GLTF_ISSUE_INFO(code, severity, meaning) \
    IssueCodeInfo{IssueCode::code, #code, IssueSeverity::severity, meaning},
    LFD_GLTF_ISSUE_CODES(LFD_GLTF_ISSUE_INFO)
#undef LFD_GLTF_ISSUE_INFO
};

} // namespace

std::span<const IssueCodeInfo> issueCodes() { return kCodes; }

const IssueCodeInfo& issueCodeInfo(IssueCode code) { return kCodes[size_t(code)]; }

std::string issueCodeTable()
{
    std::string out = "| code | severity | meaning |\n|---|---|---|\n";
    for (const IssueCodeInfo& info : kCodes)
        out += std::string("| `") + info.name + "` | " +
               (info.severity == IssueSeverity::Error ? "Error" : "Warning") + " | " + info.description + " |\n";
    return out;
}

} // namespace lfd::bake::gltf
