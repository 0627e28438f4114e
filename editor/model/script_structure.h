#pragma once
// The script language's structure lines: groups (`group`, `ungroup`, `enter`, `exit`, `pick`), layers
// (`layer ...`) and prefabs (`prefab ...`), and their expectations, parsed by script_structure_parser.cpp
// and run on the Editor by script_structure_runner.cpp. The level parser hands a line to it when its first
// word is one of these, or `expect` is followed by a structure expectation. Documented in docs/editor.md.
#include "model/script.h"
#include "model/script_tokens.h"

#include <string_view>
#include <vector>

namespace ks::editor {

bool is_structure_command(std::string_view word);
bool is_structure_expectation(std::string_view word);

Result<ScriptStep> parse_structure_line(std::string_view line,
                                        const std::vector<script_tokens::Token>& tokens, int line_no,
                                        const std::string& file);

// Runs one structure step; paths (prefab folder) resolve against `base_dir`.
Result<void> run_structure_step(const StructureStep& step, Editor& editor,
                                const std::filesystem::path& base_dir, ScriptReport& report);

} // namespace ks::editor
