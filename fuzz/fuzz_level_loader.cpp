// libFuzzer target: level files (format v3 with its level logic and brushes, older versions migrated on
// load).
#include "fuzz_oracle.h"
#include "level/level_io.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string file_name = "fuzz.json";
    ks::level::LoadReport report;
    auto level = ks::level::load_level_string(text, file_name, &report);
    if (!level.ok()) {
        ks::fuzz::check_clear_error(level.error(), file_name);
        if (!report.has_errors()) ks::fuzz::fail("rejected without an error diagnostic", level.error().str());
        return 0;
    }
    if (report.has_errors()) ks::fuzz::fail("accepted with error diagnostics", report.str());
    const std::string saved = ks::level::save_level_string(*level);
    auto again = ks::level::load_level_string(saved, "fuzz-resaved.json");
    if (!again.ok()) ks::fuzz::fail("a loaded level does not reload after saving", again.error().str());
    if (ks::level::save_level_string(*again) != saved)
        ks::fuzz::fail("save -> load -> save changed the text", saved);
    return 0;
}
