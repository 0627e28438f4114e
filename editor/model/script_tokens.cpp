#include "model/script_tokens.h"

#include "level/level.h"

#include <charconv>
#include <cmath>

namespace ks::editor::script_tokens {
namespace {

constexpr Rule kRules[] = {Rule::Format,    Rule::PlayerStart,  Rule::ControlPanel, Rule::WallOverlap,
                           Rule::Support,   Rule::StairSlope,   Rule::DoorGap,      Rule::Reachability,
                           Rule::Patrol,    Rule::RobotReach,   Rule::Sound,        Rule::LinkTarget,
                           Rule::LogicLoop, Rule::TriggerReach, Rule::Objective,    Rule::LockedDoor,
                           Rule::Texture,   Rule::Prefab,       Rule::StartAmbush};

} // namespace

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (i >= line.size()) break;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return out;
}

// A comment starts at a '#' that begins the line or stands alone as a word ("# ..."), so colour values
// like #ffcc80 stay values.
std::string_view strip_comment(std::string_view line) {
    for (size_t i = 0; i < line.size(); ++i) {
        if (line[i] != '#') continue;
        const bool starts_line = line.find_first_not_of(" \t") == i;
        const bool own_word = i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t') &&
                              (i + 1 == line.size() || line[i + 1] == ' ' || line[i + 1] == '\t');
        if (starts_line || own_word) return line.substr(0, i);
    }
    return line;
}

bool to_float(std::string_view s, float& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto res = std::from_chars(s.data(), s.data() + s.size(), out);
    return res.ec == std::errc() && res.ptr == s.data() + s.size() && std::isfinite(out);
}

bool to_int(std::string_view s, int& out) {
    auto res = std::from_chars(s.data(), s.data() + s.size(), out);
    return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

bool to_double(std::string_view s, double& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto res = std::from_chars(s.data(), s.data() + s.size(), out);
    return res.ec == std::errc() && res.ptr == s.data() + s.size() && std::isfinite(out);
}

Error error_at(const std::vector<Token>& tokens, std::string_view line, size_t token, const std::string& file,
               int line_no, std::string message, std::string hint) {
    const int column = token < tokens.size() ? tokens[token].column : static_cast<int>(line.size()) + 1;
    return Error(std::move(message), Location{file, line_no, column}, std::move(hint));
}

bool to_vec3(std::string_view s, Vec3& out) {
    for (int i = 0; i < 3; ++i) {
        size_t comma = s.find(',');
        if ((i < 2) != (comma != std::string_view::npos)) return false;
        if (!to_float(s.substr(0, comma), out[i])) return false;
        if (comma != std::string_view::npos) s.remove_prefix(comma + 1);
    }
    return true;
}

std::optional<Rule> rule_from_name(std::string_view name) {
    for (Rule r : kRules)
        if (name == rule_name(r)) return r;
    return std::nullopt;
}

Result<void> entity_type(const LineWords& words, size_t token, level::EntityType& out) {
    if (token >= words.size()) return words.fail(token, "expected an entity type", "types: " + type_names());
    if (!level::type_from_name(words.text(token), out))
        return words.fail(token, "unknown entity type '" + words.word(token) + "'", "types: " + type_names());
    return ok();
}

Result<void> rule(const LineWords& words, size_t token, Rule& out) {
    const auto found = rule_from_name(words.text(token));
    if (!found) return words.fail(token, "unknown rule", "rules: " + rule_names());
    out = *found;
    return ok();
}

std::string rule_names() {
    std::string s;
    for (Rule r : kRules) s += (s.empty() ? "" : ", ") + std::string(rule_name(r));
    return s;
}

std::string type_names() {
    std::string s;
    for (auto t : level::all_types()) s += (s.empty() ? "" : ", ") + std::string(level::type_name(t));
    return s;
}

} // namespace ks::editor::script_tokens
