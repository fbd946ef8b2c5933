// The lobe tap table compiled in, and its GL_LINEAR read; see lobe_taps.h.
#include "lobe_taps.h"

#include "brdf_table.h"

#include <algorithm>
#include <cmath>

namespace lfd::lighting {

namespace {
#include "lobe_taps_data.inc"
} // namespace

const LobeTapTable& lobeTapTable()
{
    static const LobeTapTable table{kLobeTapTableSize, std::vector<float>(std::begin(kLobeTapTableData),
                                                                          std::end(kLobeTapTableData))};
    return table;
}

glm::vec4 sampleLobeTapTable(const LobeTapTable& table, float nDotV, float roughness)
{
    // GL_LINEAR at brdfTableCoordinate: texel centres at (i + 0.5) / size, clamped to edge.
    const glm::vec2 texel = brdfTableCoordinate(nDotV, roughness, table.size) * float(table.size) - 0.5f;
    const int last = int(table.size) - 1;
    const float x0f = std::floor(texel.x), y0f = std::floor(texel.y);
    const float fx = texel.x - x0f, fy = texel.y - y0f;
    const auto at = [&](float x, float y) {
        return table.texel(uint32_t(std::clamp(int(x), 0, last)), uint32_t(std::clamp(int(y), 0, last)));
    };
    return glm::mix(glm::mix(at(x0f, y0f), at(x0f + 1.0f, y0f), fx),
                    glm::mix(at(x0f, y0f + 1.0f), at(x0f + 1.0f, y0f + 1.0f), fx), fy);
}

} // namespace lfd::lighting
