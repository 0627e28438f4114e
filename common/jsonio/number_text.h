#pragma once
// Numbers as text, the same in every file we write and every message: the shortest decimal form that reads
// back to exactly the same value, so saving is deterministic and load -> save is byte-identical.
#include <string>

namespace ks::jsonio {

// The shortest text that reads back to exactly `value`; -0 prints as 0 (JSON readers would turn it into an
// integer 0 anyway). Non-finite values print as "inf", "-inf" or "nan": fine in messages, not valid JSON.
std::string shortest_text(double value);
// The same for a float: its own shortest form (0.8f prints as 0.8, not 0.800000011920929).
std::string shortest_text(float value);

// A number for a JSON file: shortest_text, with non-finite values written as null.
std::string format_number(double value);

// A float as the double whose shortest decimal form is the float's shortest form, so 0.8f is stored (and
// later printed) as 0.8 rather than 0.800000011920929. Non-finite values pass through unchanged.
double float_to_double(float value);

// For messages: whole numbers below 1e15 in plain digits (100000, not 1e+05), others as format_number.
std::string format_readable(double value);
// For messages about a float field: format_readable of its shortest form; NaN and the infinities by name.
std::string readable_float(float value);

} // namespace ks::jsonio
