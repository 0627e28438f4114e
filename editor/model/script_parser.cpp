// The script language's parser: each line to its command's parser, found in the registry
// (script_command.h) by its first word (or, after `expect`, its second), or an error at the unknown word.
#include "model/script_command.h"

#include "jsonio/suggest.h"

namespace ks::editor {
namespace {
using namespace script_tokens;

// Every registered word of one kind (commands or expectations), in table order; built once.
const std::vector<std::string>& registered_words(bool expectation) {
    static const auto build = [](bool which) {
        std::vector<std::string> words;
        for (const CommandTable& table : script_command_tables())
            for (const CommandSpec& command : table.commands)
                if (command.expectation == which) words.emplace_back(command.word);
        return words;
    };
    static const std::vector<std::string> commands = build(false), expectations = build(true);
    return expectation ? expectations : commands;
}

// "did you mean 'place'? " when a registered word of the kind is close to `word`.
std::string did_you_mean(std::string_view word, bool expectation) {
    const std::string near = jsonio::closest_match(word, registered_words(expectation));
    return near.empty() ? std::string() : "did you mean '" + near + "'? ";
}

Result<ScriptStep> parse_line(const LineWords& words) {
    const bool expectation = words.text(0) == "expect";
    if (expectation && words.size() < 2)
        return words.fail(1, "missing words", "expect WORD ...; " + script_expectation_words());
    const std::string_view word = words.text(expectation ? 1 : 0);
    if (const CommandSpec* command = find_script_command(word, expectation)) return command->parse(words);
    if (expectation)
        return words.fail(1, "unknown expectation '" + std::string(word) + "'",
                          did_you_mean(word, true) + script_expectation_words());
    return words.fail(0, "unknown command '" + std::string(word) + "'",
                      did_you_mean(word, false) + script_command_words());
}

} // namespace

Result<Script> parse_script(std::string_view text, const std::string& file_name) {
    Script script;
    script.file_name = file_name;
    std::vector<Error> errors;
    int line_no = 0;
    while (!text.empty() || line_no == 0) {
        ++line_no;
        size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        line = strip_comment(line);
        const auto tokens = tokenize(line);
        if (tokens.empty()) {
            if (text.empty()) break;
            continue;
        }
        auto step = parse_line(LineWords(line, tokens, line_no, file_name));
        if (step) {
            step->line = line_no;
            script.steps.push_back(std::move(*step));
        } else {
            errors.push_back(step.error());
        }
        if (text.empty()) break;
    }
    if (!errors.empty()) return errors.size() == 1 ? errors.front() : combine_errors(errors);
    return script;
}

} // namespace ks::editor
