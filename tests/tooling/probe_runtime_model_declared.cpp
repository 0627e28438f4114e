// Compiled by tooling/module_boundaries: the runtime model sees its own headers and the game's.
#include "game/game.h"
#include "runtime/model/screen_table.h"

bool ks_boundary_probe_runtime_model_declared() {
    return ks::runtime::parse_screen_request("pause").has_value();
}
