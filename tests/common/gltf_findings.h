// What the glTF checks find in a file, by issue code (baker/gltf/gltf_issue_codes.h): the
// tests assert the code, JSON path and severity of a finding, not its wording. Shared by the
// glTF validation, conformance, import and compression tests.
#pragma once

#include "bake_log.h"
#include "gltf_load.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace lfd::test {

using lfd::bake::gltf::IssueCode;
using lfd::bake::gltf::IssueSeverity;
using lfd::bake::gltf::SchemaIssue;

// Every finding of loading `path` (gltf::loadGltf), errors included when it is refused.
inline std::vector<SchemaIssue> gltfFindings(const std::filesystem::path& path)
{
    std::vector<SchemaIssue> issues;
    try {
        lfd::bake::gltf::loadGltf(path, path.string(), issues, 1);
    } catch (const lfd::bake::BakeError&) {
    }
    return issues;
}

inline std::string codeName(IssueCode code) { return lfd::bake::gltf::issueCodeInfo(code).name; }

// "CODE at path (Error): message" lines, for failure messages.
inline std::string listFindings(const std::vector<SchemaIssue>& issues)
{
    std::string out;
    for (const SchemaIssue& i : issues)
        out += "\n  " + codeName(i.code) + " at " + i.path +
               (i.severity == IssueSeverity::Error ? " (Error): " : " (Warning): ") + i.message;
    return out.empty() ? "\n  (none)" : out;
}

// The first error among `issues` (the one a refusal names), or nullptr.
inline const SchemaIssue* firstError(const std::vector<SchemaIssue>& issues)
{
    for (const SchemaIssue& i : issues)
        if (i.severity == IssueSeverity::Error)
            return &i;
    return nullptr;
}

// Loading `file` is refused, and the first error is `code` at `jsonPath`.
inline void expectRefusedWith(const std::filesystem::path& file, IssueCode code, const std::string& jsonPath)
{
    const std::vector<SchemaIssue> issues = gltfFindings(file);
    const SchemaIssue* first = firstError(issues);
    if (first == nullptr) {
        ADD_FAILURE() << "accepted, expected " << codeName(code) << " at " << jsonPath << listFindings(issues);
        return;
    }
    EXPECT_EQ(codeName(first->code), codeName(code)) << listFindings(issues);
    EXPECT_EQ(first->path, jsonPath) << listFindings(issues);
}

// Loading `file` finds a warning `code` at `jsonPath`.
inline void expectWarningWith(const std::filesystem::path& file, IssueCode code, const std::string& jsonPath)
{
    const std::vector<SchemaIssue> issues = gltfFindings(file);
    bool found = false;
    for (const SchemaIssue& i : issues)
        found = found || (i.code == code && i.path == jsonPath && i.severity == IssueSeverity::Warning);
    EXPECT_TRUE(found) << "expected warning " << codeName(code) << " at " << jsonPath << listFindings(issues);
}

} // namespace lfd::test
