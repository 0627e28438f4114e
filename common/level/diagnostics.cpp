#include "level/diagnostics.h"

#include "jsonio/json_path.h"
#include "jsonio/number_text.h"
#include "jsonio/text.h"

#include <algorithm>
#include <climits>

namespace ks::level {

void DiagnosticSink::add(Diagnostic::Severity severity, jsonio::TextPosition pos, const std::string& path,
                         std::string message, std::string hint) {
    Diagnostic d;
    d.severity = severity;
    if (!subject_.empty()) message = subject_ + ": " + message;
    d.error = Error(std::move(message), jsonio::location_at(file_, pos, path), std::move(hint));
    list_.push_back(std::move(d));
}

void DiagnosticSink::error(const std::string& path, std::string message, std::string hint) {
    add(Diagnostic::Severity::Error, positions_ ? positions_->find(path) : jsonio::TextPosition{}, path,
        std::move(message), std::move(hint));
}

void DiagnosticSink::warning(const std::string& path, std::string message, std::string hint) {
    add(Diagnostic::Severity::Warning, positions_ ? positions_->find(path) : jsonio::TextPosition{}, path,
        std::move(message), std::move(hint));
}

void DiagnosticSink::error_at(jsonio::TextPosition pos, const std::string& path, std::string message,
                              std::string hint) {
    add(Diagnostic::Severity::Error, pos, path, std::move(message), std::move(hint));
}

void DiagnosticSink::report(jsonio::Severity severity, const std::string& path, std::string message,
                            std::string hint) {
    if (severity == jsonio::Severity::Error)
        error(path, std::move(message), std::move(hint));
    else
        warning(path, std::move(message), std::move(hint));
}

void DiagnosticSink::report_at(jsonio::Severity severity, jsonio::TextPosition pos, const std::string& path,
                               std::string message, std::string hint) {
    add(severity == jsonio::Severity::Error ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning,
        pos, path, std::move(message), std::move(hint));
}

void DiagnosticSink::tag_last(Diagnostic::Kind kind, std::string suggestion) {
    if (list_.empty()) return;
    list_.back().kind = kind;
    list_.back().suggestion = std::move(suggestion);
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

std::string entity_subject(const Entity& entity) {
    std::string out = std::string(type_name(entity.type())) + " " + std::to_string(entity.id);
    if (!entity.name.empty()) out += " (" + jsonio::quote_text(entity.name) + ")";
    return out;
}

std::string entity_path(size_t i, const std::vector<size_t>& source_index) {
    return jsonio::element_path("entities", i < source_index.size() ? source_index[i] : i);
}

Error errors_of(const std::vector<Diagnostic>& diagnostics, const std::string& file) {
    std::vector<Error> errors;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Diagnostic::Severity::Error) errors.push_back(d.error);
    return jsonio::combined_error(std::move(errors), file);
}

std::string range_text(const FieldInfo& info) {
    std::string out = jsonio::format_readable(info.min) + " .. " + jsonio::format_readable(info.max);
    if (info.unit && *info.unit) out += std::string(" ") + info.unit;
    return out;
}

} // namespace ks::level
