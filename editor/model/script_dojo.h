#pragma once
// The script language's dojo context (script.h, DojoOp): the lines that edit an animation clip file, parsed
// by script_dojo_parser.cpp and run on a DojoDocument by script_dojo_runner.cpp. The level parser hands a
// line to it when its first word is a dojo word, or `expect` is followed by one.
#include "model/dojo_document.h"
#include "model/script.h"
#include "model/script_tokens.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// dojo, clip, blend, event, key.
bool is_dojo_command(std::string_view word);
// What may follow `expect` in the dojo context: clip, blend, events, event, key, curve, dojo.
bool is_dojo_expectation(std::string_view word);
// "dojo open [FILE] | ... ": every dojo command's usage, for the level parser's hints.
const char* dojo_commands_usage();

// Parses a dojo line (tokens[0] is a dojo command, or `expect` and a dojo expectation) into a ScriptOp::Dojo
// step; errors carry the line and the column of the offending word.
Result<ScriptStep> parse_dojo_line(std::string_view line, const std::vector<script_tokens::Token>& tokens,
                                   int line_no, const std::string& file);

// Runs one dojo step on `dojo` (relative paths against `base_dir`); a saved file and a checked expectation
// are counted in `report`.
Result<void> run_dojo_step(const DojoStep& step, DojoDocument& dojo, const std::filesystem::path& base_dir,
                           ScriptReport& report);

} // namespace ks::editor
