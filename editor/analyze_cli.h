#pragma once
// `killswitch-editor --analyze LEVEL [--runs N] [--report FILE] [--seconds S] [--threads T]`: the play-test
// report without a window (game/playtest_analysis.h), for CI and scripts. Prints a short summary and where
// the report went; exit 0 on success, 1 when the level cannot be loaded or analysed, 2 for a bad option.
#include "core/cli.h"

#include <string>
#include <vector>

namespace ks::editor {

// The options --analyze takes besides itself (for the unknown-option check).
const std::vector<std::string>& analyze_option_names();
int run_analyze_mode(const CommandLine& command_line);

} // namespace ks::editor
