// Compiled by tooling/module_boundaries and expected to FAIL: level/level_reader.h is internal to level
// (ks_module(level ... INTERNAL ...)), so game code must not see it although game declares level.
#include "level/level_reader.h"

int ks_boundary_probe_internal() {
    return static_cast<int>(sizeof(ks::level::ReadLevel));
}
