// What every bake stage reports through: BakeError, the one error of bad input (a one-line
// message naming the file), and Log, the progress / warning sink the caller supplies.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace lfd::bake {

class BakeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Progress / warning sink. Stages report what they do; the driver decides whether to
// print (--quiet keeps warnings and errors only).
struct Log {
    std::function<void(const std::string&)> info = [](const std::string&) {};
    std::function<void(const std::string&)> warn = [](const std::string&) {};
};

} // namespace lfd::bake
