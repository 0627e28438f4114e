#include "level/json_text.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ks::level::json_text {
namespace {

// Strings in memory may hold invalid UTF-8 (typed or pasted in the editor); saving must not throw over them.
std::string dump(const nlohmann::ordered_json& value) {
    return value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

bool is_scalar(const nlohmann::ordered_json& value) {
    return !value.is_object() && !value.is_array();
}

bool all_scalars(const nlohmann::ordered_json& array) {
    for (const auto& element : array)
        if (!is_scalar(element)) return false;
    return true;
}

void write_scalar(const nlohmann::ordered_json& value, std::string& out) {
    if (value.is_number_float()) {
        out += format_number(value.get<double>());
    } else {
        out += dump(value); // strings (escaped), integers, booleans, null
    }
}

void write_value(const nlohmann::ordered_json& value, int depth, std::string& out) {
    const std::string indent(static_cast<size_t>(depth + 1) * 2, ' ');
    const std::string closing_indent(static_cast<size_t>(depth) * 2, ' ');
    if (value.is_object()) {
        if (value.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        bool first = true;
        for (const auto& [key, member] : value.items()) {
            if (!first) out += ",\n";
            first = false;
            out += indent;
            out += dump(nlohmann::ordered_json(key));
            out += ": ";
            write_value(member, depth + 1, out);
        }
        out += "\n" + closing_indent + "}";
    } else if (value.is_array()) {
        if (value.empty()) {
            out += "[]";
        } else if (all_scalars(value)) {
            out += "[";
            for (size_t i = 0; i < value.size(); ++i) {
                if (i > 0) out += ", ";
                write_scalar(value[i], out);
            }
            out += "]";
        } else {
            out += "[\n";
            for (size_t i = 0; i < value.size(); ++i) {
                if (i > 0) out += ",\n";
                out += indent;
                write_value(value[i], depth + 1, out);
            }
            out += "\n" + closing_indent + "]";
        }
    } else {
        write_scalar(value, out);
    }
}

} // namespace

double float_to_double(float value) {
    if (!std::isfinite(value)) return static_cast<double>(value);
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer) - 1, value);
    *result.ptr = '\0';
    return std::strtod(buffer, nullptr);
}

std::string format_number(double value) {
    if (!std::isfinite(value)) return "null";
    if (value == 0.0) return "0"; // also folds -0, which JSON readers would turn into an integer 0 anyway
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

std::string format_readable(double value) {
    if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
    return format_number(value);
}

std::string quote(const nlohmann::ordered_json& value) {
    std::string text = dump(value);
    if (text.size() > 80) text = text.substr(0, 77) + "...";
    return text;
}

std::string write(const nlohmann::ordered_json& document) {
    std::string out;
    out.reserve(4096);
    write_value(document, 0, out);
    out += "\n";
    return out;
}

} // namespace ks::level::json_text
