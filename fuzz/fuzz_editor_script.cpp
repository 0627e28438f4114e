// libFuzzer target: the editor's script language parser (killswitch-editor --script). Only parsing: running
// a script opens and saves files named in it.
#include "fuzz_oracle.h"
#include "model/script.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string file_name = "fuzz.kss";
    auto script = ks::editor::parse_script(text, file_name);
    if (!script.ok()) {
        ks::fuzz::check_clear_error(script.error(), file_name);
        // Errors read "file:line:column: message"; a line number outside the text is a wrong place.
        const int line = script.error().where.line;
        if (line < 0 || line > static_cast<int>(size) + 1)
            ks::fuzz::fail("error names a line past the end", script.error().str());
    }
    return 0;
}
