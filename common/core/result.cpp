#include "core/result.h"

namespace ks {

std::string Location::str() const {
    std::string out = file;
    if (line > 0) {
        out += ":" + std::to_string(line);
        if (column > 0) out += ":" + std::to_string(column);
    }
    if (!path.empty()) {
        if (!out.empty()) out += ": ";
        out += path;
    }
    return out;
}

std::string Error::str() const {
    std::string where_str = where.str();
    std::string out = where_str.empty() ? message : where_str + ": " + message;
    if (!hint.empty()) out += " (" + hint + ")";
    return out;
}

Error combine_errors(const std::vector<Error>& errors) {
    if (errors.size() == 1) return errors.front();
    Error combined;
    combined.message = std::to_string(errors.size()) + " problems:";
    for (const Error& e : errors) combined.message += "\n  " + e.str();
    if (!errors.empty()) combined.where.file = errors.front().where.file;
    return combined;
}

} // namespace ks
