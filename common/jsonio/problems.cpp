#include "jsonio/problems.h"

#include "core/log.h"

#include <algorithm>
#include <climits>

namespace ks::jsonio {

void Problems::report(Severity severity, const std::string& path, std::string message, std::string hint) {
    report_at(severity, positions_ ? positions_->find(path) : TextPosition{}, path, std::move(message),
              std::move(hint));
}

void Problems::report_at(Severity severity, TextPosition position, const std::string& path,
                         std::string message, std::string hint) {
    list_.push_back(
        {severity, Error(std::move(message), location_at(file_, position, path), std::move(hint))});
}

bool Problems::has_errors() const {
    return std::any_of(list_.begin(), list_.end(),
                       [](const Problem& p) { return p.severity == Severity::Error; });
}

std::vector<Error> Problems::of(Severity severity) const {
    std::vector<Error> out;
    for (const Problem& p : list_)
        if (p.severity == severity) out.push_back(p.error);
    std::stable_sort(out.begin(), out.end(), [](const Error& a, const Error& b) {
        const auto key = [](const Error& e) {
            return std::pair(e.where.line > 0 ? e.where.line : INT_MAX, e.where.column);
        };
        return key(a) < key(b);
    });
    return out;
}

std::vector<Error> Problems::errors() const {
    return of(Severity::Error);
}

std::vector<Error> Problems::warnings() const {
    return of(Severity::Warning);
}

Error Problems::combined() const {
    return combined_error(errors(), file_);
}

void Problems::pass_warnings(std::vector<Error>* out) const {
    for (Error& warning : warnings()) {
        if (out)
            out->push_back(std::move(warning));
        else
            log::warn(warning.str());
    }
}

Error combined_error(std::vector<Error> errors, const std::string& file, std::size_t max_listed) {
    std::stable_sort(errors.begin(), errors.end(), [](const Error& a, const Error& b) {
        const auto key = [](const Error& e) {
            return std::pair(e.where.line > 0 ? e.where.line : INT_MAX, e.where.column);
        };
        return key(a) < key(b);
    });
    const std::size_t total = errors.size();
    if (total > max_listed) {
        errors.resize(max_listed);
        errors.emplace_back("... and " + std::to_string(total - max_listed) + " more errors", Location(file));
    }
    Error combined = combine_errors(errors);
    if (combined.where.file.empty()) combined.where.file = file;
    return combined;
}

} // namespace ks::jsonio
