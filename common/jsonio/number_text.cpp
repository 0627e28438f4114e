#include "jsonio/number_text.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ks::jsonio {
namespace {

template <class Number>
std::string shortest(Number value) {
    if (value == 0) return "0";
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

} // namespace

std::string shortest_text(double value) {
    return shortest(value);
}

std::string shortest_text(float value) {
    return shortest(value);
}

std::string format_number(double value) {
    return std::isfinite(value) ? shortest(value) : "null";
}

double float_to_double(float value) {
    if (!std::isfinite(value)) return static_cast<double>(value);
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer) - 1, value);
    *result.ptr = '\0';
    return std::strtod(buffer, nullptr);
}

std::string format_readable(double value) {
    if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
    return format_number(value);
}

std::string readable_float(float value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return format_readable(float_to_double(value));
}

} // namespace ks::jsonio
