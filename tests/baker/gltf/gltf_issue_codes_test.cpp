// The catalogue of glTF issue codes (baker/gltf/gltf_issue_codes.h): codes are unique
// UPPER_SNAKE names, each with a one-line meaning, in the generated table once; and the
// severity rule (an Error code in a value the baker goes on without is a Warning).
#include "gltf_validation.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using lfd::bake::gltf::IssueCode;
using lfd::bake::gltf::IssueCodeInfo;
using lfd::bake::gltf::IssueSeverity;
using lfd::bake::gltf::issueCodeInfo;
using lfd::bake::gltf::issueCodes;

TEST(GltfIssueCodes, CodesAreUniqueUpperSnakeNamesWithAMeaning)
{
    std::set<std::string> names;
    size_t index = 0;
    for (const IssueCodeInfo& info : issueCodes()) {
        const std::string name = info.name;
        SCOPED_TRACE(name);
        EXPECT_TRUE(names.insert(name).second) << "listed twice";
        EXPECT_EQ(size_t(info.code), index++);
        EXPECT_EQ(&issueCodeInfo(info.code), &info);
        ASSERT_FALSE(name.empty());
        for (char c : name)
            EXPECT_TRUE((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_') << c;
        const std::string meaning = info.description;
        EXPECT_GT(meaning.size(), 10u);
        EXPECT_EQ(meaning.find('\n'), std::string::npos);
        EXPECT_EQ(meaning.find('|'), std::string::npos); // a Markdown table cell
        EXPECT_EQ(meaning.back(), '.');
    }
    EXPECT_GT(names.size(), 50u);
}

TEST(GltfIssueCodes, TheTableHasOneRowPerCode)
{
    const std::string table = lfd::bake::gltf::issueCodeTable();
    for (const IssueCodeInfo& info : issueCodes()) {
        const std::string row = std::string("| `") + info.name + "` | " +
                                (info.severity == IssueSeverity::Error ? "Error" : "Warning") + " | " +
                                info.description + " |\n";
        EXPECT_NE(table.find(row), std::string::npos) << row;
    }
    size_t rows = 0;
    for (char c : table)
        rows += c == '\n';
    EXPECT_EQ(rows, issueCodes().size() + 2); // header and separator
}

TEST(GltfIssueCodes, AnErrorInAValueTheBakerIgnoresIsAWarning)
{
    using lfd::bake::gltf::makeIssue;
    const auto read = makeIssue(IssueCode::VALUE_NOT_IN_LIST, "samplers[0].magFilter", "m");
    EXPECT_EQ(read.severity, IssueSeverity::Error);
    EXPECT_EQ(read.text(), "samplers[0].magFilter: m");
    const auto ignored = makeIssue(IssueCode::VALUE_NOT_IN_LIST, "samplers[0].magFilter", "m", lfd::bake::gltf::kIgnored);
    EXPECT_EQ(ignored.severity, IssueSeverity::Warning);
    EXPECT_EQ(ignored.code, IssueCode::VALUE_NOT_IN_LIST);
    // A Warning code stays a warning wherever it is found.
    EXPECT_EQ(makeIssue(IssueCode::VALUE_CLAMPED, "p", "m").severity, IssueSeverity::Warning);
}

} // namespace
