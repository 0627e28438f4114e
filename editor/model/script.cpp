// The script entry points that read and run whole scripts; parsing is in script_parser.cpp, running in
// script_runner.cpp.
#include "model/script.h"

#include "core/files.h"

namespace ks::editor {
namespace fs = std::filesystem;

Result<ScriptReport> run_script_text(std::string_view text, const std::string& file_name,
                                     const fs::path& base_dir, Editor& editor) {
    auto script = parse_script(text, file_name);
    if (!script) return script.error();
    script->base_dir = base_dir;
    return run_parsed_script(*script, editor);
}

Result<ScriptReport> run_script(const fs::path& path) {
    auto text = files::read_text(path);
    if (!text) return text.error();
    Editor editor;
    return run_script_text(*text, path.string(), path.has_parent_path() ? path.parent_path() : fs::path("."),
                           editor);
}

} // namespace ks::editor
