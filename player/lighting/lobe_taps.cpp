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
    return sampleSquareTableLinear(table, nDotV, roughness);
}

} // namespace lfd::lighting
