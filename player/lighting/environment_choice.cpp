#include "environment_choice.h"

#include "environment_file.h"
#include "neutral_environment.h"

#include <xxhash.h>

#include <cstdio>

namespace lfd::lighting {

EnvironmentChoice chooseEnvironment(const std::string& choice)
{
    EnvironmentChoice out;
    if (choice == "none")
        return out;
    if (choice == "neutral") {
        out.environment = std::make_shared<const Environment>(neutralEnvironment());
        out.key = "neutral";
        return out;
    }
    const Environment& e = *(out.environment = std::make_shared<const Environment>(loadEnvironment(choice)));
    const XXH64_hash_t hash = XXH3_64bits(e.rgb.data(), e.rgb.size() * sizeof(float));
    char text[64];
    std::snprintf(text, sizeof(text), "file:%016llx:%ux%u", static_cast<unsigned long long>(hash), e.width, e.height);
    out.key = text;
    return out;
}

} // namespace lfd::lighting
