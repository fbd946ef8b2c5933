#include "lfdpr_counters.h"

#include <epoxy/gl.h>

namespace lfd::player {

LfdprCountersGpu readLfdprCounters(unsigned buffer)
{
    LfdprCountersGpu counters{};
    glGetNamedBufferSubData(buffer, 0, sizeof(counters), &counters);
    return counters;
}

LfdprVisCountersGpu readLfdprVisCounters(unsigned buffer)
{
    LfdprVisCountersGpu counters{};
    glGetNamedBufferSubData(buffer, 0, sizeof(counters), &counters);
    return counters;
}

} // namespace lfd::player
