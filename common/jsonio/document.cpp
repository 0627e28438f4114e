#include "jsonio/document.h"

#include "jsonio/describe.h"
#include "jsonio/parse_failure.h"
#include "jsonio/text.h"

#include <algorithm>
#include <cstdio>

namespace ks::jsonio {
namespace {

bool is_blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

// Offset of the first byte that cannot be in a UTF-8 text file (NUL, other control bytes, broken UTF-8),
// or npos. Files that fail this are binary or corrupt: one clear message beats a cryptic parse error.
std::size_t first_binary_byte(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') return i;
            ++i;
            continue;
        }
        const int continuation = c >= 0xF0 && c <= 0xF4   ? 3
                                 : c >= 0xE0 && c <= 0xEF ? 2
                                 : c >= 0xC2 && c <= 0xDF ? 1
                                                          : -1;
        if (continuation < 0) return i;
        for (int k = 1; k <= continuation; ++k) {
            const std::size_t at = i + static_cast<std::size_t>(k);
            if (at >= text.size() || (static_cast<unsigned char>(text[at]) & 0xC0) != 0x80) return i;
        }
        i += static_cast<std::size_t>(continuation) + 1;
    }
    return std::string_view::npos;
}

// Offset of the first bracket that opens a level deeper than kMaxNestingDepth, or npos. Brackets inside
// strings do not count.
std::size_t first_too_deep(std::string_view text) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNestingDepth) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string_view::npos;
}

std::string byte_text(char byte) {
    char out[8];
    std::snprintf(out, sizeof(out), "0x%02x", static_cast<unsigned>(static_cast<unsigned char>(byte)));
    return out;
}

// A designer who wrote NaN or Infinity needs to hear that JSON has no such numbers, not just "syntax error".
std::string syntax_hint(std::string_view text, std::size_t byte) {
    const std::size_t offset = byte > 0 ? byte - 1 : 0;
    const std::string_view near = text.substr(offset >= 8 ? offset - 8 : 0, 16);
    for (const char* bad : {"NaN", "nan", "Infinity", "inf"})
        if (near.find(bad) != std::string_view::npos)
            return "JSON has no NaN or Infinity: write a finite number";
    return "fix the JSON syntax at this place";
}

} // namespace

Document Document::parse(std::string_view text, std::string file, const DocumentKind& kind) {
    Document doc;
    doc.file_ = std::move(file);
    doc.parse_text(text, kind);
    std::stable_sort(doc.problems_.begin(), doc.problems_.end(), [](const Problem& a, const Problem& b) {
        return std::pair(a.error.where.line, a.error.where.column) <
               std::pair(b.error.where.line, b.error.where.column);
    });
    return doc;
}

void Document::add(TextPosition position, std::string path, std::string message, std::string hint) {
    problems_.push_back(
        {Severity::Error,
         Error(std::move(message), location_at(file_, position, std::move(path)), std::move(hint))});
}

void Document::parse_text(std::string_view text, const DocumentKind& kind) {
    // Some Windows editors start UTF-8 files with a byte-order mark; it is not JSON, but it is not an error.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (is_blank(text)) return add({1, 1}, "", "file is empty", kind.example);
    if (const std::size_t bad = first_binary_byte(text); bad != std::string_view::npos)
        return add(position_of_offset(text, bad), "",
                   "file is not a text file (byte " + byte_text(text[bad]) + " at offset " +
                       std::to_string(bad) + ")",
                   "this does not look like a " + kind.what + " file; " + kind.example);
    if (const std::size_t deep = first_too_deep(text); deep != std::string_view::npos)
        return add(position_of_offset(text, deep), "",
                   "nested deeper than " + std::to_string(kMaxNestingDepth) + " levels",
                   "a " + kind.what + " file nests a few levels; check the brackets, or restore the file");

    positions_ = PositionMap::scan(text);
    std::string patched;
    std::string_view to_parse = text;
    if (!positions_.overflowing_numbers().empty()) {
        // nlohmann refuses the whole document over one 1e999: report each, read it as null (same length,
        // so every position holds), and parse the rest.
        patched = std::string(text);
        for (const OverflowingNumber& n : positions_.overflowing_numbers()) {
            add(n.position, n.path, "number " + n.token + " overflows to infinity",
                "write a finite number within the field's range");
            overflowing_paths_.push_back(n.path);
            patched.replace(n.offset, n.length, "null" + std::string(n.length - 4, ' '));
        }
        to_parse = patched;
    }
    try {
        root_ = Json::parse(to_parse);
    } catch (const nlohmann::json::parse_error& e) {
        const ParseFailure failure = describe_parse_error(text, e);
        if (failure.at_end)
            add(failure.position, "", "file ends early (truncated?): " + failure.message,
                "complete the file or restore it from a backup");
        else
            add(failure.position, "", failure.message, syntax_hint(text, e.byte));
        return;
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        if (const auto cut = what.find("] "); cut != std::string::npos) what = what.substr(cut + 2);
        return add({1, 1}, "", "JSON could not be read: " + what, "fix the JSON syntax");
    }
    for (const DuplicateKey& d : positions_.duplicate_keys())
        add(d.second, d.path,
            "duplicate key (also at line " + std::to_string(d.first.line) + ":" +
                std::to_string(d.first.column) + "); only one would be kept",
            "remove one of them");
    if (!root_.is_object())
        return add(positions_.find(""), "",
                   "expected the " + kind.what + " as a JSON object {...}, found " + describe_value(root_),
                   kind.example);
    readable_ = true;
}

void Document::report_to(ProblemSink& sink) const {
    for (const Problem& p : problems_)
        sink.report_at(p.severity, {p.error.where.line, p.error.where.column}, p.error.where.path,
                       p.error.message, p.error.hint);
    for (const std::string& path : overflowing_paths_) sink.mark_reported(path);
}

} // namespace ks::jsonio
