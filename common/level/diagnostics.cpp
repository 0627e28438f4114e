#include "level/diagnostics.h"

#include "level/json_text.h"

#include <algorithm>
#include <climits>

namespace ks::level {

void DiagnosticSink::add(Diagnostic::Severity severity, TextPosition pos, const std::string& path,
                         std::string message, std::string hint) {
    Diagnostic d;
    d.severity = severity;
    d.error = Error(std::move(message), Location(file_, pos.line, pos.column, path), std::move(hint));
    list_.push_back(std::move(d));
}

void DiagnosticSink::error(const std::string& path, std::string message, std::string hint) {
    add(Diagnostic::Severity::Error, positions_ ? positions_->find(path) : TextPosition{}, path,
        std::move(message), std::move(hint));
}

void DiagnosticSink::warning(const std::string& path, std::string message, std::string hint) {
    add(Diagnostic::Severity::Warning, positions_ ? positions_->find(path) : TextPosition{}, path,
        std::move(message), std::move(hint));
}

void DiagnosticSink::error_at(TextPosition pos, const std::string& path, std::string message,
                              std::string hint) {
    add(Diagnostic::Severity::Error, pos, path, std::move(message), std::move(hint));
}

bool DiagnosticSink::has_errors() const {
    return std::any_of(list_.begin(), list_.end(),
                       [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; });
}

std::vector<Diagnostic> DiagnosticSink::take_sorted() {
    auto key = [](const Diagnostic& d) {
        const int line = d.error.where.line > 0 ? d.error.where.line : INT_MAX;
        return std::pair(line, d.error.where.column);
    };
    std::stable_sort(list_.begin(), list_.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
    return std::move(list_);
}

namespace {
size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}
} // namespace

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1; // only suggest plausible typos
    for (const std::string& c : candidates) {
        const size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

std::string range_text(const FieldInfo& info) {
    std::string out = json_text::format_readable(info.min) + " .. " + json_text::format_readable(info.max);
    if (info.unit && *info.unit) out += std::string(" ") + info.unit;
    return out;
}

std::string join(const std::vector<std::string>& words, std::string_view separator) {
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) {
        if (i > 0) out += separator;
        out += words[i];
    }
    return out;
}

} // namespace ks::level
