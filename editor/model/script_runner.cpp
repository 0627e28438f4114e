// The script language's runner: each parsed step's own `run` on the script's context (script_command.h);
// a failing line stops the script with its line number.
#include "model/script_command.h"

namespace ks::editor {
namespace fs = std::filesystem;

fs::path ScriptContext::resolve(const std::string& p) const {
    fs::path path(p);
    return path.is_absolute() || base_dir.empty() ? path : base_dir / path;
}

Result<void> ScriptContext::expect(bool condition, const std::string& message) {
    ++report.expectations_checked;
    if (!condition) return Error("expectation failed: " + message);
    return ok();
}

Result<void> LevelStep::run(ScriptContext& c) const {
    return std::visit([&](const auto& s) { return s.run(c); }, step);
}

Result<ScriptReport> run_parsed_script(const Script& script, Editor& editor) {
    DojoDocument dojo; // the clip file the dojo lines edit (`dojo open`)
    ScriptReport report;
    ScriptContext context{editor, dojo, script.base_dir, script.file_name, report};
    for (const ScriptStep& step : script.steps) {
        context.line = step.line;
        auto r = std::visit([&](const auto& concern) { return concern.run(context); }, step.action);
        if (!r) {
            Error e = r.error();
            std::string where = e.where.str();
            e.message = (where.empty() ? "" : where + ": ") + e.message;
            e.where = Location{script.file_name, step.line};
            return e;
        }
        ++report.lines_run;
    }
    if (editor.history().in_transaction()) {
        editor.commit_transaction();
        return Error("the script ended inside a transaction", Location{script.file_name},
                     "close every 'begin' with 'commit' or 'cancel'");
    }
    return report;
}

} // namespace ks::editor
