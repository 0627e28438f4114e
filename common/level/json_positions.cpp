#include "level/json_positions.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace ks::level {

std::string member_path(const std::string& parent, std::string_view key) {
    std::string out = parent;
    if (!out.empty()) out += '.';
    out += key;
    return out;
}

std::string element_path(const std::string& parent, size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

TextPosition position_of_offset(std::string_view text, size_t offset) {
    if (offset > text.size()) offset = text.size();
    TextPosition pos{1, 1};
    for (size_t i = 0; i < offset; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if ((c & 0xC0) != 0x80) { // count code points, not UTF-8 continuation bytes
            ++pos.column;
        }
    }
    return pos;
}

// A recursive-descent walk over valid JSON that tracks line and column as it goes (one pass, no
// backtracking).
class PositionScanner {
  public:
    PositionScanner(std::string_view text, PositionMap& map) : text_(text), map_(map) {}

    void run() {
        skip_space();
        map_.positions_[""] = here();
        value("", 0);
    }

  private:
    static constexpr int kMaxDepth = 512; // nlohmann accepted the text; this only guards our own stack

    std::string_view text_;
    PositionMap& map_;
    size_t at_ = 0;
    TextPosition pos_{1, 1};

    TextPosition here() const { return pos_; }
    bool done() const { return at_ >= text_.size(); }
    char peek() const { return done() ? '\0' : text_[at_]; }

    void advance() {
        const auto c = static_cast<unsigned char>(text_[at_++]);
        if (c == '\n') {
            ++pos_.line;
            pos_.column = 1;
        } else if ((c & 0xC0) != 0x80) {
            ++pos_.column;
        }
    }

    void skip_space() {
        while (!done() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) advance();
    }

    std::string string_token() {
        std::string out;
        advance(); // opening quote
        while (!done() && peek() != '"') {
            if (peek() == '\\') {
                advance();
                if (done()) break;
                const char escaped = peek();
                switch (escaped) {
                case 'n':
                    out += '\n';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'u':
                    out += "\\u";
                    break; // kept raw: keys with \u escapes are not ours anyway
                default:
                    out += escaped;
                    break;
                }
                advance();
            } else {
                out += peek();
                advance();
            }
        }
        if (!done()) advance(); // closing quote
        return out;
    }

    void value(const std::string& path, int depth) {
        if (depth > kMaxDepth) return;
        const char c = peek();
        if (c == '{') {
            object(path, depth);
        } else if (c == '[') {
            array(path, depth);
        } else if (c == '"') {
            string_token();
        } else {
            const size_t start = at_;
            const TextPosition start_pos = here();
            while (!done() && peek() != ',' && peek() != '}' && peek() != ']' && peek() != ' ' &&
                   peek() != '\n' && peek() != '\t' && peek() != '\r')
                advance();
            note_overflow(path, start_pos, start, at_ - start);
        }
    }

    void note_overflow(const std::string& path, TextPosition pos, size_t start, size_t length) {
        if (length == 0 || length > 400) return;
        const std::string token(text_.substr(start, length));
        if (!(std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '-')) return;
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end == token.c_str() + token.size() && std::isinf(value))
            map_.overflows_.push_back({path, pos, start, length, token});
    }

    void object(const std::string& path, int depth) {
        advance(); // {
        skip_space();
        while (!done() && peek() != '}') {
            const TextPosition key_pos = here();
            const std::string key = string_token();
            const std::string child = member_path(path, key);
            auto [it, inserted] = map_.positions_.emplace(child, key_pos);
            if (!inserted) map_.duplicates_.push_back({child, it->second, key_pos});
            skip_space();
            if (peek() == ':') advance();
            skip_space();
            value(child, depth + 1);
            skip_space();
            if (peek() == ',') advance();
            skip_space();
            if (!done() && peek() != '"' && peek() != '}') advance(); // broken text: always make progress
        }
        if (!done()) advance(); // }
    }

    void array(const std::string& path, int depth) {
        advance(); // [
        skip_space();
        size_t index = 0;
        while (!done() && peek() != ']') {
            const std::string child = element_path(path, index++);
            map_.positions_.emplace(child, here());
            const size_t before = at_;
            value(child, depth + 1);
            skip_space();
            if (peek() == ',') advance();
            skip_space();
            if (at_ == before) advance(); // broken text: always make progress
        }
        if (!done()) advance(); // ]
    }
};

PositionMap PositionMap::scan(std::string_view text) {
    PositionMap map;
    PositionScanner(text, map).run();
    return map;
}

TextPosition PositionMap::find(const std::string& path) const {
    std::string probe = path;
    while (true) {
        if (auto it = positions_.find(probe); it != positions_.end()) return it->second;
        if (probe.empty()) return {};
        // Strip the last component: "a.b[2]" -> "a.b" -> "a" -> "".
        const size_t cut = probe.find_last_of(".[");
        probe = cut == std::string::npos ? std::string() : probe.substr(0, cut);
    }
}

} // namespace ks::level
