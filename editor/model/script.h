#pragma once
// Scripted mode: a line-based language that drives the same Editor operations the UI dispatches, for tests
// and automation (`killswitch-editor --script FILE`). The whole script is parsed first, so a typo on line 40
// is reported before line 1 changes anything; errors read "file:line:column: message (hint)".
// The language is documented in docs/editor.md.
#include "core/result.h"
#include "model/editor.h"
#include "model/script_brush.h"
#include "model/script_dojo.h"
#include "model/script_level.h"
#include "model/script_logic.h"
#include "model/script_structure.h"
#include "model/script_tool.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ks::editor {

// One parsed line: its number and its typed step, one of each concern's steps (script_level.h,
// script_brush.h, script_tool.h, script_structure.h, script_logic.h, script_dojo.h). The commands that make
// them are in the registry (script_command.h).
struct ScriptStep {
    int line = 0;
    std::variant<LevelStep, BrushStep, ToolStep, StructureStep, LogicStep, DojoStep> action;
};

struct Script {
    std::string file_name;
    std::filesystem::path base_dir; // relative paths in the script resolve against it
    std::vector<ScriptStep> steps;
};

struct ScriptReport {
    int lines_run = 0;
    int expectations_checked = 0;
    std::vector<std::filesystem::path> saved; // every file written by `save` and `dojo save`, in order
};

// Parses every line; all syntax errors at once, one per line of the combined Error.
Result<Script> parse_script(std::string_view text, const std::string& file_name);
// Runs a parsed script on `editor`; stops at the first failing line.
Result<ScriptReport> run_parsed_script(const Script& script, Editor& editor);
// Reads, parses and runs a script file on a fresh editor (paths relative to the script's folder).
Result<ScriptReport> run_script(const std::filesystem::path& path);
// The same on an existing editor, for tests and a script console.
Result<ScriptReport> run_script_text(std::string_view text, const std::string& file_name,
                                     const std::filesystem::path& base_dir, Editor& editor);

} // namespace ks::editor
