// Compiled by tooling/module_boundaries and expected to FAIL: the runtime model runs without a window, so
// the build must not let its code include the shell (nor render, nor runtime/app).
#include "shell/app_shell.h"

int ks_boundary_probe_runtime_model_undeclared() {
    return 0;
}
