// Compiled by tooling/module_boundaries and expected to FAIL: level/level_migrate.h is internal to level
// (ks_module(level ... INTERNAL ...)), so game code must not see it although game declares level.
#include "level/level_migrate.h"

int ks_boundary_probe_internal() {
    return static_cast<int>(sizeof(ks::level::Migration));
}
