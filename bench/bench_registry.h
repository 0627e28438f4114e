#pragma once
// Benchmarks register a sub-command of ks_bench: `ks_bench NAME [options]`. Each prints a table, and may
// write a CSV/PNG plot under docs/bench/ and one JSON object on the last line with --json.
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ks::bench {

struct Command {
    std::string name;
    std::string summary;
    std::function<int(int argc, const char* const* argv)> run; // argv[0] is the sub-command name
    bool in_default_suite = true; // run by `ks_bench all` (what ./run.sh bench runs)
};

std::vector<Command>& registry();

// The one option most benchmarks take: `--quick` (a short run that leaves docs/bench/ alone). Whether it was
// given; nullopt, after naming the bench and the option on stderr, for anything else (the bench exits 2).
inline std::optional<bool> quick_option(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") != 0) {
            std::fprintf(stderr, "ks_bench %s: unknown option '%s' (options: --quick)\n", argv[0], argv[i]);
            return std::nullopt;
        }
        quick = true;
    }
    return quick;
}

struct Registrar {
    explicit Registrar(Command command) { registry().push_back(std::move(command)); }
};

} // namespace ks::bench
