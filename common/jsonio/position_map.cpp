#include "jsonio/position_map.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ks::jsonio {

// A recursive-descent walk over the text that tracks line and column as it goes (one pass, no
// backtracking). The current path lives in one buffer that grows and shrinks as the walk goes in and out.
class PositionScanner {
  public:
    // The first pass notes duplicate keys and overflowing numbers; the lookup index's pass records every
    // value's path and position.
    struct Findings {
        std::vector<DuplicateKey>* duplicates;
        std::vector<OverflowingNumber>* overflows;
    };
    struct Index {
        std::string* arena;
        std::vector<PositionMap::Entry>* entries;
    };
    PositionScanner(std::string_view text, Findings findings) : text_(text), findings_(findings) {}
    PositionScanner(std::string_view text, Index index) : text_(text), index_(index) {}

    void run() {
        skip_space();
        record(here());
        value(0);
    }

  private:
    static constexpr int kMaxDepth = 512; // nlohmann refuses deeper text anyway; this guards our own stack

    std::string_view text_;
    Findings findings_{nullptr, nullptr};
    Index index_{nullptr, nullptr};
    std::size_t at_ = 0;
    TextPosition pos_{1, 1};
    std::string path_;

    TextPosition here() const { return pos_; }
    bool done() const { return at_ >= text_.size(); }
    char peek() const { return done() ? '\0' : text_[at_]; }

    // Records the current path; returns its entry so that a member's value position can follow its key's.
    std::size_t record(TextPosition pos) {
        if (!index_.entries) return 0;
        index_.entries->push_back({static_cast<std::uint32_t>(index_.arena->size()),
                                   static_cast<std::uint32_t>(path_.size()), pos, pos});
        *index_.arena += path_;
        return index_.entries->size() - 1;
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
            const std::size_t start = at_;
            const TextPosition start_pos = here();
            while (!done() && peek() != ',' && peek() != '}' && peek() != ']' && peek() != ' ' &&
                   peek() != '\n' && peek() != '\t' && peek() != '\r')
                advance();
            note_overflow(start_pos, start, at_ - start);
        }
    }

    void note_overflow(TextPosition pos, std::size_t start, std::size_t length) {
        if (!findings_.overflows || length < 4 || length > 400)
            return; // nothing shorter than "1e39" leaves the range of a double
        // Without an exponent only a number of 309 digits or more can overflow: most numbers stop here,
        // before the copy and strtod below.
        const std::string_view raw = text_.substr(start, length);
        if (length < 309 && raw.find_first_of("eE") == std::string_view::npos) return;
        const std::string token(raw);
        if (!(std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '-')) return;
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end == token.c_str() + token.size() && std::isinf(value))
            findings_.overflows->push_back({path_, pos, start, length, token});
    }

    void object(int depth) {
        advance(); // {
        skip_space();
        std::vector<std::pair<std::string, TextPosition>>
            keys; // objects are small: a linear check is fastest
        const std::size_t base = path_.size();
        while (!done() && peek() != '}') {
            const TextPosition key_pos = here();
            std::string key = string_token();
            if (base > 0) path_ += '.';
            path_ += key;
            auto seen = std::find_if(keys.begin(), keys.end(), [&](const auto& k) { return k.first == key; });
            if (seen != keys.end()) {
                if (findings_.duplicates) findings_.duplicates->push_back({path_, seen->second, key_pos});
            } else
                keys.emplace_back(std::move(key), key_pos);
            const std::size_t entry = record(key_pos);
            skip_space();
            if (peek() == ':') advance();
            skip_space();
            if (index_.entries) (*index_.entries)[entry].value = here();
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
        const std::size_t base = path_.size();
        char index[24];
        std::size_t count = 0;
        while (!done() && peek() != ']') {
            // "[n]" without snprintf: every number of every [x, y, z] passes here.
            index[0] = '[';
            char* end = std::to_chars(index + 1, index + sizeof(index) - 1, count++).ptr;
            *end++ = ']';
            path_.append(index, static_cast<std::size_t>(end - index));
            record(here());
            const std::size_t before = at_;
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
    map.text_ = std::string(text);
    PositionScanner(map.text_, PositionScanner::Findings{&map.duplicates_, &map.overflows_}).run();
    return map;
}

void PositionMap::index() const {
    if (indexed_) return;
    indexed_ = true;
    entries_.reserve(text_.size() / 8);
    arena_.reserve(text_.size());
    PositionScanner(text_, PositionScanner::Index{&arena_, &entries_}).run();
}

std::pair<std::size_t, std::size_t> PositionMap::occurrences(std::string_view path) const {
    index();
    if (sorted_.size() != entries_.size()) {
        sorted_.resize(entries_.size());
        for (std::uint32_t i = 0; i < sorted_.size(); ++i) sorted_[i] = i;
        // Stable: the occurrences of one path stay in document order.
        std::stable_sort(sorted_.begin(), sorted_.end(), [&](std::uint32_t a, std::uint32_t b) {
            return path_of(entries_[a]) < path_of(entries_[b]);
        });
    }
    const auto first =
        std::lower_bound(sorted_.begin(), sorted_.end(), path,
                         [&](std::uint32_t i, std::string_view p) { return path_of(entries_[i]) < p; });
    const auto last = std::upper_bound(first, sorted_.end(), path, [&](std::string_view p, std::uint32_t i) {
        return p < path_of(entries_[i]);
    });
    return {static_cast<std::size_t>(first - sorted_.begin()),
            static_cast<std::size_t>(last - sorted_.begin())};
}

namespace {
// "a.b[2]" -> "a.b" -> "a" -> "".
std::string_view parent_path(std::string_view path) {
    const std::size_t cut = path.find_last_of(".[");
    return cut == std::string_view::npos ? std::string_view() : path.substr(0, cut);
}
} // namespace

TextPosition PositionMap::find(const std::string& path) const {
    std::string_view probe = path;
    while (true) {
        const auto [first, last] = occurrences(probe);
        if (first != last) return entries_[sorted_[first]].key;
        if (probe.empty()) return {};
        probe = parent_path(probe);
    }
}

TextPosition PositionMap::find_value(const std::string& path) const {
    const auto [first, last] = occurrences(path);
    if (first == last) return {};
    const std::uint32_t found = sorted_[last - 1];
    // The path must lie inside the last occurrence of each ancestor: with {"a": [1], "a": {}} the parser
    // keeps the object, so "a[0]" is not in the document even though the text holds it. Entries are in
    // document order, so "inside" is "after the ancestor's last occurrence".
    std::uint32_t inner = found;
    std::string_view ancestor = path;
    while (!ancestor.empty()) {
        ancestor = parent_path(ancestor);
        const auto [a_first, a_last] = occurrences(ancestor);
        if (a_first == a_last || sorted_[a_last - 1] > inner) return {};
        inner = sorted_[a_last - 1];
    }
    return entries_[found].value;
}

TextPosition locate(std::string_view text, const JsonPath& path) {
    return PositionMap::scan(text).find_value(path.str());
}

} // namespace ks::jsonio
