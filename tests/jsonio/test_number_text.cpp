// The shortest round-trip number text that files and messages share.
#include "jsonio/number_text.h"

#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>

using namespace ks::jsonio;

namespace {
double read_double(const std::string& text) {
    return std::strtod(text.c_str(), nullptr);
}
} // namespace

TEST_CASE("doubles print in their shortest form and read back exactly") {
    CHECK(format_number(0.1) == "0.1");
    CHECK(format_number(1e-7) == "1e-07");
    CHECK(format_number(100.0) == "100");
    CHECK(format_number(-2.5) == "-2.5");
    CHECK(format_number(0.1 + 0.2) == "0.30000000000000004");
    CHECK(format_number(1e300) == "1e+300");
    const double hard[] = {0.1,
                           1e-7,
                           1.0 / 3.0,
                           0.1 + 0.2,
                           -123456.789,
                           DBL_MAX,
                           -DBL_MAX,
                           DBL_MIN,
                           std::numeric_limits<double>::denorm_min(),
                           DBL_MIN / 3, // denormal
                           9007199254740993.0,
                           5e-324,
                           2.2250738585072011e-308};
    for (double value : hard) {
        CAPTURE(value);
        CHECK(read_double(format_number(value)) == value);
        CHECK(read_double(shortest_text(value)) == value);
    }
}

TEST_CASE("negative zero prints as 0") {
    CHECK(format_number(-0.0) == "0");
    CHECK(shortest_text(-0.0) == "0");
    CHECK(shortest_text(-0.0f) == "0");
}

TEST_CASE("floats print their own shortest form, not their double's") {
    CHECK(shortest_text(0.8f) == "0.8");
    CHECK(shortest_text(0.1f) == "0.1");
    CHECK(shortest_text(1e-7f) == "1e-07");
    CHECK(format_number(static_cast<double>(0.8f)) == "0.800000011920929");
    CHECK(format_number(float_to_double(0.8f)) == "0.8");
    const float hard[] = {0.1f,        1e-7f,  3.4028235e38f, -FLT_MAX, FLT_MIN,
                          FLT_MIN / 8, 1e-45f, 16777217.0f,   -78.6863f};
    for (float value : hard) {
        CAPTURE(value);
        CHECK(std::strtof(shortest_text(value).c_str(), nullptr) == value);
        CHECK(static_cast<float>(float_to_double(value)) == value);
    }
}

TEST_CASE("non-finite numbers: null in files, their name in messages") {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(format_number(inf) == "null");
    CHECK(format_number(-inf) == "null");
    CHECK(format_number(nan) == "null");
    CHECK(shortest_text(inf) == "inf");
    CHECK(shortest_text(-inf) == "-inf");
    CHECK(shortest_text(std::numeric_limits<float>::infinity()) == "inf");
    CHECK(std::isinf(float_to_double(std::numeric_limits<float>::infinity())));
    CHECK(std::isnan(float_to_double(std::numeric_limits<float>::quiet_NaN())));
    CHECK(format_readable(inf) == "null");
}

TEST_CASE("format_readable writes whole numbers in plain digits") {
    CHECK(format_readable(100000) == "100000");
    CHECK(format_readable(-42) == "-42");
    CHECK(format_readable(0.25) == "0.25");
    CHECK(format_readable(1e20) == "1e+20");
    CHECK(format_readable(-0.0) == "0");
}
