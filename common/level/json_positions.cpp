#include "level/json_positions.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
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

// A recursive-descent walk over the text that tracks line and column as it goes (one pass, no
// backtracking). The current path lives in one buffer that grows and shrinks as the walk goes in and out.
class PositionScanner {
  public:
    PositionScanner(std::string_view text, PositionMap& map) : text_(text), map_(map) {}

    void run() {
        skip_space();
        record(here());
        value(0);
    }

  private:
    static constexpr int kMaxDepth = 512; // nlohmann refuses deeper text anyway; this guards our own stack

    std::string_view text_;
    PositionMap& map_;
    size_t at_ = 0;
    TextPosition pos_{1, 1};
    std::string path_;

    TextPosition here() const { return pos_; }
    bool done() const { return at_ >= text_.size(); }
    char peek() const { return done() ? '\0' : text_[at_]; }

    void record(TextPosition pos) {
        map_.entries_.push_back(
            {static_cast<std::uint32_t>(map_.arena_.size()), static_cast<std::uint32_t>(path_.size()), pos});
        map_.arena_ += path_;
    }

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

    void value(int depth) {
        if (depth > kMaxDepth) return;
        const char c = peek();
        if (c == '{') {
            object(depth);
        } else if (c == '[') {
            array(depth);
        } else if (c == '"') {
            string_token();
        } else {
            const size_t start = at_;
            const TextPosition start_pos = here();
            while (!done() && peek() != ',' && peek() != '}' && peek() != ']' && peek() != ' ' &&
                   peek() != '\n' && peek() != '\t' && peek() != '\r')
                advance();
            note_overflow(start_pos, start, at_ - start);
        }
    }

    void note_overflow(TextPosition pos, size_t start, size_t length) {
        if (length < 4 || length > 400) return; // nothing shorter than "1e39" leaves the range of a double
        const std::string token(text_.substr(start, length));
        if (!(std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '-')) return;
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end == token.c_str() + token.size() && std::isinf(value))
            map_.overflows_.push_back({path_, pos, start, length, token});
    }

    void object(int depth) {
        advance(); // {
        skip_space();
        std::vector<std::pair<std::string, TextPosition>>
            keys; // objects are small: a linear check is fastest
        const size_t base = path_.size();
        while (!done() && peek() != '}') {
            const TextPosition key_pos = here();
            std::string key = string_token();
            if (base > 0) path_ += '.';
            path_ += key;
            auto seen = std::find_if(keys.begin(), keys.end(), [&](const auto& k) { return k.first == key; });
            if (seen != keys.end())
                map_.duplicates_.push_back({path_, seen->second, key_pos});
            else
                keys.emplace_back(std::move(key), key_pos);
            record(key_pos);
            skip_space();
            if (peek() == ':') advance();
            skip_space();
            value(depth + 1);
            path_.resize(base);
            skip_space();
            if (peek() == ',') advance();
            skip_space();
            if (!done() && peek() != '"' && peek() != '}') advance(); // broken text: always make progress
        }
        if (!done()) advance(); // }
    }

    void array(int depth) {
        advance(); // [
        skip_space();
        const size_t base = path_.size();
        char index[24];
        size_t count = 0;
        while (!done() && peek() != ']') {
            const int n = std::snprintf(index, sizeof(index), "[%zu]", count++);
            path_.append(index, static_cast<size_t>(n));
            record(here());
            const size_t before = at_;
            value(depth + 1);
            path_.resize(base);
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
    map.entries_.reserve(text.size() / 8);
    map.arena_.reserve(text.size());
    PositionScanner(text, map).run();
    return map;
}

TextPosition PositionMap::find(const std::string& path) const {
    if (sorted_.size() != entries_.size()) {
        sorted_.resize(entries_.size());
        for (std::uint32_t i = 0; i < sorted_.size(); ++i) sorted_[i] = i;
        // Stable: for a duplicated key the first occurrence is found, like the earlier position in messages.
        std::stable_sort(sorted_.begin(), sorted_.end(), [&](std::uint32_t a, std::uint32_t b) {
            return path_of(entries_[a]) < path_of(entries_[b]);
        });
    }
    std::string_view probe = path;
    while (true) {
        auto it =
            std::lower_bound(sorted_.begin(), sorted_.end(), probe,
                             [&](std::uint32_t i, std::string_view p) { return path_of(entries_[i]) < p; });
        if (it != sorted_.end() && path_of(entries_[*it]) == probe) return entries_[*it].position;
        if (probe.empty()) return {};
        // Strip the last component: "a.b[2]" -> "a.b" -> "a" -> "".
        const size_t cut = probe.find_last_of(".[");
        probe = cut == std::string_view::npos ? std::string_view() : probe.substr(0, cut);
    }
}

} // namespace ks::level
