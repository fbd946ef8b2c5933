// Reading glTF JSON after the schema check (internal to the baker): the check reported
// every malformed value, so the readers that run after it take what is well formed and
// skip the rest, with one rule for integers.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <optional>

namespace lfd::bake::gltf {

// A non-negative integer member of object `o` ("count": 4.0 is one, as JSON Schema
// integers are), or nullopt when `o` is no object, the member is absent, or it is not such
// an integer. Values are bounded before the cast (9e15 < 2^53), so no double overflows it.
inline std::optional<size_t> jsonIndex(const nlohmann::json& o, const char* key)
{
    if (!o.is_object())
        return std::nullopt;
    const auto it = o.find(key);
    if (it == o.end() || !it->is_number())
        return std::nullopt;
    const double d = it->get<double>();
    if (!(d >= 0 && d < 9.0e15) || d != std::floor(d))
        return std::nullopt;
    return size_t(d);
}

} // namespace lfd::bake::gltf
