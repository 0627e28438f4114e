// Compiled by tooling/module_boundaries: game declares level, and level/level_io.h is one of level's public
// headers (level lists internal ones, so its headers reach game one link each).
#include "level/level_io.h"

bool ks_boundary_probe_public() {
    return ks::level::load_level_string("{", "probe.json").ok();
}
