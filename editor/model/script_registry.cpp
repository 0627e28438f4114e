// The script language's command registry (script_command.h): the concerns' tables gathered, looked up, and
// listed for hints and --help-script.
#include "model/script_command.h"

namespace ks::editor {

std::span<const CommandTable> script_command_tables() {
    static const CommandTable kTables[] = {
        {"commands", level_edit_commands()},       {"commands", level_setting_commands()},
        {"expectations", level_expect_commands()}, {"brushes", brush_commands()},
        {"geometry tools", tool_commands()},       {"groups, layers, prefabs", structure_commands()},
        {"level logic", logic_commands()},         {"clip files", dojo_commands()},
    };
    return kTables;
}

const CommandSpec* find_script_command(std::string_view word, bool expectation) {
    for (const CommandTable& table : script_command_tables())
        for (const CommandSpec& command : table.commands)
            if (command.expectation == expectation && command.word == word) return &command;
    return nullptr;
}

namespace {

// "label: word word; label: word ...", each label once, in table order; `expectation` picks which words.
std::string words_by_label(bool expectation) {
    std::vector<std::pair<std::string, std::string>> groups;
    for (const CommandTable& table : script_command_tables()) {
        for (const CommandSpec& command : table.commands) {
            if (command.expectation != expectation) continue;
            if (groups.empty() || groups.back().first != table.label) groups.push_back({table.label, ""});
            std::string& words = groups.back().second;
            words += (words.empty() ? "" : " ") + std::string(command.word);
        }
    }
    std::string out;
    for (const auto& [label, words] : groups) out += (out.empty() ? "" : "; ") + label + ": " + words;
    return out;
}

} // namespace

// The tables never change after start-up: the hints are built once (a script of many bad lines asks for one
// per line).
std::string script_command_words() {
    static const std::string words = words_by_label(false) + "; assertions: expect WORD ...";
    return words;
}

std::string script_expectation_words() {
    static const std::string words = words_by_label(true);
    return words;
}

std::string script_usage_listing() {
    std::string out;
    const char* label = "";
    for (const CommandTable& table : script_command_tables()) {
        if (std::string_view(label) != table.label)
            out += std::string(out.empty() ? "" : "\n") + table.label + ":\n";
        label = table.label;
        for (const CommandSpec& command : table.commands) {
            std::string_view usage = command.usage;
            out += "  ";
            for (size_t bar; (bar = usage.find(" | ")) != std::string_view::npos;
                 usage.remove_prefix(bar + 3))
                out += std::string(usage.substr(0, bar)) + "\n  ";
            out += std::string(usage) + "\n      " + command.summary + "\n";
        }
    }
    return out;
}

} // namespace ks::editor
