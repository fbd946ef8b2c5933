// LFDPR's counter blocks through the generated structs (named fields, never array
// positions): LfdprCountersGpu (the paper's pipeline, LfdprCounters block) and
// LfdprVisCountersGpu (the visibility pipeline). The renderers read them back frames later
// through gl::GpuReadback, never waiting for them.
#pragma once

#include "lfdpr_bindings_gpu.h"

namespace lfd::player {

using lfdpr_bindings::LfdprCountersGpu;
using lfdpr_bindings::LfdprVisCountersGpu;

} // namespace lfd::player
