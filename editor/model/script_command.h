#pragma once
// The script language's command registry: every command is one CommandSpec (its word, usage, a line of
// summary and the function that parses a line into a typed step), kept in one table per concern (level
// edits and expectations, groups/layers/prefabs, level logic, clip files). The line parser finds a line's
// entry here; the unknown-command hint, `killswitch-editor --help-script` and the test that checks
// docs/editor.md's command tables all read the same tables.
//
// Adding a command: its step struct (with `run`) joins its concern's variant in script_<concern>.h, and its
// parse function, `run` and table entry go in that concern's .cpp (script_level_edits.cpp,
// script_level_settings.cpp, script_level_expect.cpp, script_brush_parser.cpp, script_tool_parser.cpp,
// script_structure_*.cpp, script_logic_*.cpp, script_dojo_*.cpp).
#include "model/dojo_document.h"
#include "model/script.h"
#include "model/script_tokens.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace ks::editor {

// What a step runs on: the editor, the dojo's clip file, the script's folder (relative paths resolve
// against it) and the report that counts expectations and saved files.
struct ScriptContext {
    Editor& editor;
    DojoDocument& dojo;
    const std::filesystem::path& base_dir;
    const std::string& file_name;
    ScriptReport& report;
    int line = 0; // of the step running, for log lines

    std::filesystem::path resolve(const std::string& path) const;
    // Counts the expectation; an error "expectation failed: MESSAGE" unless `condition` holds.
    Result<void> expect(bool condition, const std::string& message);
};

struct CommandSpec {
    std::string_view word; // the line's first word, or for an expectation the word after `expect`
    bool expectation;      // `expect WORD ...`
    const char* usage;     // every form, " | " between them; the hint when the words do not fit
    const char* summary;   // what it does, for --help-script
    Result<ScriptStep> (*parse)(const script_tokens::LineWords& words);
};

// A parsed step of concern `Concern` (LevelStep, StructureStep, LogicStep, DojoStep); the line number is
// filled in by the line parser.
template <class Concern, class Step>
Result<ScriptStep> step_of(Step step) {
    return ScriptStep{0, Concern{std::move(step)}};
}

// One concern's commands; `label` heads them in hints and listings.
struct CommandTable {
    const char* label;
    std::span<const CommandSpec> commands;
};

// The concerns' tables (defined beside their parsers).
std::span<const CommandSpec> level_edit_commands();
std::span<const CommandSpec> level_setting_commands();
std::span<const CommandSpec> level_expect_commands();
std::span<const CommandSpec> brush_commands();
std::span<const CommandSpec> tool_commands();
std::span<const CommandSpec> structure_commands();
std::span<const CommandSpec> logic_commands();
std::span<const CommandSpec> dojo_commands();

// Every table, in the order hints and listings show them.
std::span<const CommandTable> script_command_tables();
// The entry for a command word (expectation: the word after `expect`), or null.
const CommandSpec* find_script_command(std::string_view word, bool expectation);
// Every command word, by concern: the hint of an unknown command.
std::string script_command_words();
// Every expectation word: the hint of an unknown expectation.
std::string script_expectation_words();
// Every command's usage and summary, one form a line, by concern: `killswitch-editor --help-script`.
std::string script_usage_listing();

} // namespace ks::editor
