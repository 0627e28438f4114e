#include "anim/json_path.h"

#include <cctype>

namespace ks::anim {

JsonPath JsonPath::operator/(std::string_view key) const {
    JsonPath p = *this;
    p.steps_.push_back({std::string(key), -1});
    return p;
}

JsonPath JsonPath::operator[](std::size_t index) const {
    JsonPath p = *this;
    p.steps_.push_back({{}, static_cast<long>(index)});
    return p;
}

std::string JsonPath::str() const {
    std::string out;
    for (const JsonPathStep& s : steps_) {
        if (s.index >= 0) {
            out += "[" + std::to_string(s.index) + "]";
        } else {
            if (!out.empty()) out += ".";
            out += s.key;
        }
    }
    return out;
}

TextPosition line_column(std::string_view text, std::size_t byte_offset) {
    TextPosition pos{1, 1};
    for (std::size_t i = 0; i < byte_offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) { // count UTF-8 characters
            ++pos.column;
        }
    }
    return pos;
}

namespace {

// A forward-only scanner over text already known to be valid JSON.
struct Scanner {
    std::string_view s;
    std::size_t i = 0;

    void skip_ws() {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    std::string read_string() { // at the opening quote; returns the decoded-enough key (escapes kept simple)
        std::string out;
        ++i;
        while (i < s.size() && s[i] != '"') {
            if (s[i] == '\\' && i + 1 < s.size()) {
                ++i;
                out += s[i] == 'n' ? '\n' : s[i] == 't' ? '\t' : s[i];
            } else {
                out += s[i];
            }
            ++i;
        }
        ++i;
        return out;
    }
    void skip_value() {
        skip_ws();
        if (i >= s.size()) return;
        char c = s[i];
        if (c == '"') {
            read_string();
        } else if (c == '{' || c == '[') {
            char close = c == '{' ? '}' : ']';
            ++i;
            skip_ws();
            if (i < s.size() && s[i] == close) {
                ++i;
                return;
            }
            while (i < s.size()) {
                skip_ws();
                if (c == '{') {
                    read_string();
                    skip_ws();
                    ++i; // ':'
                }
                skip_value();
                skip_ws();
                if (i < s.size() && s[i] == ',') {
                    ++i;
                    continue;
                }
                ++i; // close
                return;
            }
        } else {
            while (i < s.size() && s[i] != ',' && s[i] != '}' && s[i] != ']' &&
                   !std::isspace(static_cast<unsigned char>(s[i])))
                ++i;
        }
    }
    // Positions the scanner at the start of the child value; false if absent.
    bool enter(const JsonPathStep& step) {
        skip_ws();
        if (i >= s.size()) return false;
        if (step.index >= 0) {
            if (s[i] != '[') return false;
            ++i;
            for (long n = 0;; ++n) {
                skip_ws();
                if (i >= s.size() || s[i] == ']') return false;
                if (n == step.index) return true;
                skip_value();
                skip_ws();
                if (i < s.size() && s[i] == ',')
                    ++i;
                else
                    return false;
            }
        }
        if (s[i] != '{') return false;
        ++i;
        // Duplicate keys: nlohmann keeps the last one, so the last match wins here too.
        std::size_t found = std::string::npos;
        for (;;) {
            skip_ws();
            if (i >= s.size() || s[i] != '"') break;
            std::string key = read_string();
            skip_ws();
            ++i; // ':'
            skip_ws();
            if (key == step.key) found = i;
            skip_value();
            skip_ws();
            if (i < s.size() && s[i] == ',')
                ++i;
            else
                break;
        }
        if (found == std::string::npos) return false;
        i = found;
        return true;
    }
};

} // namespace

TextPosition locate(std::string_view text, const JsonPath& path) {
    Scanner sc{text};
    for (const JsonPathStep& step : path.steps())
        if (!sc.enter(step)) return {};
    sc.skip_ws();
    return line_column(text, sc.i);
}

} // namespace ks::anim
