#pragma once
// The script language's level-logic lines (script.h, LogicOp): naming entities for links, links of an
// entity, an objective or the level, objectives, and their expectations, parsed by script_logic_parser.cpp
// and run on the Editor's logic edits (logic_edit.h) by script_logic_runner.cpp. The level parser hands a
// line to it when its first word is a logic word, or `expect` is followed by one.
#include "model/script.h"
#include "model/script_tokens.h"

#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// name, link, objective.
bool is_logic_command(std::string_view word);
// What may follow `expect` in the logic context: links, link, objectives.
bool is_logic_expectation(std::string_view word);

// Parses a logic line (tokens[0] is a logic command, or `expect` and a logic expectation) into a
// ScriptOp::Logic step; errors carry the line and the column of the offending word, and a did-you-mean for
// event and action names.
Result<ScriptStep> parse_logic_line(std::string_view line, const std::vector<script_tokens::Token>& tokens,
                                    int line_no, const std::string& file);

// Runs one logic step on `editor`; a checked expectation is counted in `report`.
Result<void> run_logic_step(const LogicStep& step, Editor& editor, ScriptReport& report);

} // namespace ks::editor
