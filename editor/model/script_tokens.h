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

std::optional<Rule> rule_from_name(std::string_view name);
// "format, player_start, ...": every rule name, for hints.
std::string rule_names();
// Every entity type name, comma-separated, for hints.
std::string type_names();

} // namespace ks::editor::script_tokens
