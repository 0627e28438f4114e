#pragma once
// What every fuzz target checks beyond "no sanitizer report": a rejected input carries an error that says
// what is wrong and names the file, and an accepted one survives save -> load -> save unchanged. A broken
// property aborts, so libFuzzer keeps the input as a crash file like any memory error.
#include "core/result.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace ks::fuzz {

[[noreturn]] inline void fail(const char* what, std::string_view detail = {}) {
    std::fprintf(stderr, "fuzz property broken: %s\n%.*s\n", what, static_cast<int>(detail.size()),
                 detail.data());
    std::abort();
}

inline void check_clear_error(const Error& error, const std::string& file_name) {
    if (error.message.empty()) fail("error without a message", error.str());
    // A combined error lists the individual problems in its message; the first names the file either way.
    if (error.str().find(file_name) == std::string::npos) fail("error does not name the file", error.str());
}

} // namespace ks::fuzz
