#pragma once
// killswitch's render-only views, outside the game: --view MODEL (views/model_viewer.h) and --camera /
// --level (a level from a given eye with the first-person rifle and HUD, flying freely when interactive).
#include "core/cli.h"

#include <string>
#include <vector>

namespace ks::runtime {

// The options the views understand beyond the shell's (for the unknown-option check).
const std::vector<std::string>& render_view_options();
void print_render_view_help();
// Runs the view the command line asks for; returns the process exit code (2: bad options or level,
// 3: no display, 1: no window or renderer).
int run_render_view(const CommandLine& cl);

} // namespace ks::runtime
