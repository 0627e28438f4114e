#pragma once
// The script language's words (see script.h): splitting a line into tokens, reading numbers and X,Y,Z
// vectors, and the rule and entity type names scripts may use. Shared by the parser and the runner.
#include "model/validation.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor::script_tokens {

struct Token {
    std::string_view text;
    int column = 0; // 1-based
};

// The words of a line, split at spaces and tabs.
std::vector<Token> tokenize(std::string_view line);
// The line without its comment, if any.
std::string_view strip_comment(std::string_view line);

// Each reads the whole word or fails; a float may carry a leading '+' and must be finite.
bool to_float(std::string_view s, float& out);
bool to_int(std::string_view s, int& out);
// Seconds and values of animation files are doubles (the file keeps them exactly).
bool to_double(std::string_view s, double& out);
// "X,Y,Z" with no spaces.
bool to_vec3(std::string_view s, Vec3& out);

// An error at word `token` of `line` (its column), or just past the line's end when there is no such word.
Error error_at(const std::vector<Token>& tokens, std::string_view line, size_t token, const std::string& file,
               int line_no, std::string message, std::string hint);

// The words of one line as the command parsers read them (script_command.h): each word and its column,
// errors at a word, a word count check against the usage, a word and the rest of the line from a word on.
class LineWords {
  public:
    LineWords(std::string_view line, const std::vector<Token>& tokens, int line_no, const std::string& file)
        : line_(line), tokens_(tokens), line_no_(line_no), file_(file) {}

    size_t size() const { return tokens_.size(); }
    std::string_view text(size_t token) const { return tokens_[token].text; }
    std::string word(size_t token) const { return std::string(tokens_[token].text); }
    // The line from word `token` on, spaces kept (names and values with spaces).
    std::string rest(size_t token) const {
        return std::string(line_.substr(static_cast<size_t>(tokens_[token].column - 1)));
    }
    Error fail(size_t token, std::string message, std::string hint) const {
        return error_at(tokens_, line_, token, file_, line_no_, std::move(message), std::move(hint));
    }
    // Between `min` and `max` words, or an error at the first missing or extra word.
    Result<void> need(size_t min, size_t max, const std::string& usage) const {
        if (tokens_.size() < min) return fail(tokens_.size(), "missing words", usage);
        if (tokens_.size() > max)
            return fail(max, "unexpected '" + std::string(tokens_[max].text) + "'", usage);
        return ok();
    }
    // Word `token` as X,Y,Z.
    Result<void> vec(size_t token, Vec3& out) const {
        if (!to_vec3(tokens_[token].text, out))
            return fail(token, "expected three numbers separated by commas, got '" + word(token) + "'",
                        "write it without spaces, like 10,0,-5");
        return ok();
    }

  protected:
    std::string_view line_;
    const std::vector<Token>& tokens_;
    int line_no_;
    const std::string& file_;
};

// Word `token` as an entity type, or an error listing the types.
Result<void> entity_type(const LineWords& words, size_t token, level::EntityType& out);
// Word `token` as a design rule, or an error listing the rules.
Result<void> rule(const LineWords& words, size_t token, Rule& out);

std::optional<Rule> rule_from_name(std::string_view name);
// "format, player_start, ...": every rule name, for hints.
std::string rule_names();
// Every entity type name, comma-separated, for hints.
std::string type_names();

} // namespace ks::editor::script_tokens
