// Read-back of LFDPR's counter buffers through the generated structs (named fields, never
// array positions): LfdprCountersGpu (the paper's pipeline, LfdprCounters block) and
// LfdprVisCountersGpu (the visibility pipeline). Both stall until the GPU has written them.
#pragma once

#include "lfdpr_bindings_gpu.h"

namespace lfd::player {

using lfdpr_bindings::LfdprCountersGpu;
using lfdpr_bindings::LfdprVisCountersGpu;

LfdprCountersGpu readLfdprCounters(unsigned buffer);
LfdprVisCountersGpu readLfdprVisCounters(unsigned buffer);

} // namespace lfd::player
