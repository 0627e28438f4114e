#include "bench_registry.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace ks::bench {
std::vector<Command>& registry() {
    static std::vector<Command> commands;
    return commands;
}
} // namespace ks::bench

namespace {
void usage() {
    std::printf("usage: ks_bench COMMAND [options]\n       ks_bench all   (every default benchmark)\n\ncommands:\n");
    auto commands = ks::bench::registry();
    std::sort(commands.begin(), commands.end(), [](auto& a, auto& b) { return a.name < b.name; });
    for (auto& c : commands) std::printf("  %-12s %s\n", c.name.c_str(), c.summary.c_str());
}
} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        usage();
        return argc < 2 ? 2 : 0;
    }
    auto& commands = ks::bench::registry();
    if (!std::strcmp(argv[1], "all")) {
        int failures = 0;
        for (auto& c : commands) {
            if (!c.in_default_suite) continue;
            std::printf("\n=== %s: %s ===\n", c.name.c_str(), c.summary.c_str());
            std::fflush(stdout);
            const char* args[] = {c.name.c_str()};
            if (c.run(1, args) != 0) ++failures;
        }
        return failures == 0 ? 0 : 1;
    }
    for (auto& c : commands)
        if (c.name == argv[1]) return c.run(argc - 1, argv + 1);
    std::fprintf(stderr, "ks_bench: unknown command '%s'\n", argv[1]);
    usage();
    return 2;
}
