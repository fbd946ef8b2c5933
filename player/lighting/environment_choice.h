// `--environment neutral|none|FILE.hdr`: the environment a tool asked for, read once on the
// CPU when the flags are parsed (so a bad file is a usage error naming the flag, before any
// GL work), with the key that names it in caches (gstd's views depend on it).
#pragma once

#include "environment.h"

#include <memory>
#include <string>

namespace lfd::lighting {

struct EnvironmentChoice {
    std::shared_ptr<const Environment> environment; // null: "none"
    // "none", "neutral", or "file:<XXH3-64 of the radiance>:<width>x<height>" (the content,
    // not the path: a cache survives a rename and sees an edit).
    std::string key = "none";
};

// "none", "neutral" (neutralEnvironment) or a Radiance .hdr path (loadEnvironment: throws
// EnvironmentError naming the file).
EnvironmentChoice chooseEnvironment(const std::string& choice);

} // namespace lfd::lighting
