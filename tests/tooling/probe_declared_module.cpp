// Compiled by tooling/module_boundaries: physics declares core, so physics code may include it.
#include "core/math.h"
#include "physics/shapes.h"

float ks_boundary_probe_declared() {
    return ks::radians(90.0f);
}
