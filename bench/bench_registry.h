#pragma once
// Benchmarks register a sub-command of ks_bench: `ks_bench NAME [options]`. Each prints a table, and may
// write a CSV/PNG plot under docs/bench/ and one JSON object on the last line with --json.
#include <functional>
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

struct Registrar {
    explicit Registrar(Command command) { registry().push_back(std::move(command)); }
};

} // namespace ks::bench
