// Compiled by tooling/module_boundaries and expected to FAIL: physics does not declare level, so the build
// must not let physics code include a level header.
#include "level/level.h"

int ks_boundary_probe_undeclared() {
    return ks::level::kFormatVersion;
}
