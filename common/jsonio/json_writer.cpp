#include "jsonio/json_writer.h"

#include <algorithm>

#include "jsonio/number_text.h"

namespace ks::jsonio {
namespace {

bool is_scalar(const Json& value) {
    return !value.is_object() && !value.is_array();
}

bool all_scalars(const Json& array) {
    for (const auto& element : array)
        if (!is_scalar(element)) return false;
    return true;
}

void write_scalar(const Json& value, std::string& out) {
    if (value.is_number_float()) {
        out += format_number(value.get<double>());
    } else {
        out += compact_text(value); // strings (escaped), integers, booleans, null
    }
}

void write_value(const Json& value, int depth, std::string& out) {
    const std::string indent(static_cast<std::size_t>(depth + 1) * 2, ' ');
    const std::string closing_indent(static_cast<std::size_t>(depth) * 2, ' ');
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
            out += json_string(key);
            out += ": ";
            write_value(member, depth + 1, out);
        }
        out += "\n" + closing_indent + "}";
    } else if (value.is_array()) {
        if (value.empty()) {
            out += "[]";
        } else if (all_scalars(value)) {
            out += "[";
            for (std::size_t i = 0; i < value.size(); ++i) {
                if (i > 0) out += ", ";
                write_scalar(value[i], out);
            }
            out += "]";
        } else {
            out += "[\n";
            for (std::size_t i = 0; i < value.size(); ++i) {
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

std::string compact_text(const Json& value) {
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string json_string(std::string_view text) {
    // Plain printable ASCII needs no escaping (the serializer would give the same bytes): most names and
    // messages, quoted on every load, without building a Json value.
    const bool plain = std::all_of(text.begin(), text.end(),
                                   [](char c) { return c >= 0x20 && c < 0x7f && c != '"' && c != '\\'; });
    if (plain) {
        std::string out;
        out.reserve(text.size() + 2);
        out += '"';
        out += text;
        out += '"';
        return out;
    }
    return compact_text(Json(std::string(text)));
}

std::string write_document(const Json& document) {
    std::string out;
    out.reserve(4096);
    write_value(document, 0, out);
    out += "\n";
    return out;
}

} // namespace ks::jsonio
