// Damaged files never crash the loader: random truncations, byte flips and splices of a real level each
// give a level or errors that name the file -- nothing else.
#include "core/random.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks::level;

TEST_CASE("mutated copies of the main level load or fail cleanly") {
    const std::string original = ks::test::read_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(original.size() > 1000);
    ks::Rng rng(99);
    static const char kBytes[] = "{}[],:\"0123456789.eE+-nultrfasx \n\\\x00\xff";
    int loaded = 0, failed = 0;
    for (int round = 0; round < 600; ++round) {
        std::string text = original;
        const int edits = 1 + static_cast<int>(rng.below(4));
        for (int e = 0; e < edits; ++e) {
            const size_t at = rng.below(static_cast<std::uint32_t>(text.size()));
            switch (rng.below(4)) {
            case 0:
                text.resize(at);
                break; // truncate
            case 1:
                text[at] = kBytes[rng.below(sizeof(kBytes) - 1)];
                break;
            case 2:
                text.erase(at, rng.below(40));
                break;
            default:
                text.insert(at, text.substr(rng.below(static_cast<std::uint32_t>(text.size())), 30));
                break;
            }
            if (text.empty()) break;
        }
        LoadReport report;
        auto level = load_level_string(text, "fuzz.json", &report);
        if (level.ok()) {
            ++loaded;
            CHECK(report.error_count() == 0);
            // Whatever loaded saves and reloads to the same text.
            const std::string saved = save_level_string(*level);
            auto again = load_level_string(saved, "fuzz-resaved.json");
            REQUIRE(again.ok());
            CHECK(save_level_string(*again) == saved);
        } else {
            ++failed;
            REQUIRE(report.error_count() >= 1);
            for (const Diagnostic& d : report.diagnostics) CHECK(d.error.where.file == "fuzz.json");
        }
    }
    MESSAGE("mutated files: " << loaded << " loaded, " << failed << " rejected");
    CHECK(failed > 300);
}
