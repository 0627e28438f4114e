#pragma once
// The playable game: loading screen, menus, the game itself (headless rules from common/game drawn by the
// renderer), the Dojo, and the screenshot hooks the tests use. One entry point for runtime/main.cpp.
#include "core/cli.h"
#include "shell/app_shell.h"

#include <string>
#include <vector>

namespace ks::runtime {

// Options this app reads (besides the shell's --width/--height/--screenshot/--frames/--no-vsync):
//   --level FILE, --dojo, --screen NAME, --warp x,y,z,yaw,pitch, --dojo-key K, --dojo-time S, --seed N,
//   --msaa N
const std::vector<std::string>& game_app_options();
const std::vector<std::string>& game_app_flags(); // options without a value (--dojo)

// Runs the app; returns the process exit code (0 ok, 1 runtime failure, 2 bad input, 3 no display).
int run_game_app(const CommandLine& cl, const shell::ShellConfig& shell_config);

} // namespace ks::runtime
