#include "model/script.h"

#include "core/files.h"
#include "core/log.h"

#include <charconv>
#include <cmath>
#include <optional>

namespace ks::editor {
namespace fs = std::filesystem;
namespace {

struct Token {
    std::string_view text;
    int column = 0; // 1-based
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (i >= line.size()) break;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return out;
}

bool to_float(std::string_view s, float& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto res = std::from_chars(s.data(), s.data() + s.size(), out);
    return res.ec == std::errc() && res.ptr == s.data() + s.size() && std::isfinite(out);
}

bool to_int(std::string_view s, int& out) {
    auto res = std::from_chars(s.data(), s.data() + s.size(), out);
    return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

bool to_vec3(std::string_view s, Vec3& out) {
    for (int i = 0; i < 3; ++i) {
        size_t comma = s.find(',');
        if ((i < 2) != (comma != std::string_view::npos)) return false;
        if (!to_float(s.substr(0, comma), out[i])) return false;
        if (comma != std::string_view::npos) s.remove_prefix(comma + 1);
    }
    return true;
}

// A comment starts at a '#' that begins the line or stands alone as a word ("# ..."), so colour values
// like #ffcc80 stay values.
std::string_view strip_comment(std::string_view line) {
    for (size_t i = 0; i < line.size(); ++i) {
        if (line[i] != '#') continue;
        const bool starts_line = line.find_first_not_of(" \t") == i;
        const bool own_word = i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t') &&
                              (i + 1 == line.size() || line[i + 1] == ' ' || line[i + 1] == '\t');
        if (starts_line || own_word) return line.substr(0, i);
    }
    return line;
}

std::string type_names() {
    std::string s;
    for (auto t : level::all_types()) s += (s.empty() ? "" : ", ") + std::string(level::type_name(t));
    return s;
}

std::optional<Rule> rule_from_name(std::string_view name) {
    for (Rule r : {Rule::Format, Rule::PlayerStart, Rule::ControlPanel, Rule::WallOverlap, Rule::Support,
                   Rule::StairSlope, Rule::DoorGap, Rule::Reachability})
        if (name == rule_name(r)) return r;
    return std::nullopt;
}

// Parses one line's tokens into a step; errors carry the column of the offending token.
class LineParser {
  public:
    LineParser(std::string_view line, std::vector<Token> tokens, int line_no, const std::string& file)
        : line_(line), tokens_(std::move(tokens)), line_no_(line_no), file_(file) {}

    Result<ScriptStep> parse() {
        step_.line = line_no_;
        const std::string_view op = tokens_[0].text;
        if (op == "new") return simple(ScriptOp::New);
        if (op == "open") return path_op(ScriptOp::Open);
        if (op == "save") {
            if (tokens_.size() == 1) return simple(ScriptOp::Save);
            if (tokens_.size() == 3 && tokens_[2].text != "overwrite")
                return fail(2, "unexpected '" + std::string(tokens_[2].text) + "'", "save PATH [overwrite]");
            if (tokens_.size() > 3) return fail(3, "too many words", "save PATH [overwrite]");
            step_.op = ScriptOp::SaveAs;
            step_.text = std::string(tokens_[1].text);
            step_.count = tokens_.size() == 3;
            return step_;
        }
        if (op == "place") return place();
        if (op == "select") return select();
        if (op == "move") {
            step_.op = ScriptOp::Move;
            if (auto r = need(2, 3, "move DX,DY,DZ [snap]"); !r) return r.error();
            if (auto r = vec(1, step_.vec); !r) return r.error();
            if (tokens_.size() == 3 && tokens_[2].text != "snap")
                return fail(2, "expected 'snap'", "move DX,DY,DZ [snap]");
            step_.count = tokens_.size() == 3;
            return step_;
        }
        if (op == "nudge") {
            step_.op = ScriptOp::Nudge;
            if (auto r = need(2, 2, "nudge +x|-x|+y|-y|+z|-z"); !r) return r.error();
            const std::string_view d = tokens_[1].text;
            if (d.size() != 2 || (d[0] != '+' && d[0] != '-') || d[1] < 'x' || d[1] > 'z')
                return fail(1, "expected a direction like +x or -z", "nudge +x|-x|+y|-y|+z|-z");
            step_.count = d[1] - 'x';
            step_.number = d[0] == '+' ? 1.0f : -1.0f;
            return step_;
        }
        if (op == "rotate") return number_op(ScriptOp::Rotate, "rotate DEGREES");
        if (op == "scale") {
            step_.op = ScriptOp::Scale;
            if (auto r = need(2, 2, "scale S or scale SX,SY,SZ"); !r) return r.error();
            float s = 0;
            if (to_float(tokens_[1].text, s))
                step_.vec = Vec3(s);
            else if (auto r = vec(1, step_.vec); !r)
                return r.error();
            return step_;
        }
        if (op == "set" || op == "setting") {
            step_.op = op == "set" ? ScriptOp::Set : ScriptOp::Setting;
            if (tokens_.size() < 3)
                return fail(0, "expected a field and a value", std::string(op) + " FIELD VALUE");
            step_.text = std::string(tokens_[1].text);
            step_.text2 = rest(2);
            return step_;
        }
        if (op == "reset") return word_op(ScriptOp::Reset, "reset FIELD");
        if (op == "player_start") {
            step_.op = ScriptOp::PlayerStart;
            if (tokens_.size() != 2 && tokens_.size() != 4)
                return fail(0, "wrong number of words", "player_start X,Y,Z [yaw D]");
            if (auto r = vec(1, step_.vec); !r) return r.error();
            if (tokens_.size() == 4) {
                if (tokens_[2].text != "yaw") return fail(2, "expected 'yaw'", "player_start X,Y,Z [yaw D]");
                if (!to_float(tokens_[3].text, step_.number)) return fail(3, "expected degrees", "yaw 90");
            }
            return step_;
        }
        if (op == "level_name") {
            step_.op = ScriptOp::LevelName;
            if (tokens_.size() < 2) return fail(0, "expected a name", "level_name Two Rooms");
            step_.text = rest(1);
            return step_;
        }
        if (op == "delete") return simple(ScriptOp::Delete);
        if (op == "duplicate") {
            step_.op = ScriptOp::Duplicate;
            if (auto r = need(1, 2, "duplicate [DX,DY,DZ]"); !r) return r.error();
            if (tokens_.size() == 2) {
                if (auto r = vec(1, step_.vec); !r) return r.error();
                step_.has_vec = true;
            }
            return step_;
        }
        if (op == "copy") return simple(ScriptOp::Copy);
        if (op == "paste") return simple(ScriptOp::Paste);
        if (op == "undo" || op == "redo") {
            step_.op = op == "undo" ? ScriptOp::Undo : ScriptOp::Redo;
            if (auto r = need(1, 2, std::string(op) + " [N|all]"); !r) return r.error();
            step_.count = 1;
            if (tokens_.size() == 2) {
                if (tokens_[1].text == "all")
                    step_.count = -1;
                else if (!to_int(tokens_[1].text, step_.count) || step_.count < 1)
                    return fail(1, "expected a count of steps",
                                std::string(op) + " 3, or " + std::string(op) + " all");
            }
            return step_;
        }
        if (op == "grid") {
            step_.op = ScriptOp::Grid;
            if (auto r = need(2, 3, "grid STEP [ROTATION_STEP]"); !r) return r.error();
            if (!to_float(tokens_[1].text, step_.number) || step_.number <= 0)
                return fail(1, "expected a positive grid step", "grid 0.5");
            step_.vec.x = 15.0f;
            if (tokens_.size() == 3 && (!to_float(tokens_[2].text, step_.vec.x) || step_.vec.x <= 0))
                return fail(2, "expected a positive rotation step in degrees", "grid 1 15");
            return step_;
        }
        if (op == "snap") {
            step_.op = ScriptOp::Snap;
            if (auto r = need(2, 2, "snap on|off"); !r) return r.error();
            if (tokens_[1].text != "on" && tokens_[1].text != "off")
                return fail(1, "expected on or off", "snap off");
            step_.count = tokens_[1].text == "on";
            return step_;
        }
        if (op == "lock") return ids_op(ScriptOp::Lock, "lock ID...");
        if (op == "unlock") return ids_op(ScriptOp::Unlock, "unlock ID...");
        if (op == "hide") return ids_op(ScriptOp::Hide, "hide ID...");
        if (op == "show") return ids_op(ScriptOp::Show, "show ID...");
        if (op == "begin") {
            step_.op = ScriptOp::Begin;
            step_.text = tokens_.size() > 1 ? rest(1) : "Script transaction";
            return step_;
        }
        if (op == "commit") return simple(ScriptOp::Commit);
        if (op == "cancel") return simple(ScriptOp::Cancel);
        if (op == "fix") {
            step_.op = ScriptOp::Fix;
            if (auto r = need(2, 2, "fix RULE"); !r) return r.error();
            if (!rule_from_name(tokens_[1].text)) return fail(1, "unknown rule", "rules: " + rule_list());
            step_.text = std::string(tokens_[1].text);
            return step_;
        }
        if (op == "recover") {
            step_.op = ScriptOp::Recover;
            if (auto r = need(2, 2, "recover accept|decline"); !r) return r.error();
            if (tokens_[1].text != "accept" && tokens_[1].text != "decline")
                return fail(1, "expected accept or decline", "recover accept");
            step_.count = tokens_[1].text == "accept";
            return step_;
        }
        if (op == "expect") return expect();
        return fail(
            0, "unknown command '" + std::string(op) + "'",
            "commands: new open save place select move nudge rotate scale set reset setting player_start "
            "level_name delete duplicate copy paste undo redo grid snap lock unlock hide show begin commit "
            "cancel fix recover expect");
    }

  private:
    Error fail(size_t token, std::string message, std::string hint) const {
        const int column =
            token < tokens_.size() ? tokens_[token].column : static_cast<int>(line_.size()) + 1;
        return Error(std::move(message), Location{file_, line_no_, column}, std::move(hint));
    }
    Result<void> need(size_t min, size_t max, const std::string& usage) const {
        if (tokens_.size() < min) return fail(tokens_.size(), "missing words", usage);
        if (tokens_.size() > max)
            return fail(max, "unexpected '" + std::string(tokens_[max].text) + "'", usage);
        return ok();
    }
    Result<void> vec(size_t token, Vec3& out) const {
        if (!to_vec3(tokens_[token].text, out))
            return fail(token,
                        "expected three numbers separated by commas, got '" +
                            std::string(tokens_[token].text) + "'",
                        "write it without spaces, like 10,0,-5");
        return ok();
    }
    std::string rest(size_t token) const {
        return std::string(line_.substr(static_cast<size_t>(tokens_[token].column - 1)));
    }
    static std::string rule_list() {
        std::string s;
        for (Rule r : {Rule::Format, Rule::PlayerStart, Rule::ControlPanel, Rule::WallOverlap, Rule::Support,
                       Rule::StairSlope, Rule::DoorGap, Rule::Reachability})
            s += (s.empty() ? "" : ", ") + std::string(rule_name(r));
        return s;
    }
    Result<ScriptStep> simple(ScriptOp op) {
        step_.op = op;
        if (tokens_.size() > 1)
            return fail(1, "unexpected '" + std::string(tokens_[1].text) + "'",
                        std::string(tokens_[0].text) + " takes no arguments");
        return step_;
    }
    Result<ScriptStep> path_op(ScriptOp op) {
        step_.op = op;
        if (tokens_.size() < 2)
            return fail(1, "expected a file path", std::string(tokens_[0].text) + " levels/x.json");
        step_.text = rest(1);
        return step_;
    }
    Result<ScriptStep> word_op(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        step_.text = std::string(tokens_[1].text);
        return step_;
    }
    Result<ScriptStep> number_op(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        if (!to_float(tokens_[1].text, step_.number)) return fail(1, "expected a number", usage);
        return step_;
    }
    Result<ScriptStep> ids_op(ScriptOp op, const char* usage, size_t first = 1) {
        step_.op = op;
        if (tokens_.size() <= first) return fail(first, "expected entity ids", usage);
        for (size_t i = first; i < tokens_.size(); ++i) {
            int id = 0;
            if (!to_int(tokens_[i].text, id) || id < 1)
                return fail(i, "expected an entity id (a positive whole number)", usage);
            step_.ids.push_back(id);
        }
        return step_;
    }
    Result<ScriptStep> entity_type(size_t token) {
        if (token >= tokens_.size()) return fail(token, "expected an entity type", "types: " + type_names());
        if (!level::type_from_name(tokens_[token].text, step_.type))
            return fail(token, "unknown entity type '" + std::string(tokens_[token].text) + "'",
                        "types: " + type_names());
        return step_;
    }
    Result<ScriptStep> place() {
        step_.op = ScriptOp::Place;
        const char* usage = "place TYPE at X,Y,Z [yaw D] [name TEXT]";
        if (tokens_.size() < 4) return fail(tokens_.size(), "missing words", usage);
        if (auto r = entity_type(1); !r) return r;
        if (tokens_[2].text != "at") return fail(2, "expected 'at'", usage);
        if (auto r = vec(3, step_.vec); !r) return r.error();
        size_t i = 4;
        if (i < tokens_.size() && tokens_[i].text == "yaw") {
            if (i + 1 >= tokens_.size() || !to_float(tokens_[i + 1].text, step_.number))
                return fail(i + 1, "expected degrees after 'yaw'", usage);
            i += 2;
        }
        if (i < tokens_.size()) {
            if (tokens_[i].text != "name" || i + 1 >= tokens_.size())
                return fail(i, "expected 'yaw D' or 'name TEXT'", usage);
            step_.text = rest(i + 1);
        }
        return step_;
    }
    Result<ScriptStep> select() {
        const char* usage =
            "select [add|toggle|remove] ID... | select all [TYPE] | select none | select box X,Y,Z X,Y,Z";
        if (tokens_.size() < 2) return fail(1, "missing words", usage);
        const std::string_view w = tokens_[1].text;
        if (w == "none") return simple_after(ScriptOp::SelectNone, 2);
        if (w == "all") {
            if (tokens_.size() == 2) return simple_after(ScriptOp::SelectAll, 2);
            step_.op = ScriptOp::SelectType;
            if (auto r = need(3, 3, usage); !r) return r.error();
            return entity_type(2);
        }
        if (w == "box") {
            step_.op = ScriptOp::SelectBox;
            if (auto r = need(4, 4, usage); !r) return r.error();
            if (auto r = vec(2, step_.vec); !r) return r.error();
            if (auto r = vec(3, step_.vec2); !r) return r.error();
            return step_;
        }
        size_t first = 1;
        if (w == "add")
            step_.mode = SelectMode::Add, first = 2;
        else if (w == "toggle")
            step_.mode = SelectMode::Toggle, first = 2;
        else if (w == "remove")
            step_.mode = SelectMode::Remove, first = 2;
        return ids_op(ScriptOp::Select, usage, first);
    }
    Result<ScriptStep> simple_after(ScriptOp op, size_t words) {
        step_.op = op;
        if (tokens_.size() > words)
            return fail(words, "unexpected '" + std::string(tokens_[words].text) + "'", "");
        return step_;
    }
    Result<ScriptStep> expect() {
        const char* usage = "expect count TYPE N | valid | issue RULE [ID] | no_issue RULE | selected N | "
                            "field ID FIELD VALUE | dirty | clean";
        if (tokens_.size() < 2) return fail(1, "missing words", usage);
        const std::string_view w = tokens_[1].text;
        if (w == "valid") return simple_after(ScriptOp::ExpectValid, 2);
        if (w == "dirty") return simple_after(ScriptOp::ExpectDirty, 2);
        if (w == "clean") return simple_after(ScriptOp::ExpectClean, 2);
        if (w == "count") {
            step_.op = ScriptOp::ExpectCount;
            if (auto r = need(4, 4, usage); !r) return r.error();
            if (auto r = entity_type(2); !r) return r;
            if (!to_int(tokens_[3].text, step_.count) || step_.count < 0)
                return fail(3, "expected a count", usage);
            return step_;
        }
        if (w == "selected") {
            step_.op = ScriptOp::ExpectSelected;
            if (auto r = need(3, 3, usage); !r) return r.error();
            if (!to_int(tokens_[2].text, step_.count) || step_.count < 0)
                return fail(2, "expected a count", usage);
            return step_;
        }
        if (w == "issue" || w == "no_issue") {
            step_.op = w == "issue" ? ScriptOp::ExpectIssue : ScriptOp::ExpectNoIssue;
            if (auto r = need(3, w == "issue" ? 4 : 3, usage); !r) return r.error();
            if (!rule_from_name(tokens_[2].text)) return fail(2, "unknown rule", "rules: " + rule_list());
            step_.text = std::string(tokens_[2].text);
            if (tokens_.size() == 4) {
                if (!to_int(tokens_[3].text, step_.count) || step_.count < 1)
                    return fail(3, "expected an entity id", usage);
            }
            return step_;
        }
        if (w == "field") {
            step_.op = ScriptOp::ExpectField;
            if (tokens_.size() < 5) return fail(tokens_.size(), "missing words", usage);
            if (!to_int(tokens_[2].text, step_.count) || step_.count < 1)
                return fail(2, "expected an entity id", usage);
            step_.text = std::string(tokens_[3].text);
            step_.text2 = rest(4);
            return step_;
        }
        return fail(1, "unknown expectation '" + std::string(w) + "'", usage);
    }

    std::string_view line_;
    std::vector<Token> tokens_;
    int line_no_;
    const std::string& file_;
    ScriptStep step_;
};

// ---- running ----------------------------------------------------------------------------------------

class Runner {
  public:
    Runner(const Script& script, Editor& editor) : script_(script), editor_(editor) {}

    Result<ScriptReport> run() {
        for (const auto& step : script_.steps) {
            if (auto r = run_step(step); !r) {
                Error e = r.error();
                std::string where = e.where.str();
                e.message = (where.empty() ? "" : where + ": ") + e.message;
                e.where = Location{script_.file_name, step.line};
                return e;
            }
            ++report_.lines_run;
        }
        if (editor_.history().in_transaction()) {
            editor_.commit_transaction();
            return Error("the script ended inside a transaction", Location{script_.file_name},
                         "close every 'begin' with 'commit' or 'cancel'");
        }
        return report_;
    }

  private:
    fs::path resolve(const std::string& p) const {
        fs::path path(p);
        return path.is_absolute() || script_.base_dir.empty() ? path : script_.base_dir / path;
    }

    Result<void> expect(bool condition, std::string message) {
        ++report_.expectations_checked;
        if (!condition) return Error("expectation failed: " + std::move(message));
        return ok();
    }

    static std::string issue_list(const std::vector<Issue>& issues) {
        std::string s;
        for (const auto& i : issues) s += std::string("\n  [") + rule_name(i.rule) + "] " + i.message;
        return s;
    }

    Result<void> run_step(const ScriptStep& s) {
        switch (s.op) {
        case ScriptOp::New:
            editor_.new_document();
            return ok();
        case ScriptOp::Open:
            return editor_.open(resolve(s.text));
        case ScriptOp::Save: {
            auto r = editor_.save();
            if (!r) return r.error();
            report_.saved.push_back(r->path);
            return ok();
        }
        case ScriptOp::SaveAs: {
            SaveOptions options;
            options.overwrite_existing = s.count != 0;
            auto r = editor_.save_as(resolve(s.text), options);
            if (!r) return r.error();
            report_.saved.push_back(r->path);
            if (r->draft)
                log::warn(script_.file_name, ":", s.line, ": saved a draft with ", r->error_count,
                          " error(s)");
            return ok();
        }
        case ScriptOp::Place: {
            auto r = editor_.place(s.type, s.vec, s.number, s.text);
            if (!r) return r.error();
            return ok();
        }
        case ScriptOp::Select:
            return editor_.select(s.ids, s.mode);
        case ScriptOp::SelectAll:
            editor_.select_all();
            return ok();
        case ScriptOp::SelectType:
            editor_.select_all_of_type(s.type);
            return ok();
        case ScriptOp::SelectNone:
            editor_.clear_selection();
            return ok();
        case ScriptOp::SelectBox:
            editor_.select_in_box({glm::min(s.vec, s.vec2), glm::max(s.vec, s.vec2)});
            return ok();
        case ScriptOp::Move:
            return editor_.move_selection(s.vec, s.count != 0);
        case ScriptOp::Nudge:
            return editor_.nudge(s.count, static_cast<int>(s.number));
        case ScriptOp::Rotate:
            return editor_.rotate_selection(s.number);
        case ScriptOp::Scale:
            return editor_.scale_selection(s.vec);
        case ScriptOp::Set:
            return editor_.set_field_text(s.text, s.text2);
        case ScriptOp::Reset:
            return editor_.revert_field(s.text);
        case ScriptOp::Setting:
            return editor_.set_setting_text(s.text, s.text2);
        case ScriptOp::PlayerStart:
            return editor_.set_player_start({s.vec, s.number});
        case ScriptOp::LevelName:
            return editor_.rename_level(s.text);
        case ScriptOp::Delete:
            return editor_.delete_selection();
        case ScriptOp::Duplicate:
            return editor_.duplicate(s.has_vec ? std::optional<Vec3>(s.vec) : std::nullopt);
        case ScriptOp::Copy:
            if (editor_.doc().selection.empty())
                return Error("copy: nothing is selected", Location{}, "select entities first");
            editor_.copy();
            return ok();
        case ScriptOp::Paste:
            return editor_.paste();
        case ScriptOp::Undo:
        case ScriptOp::Redo: {
            const bool undo = s.op == ScriptOp::Undo;
            for (int i = 0; s.count < 0 || i < s.count; ++i) {
                if (undo ? editor_.undo() : editor_.redo()) continue;
                if (s.count < 0) break;
                return Error(std::string("nothing to ") + (undo ? "undo" : "redo") + " (step " +
                             std::to_string(i + 1) + " of " + std::to_string(s.count) + ")");
            }
            return ok();
        }
        case ScriptOp::Grid:
            editor_.grid().step = s.number;
            editor_.grid().rotation_step = s.vec.x;
            return ok();
        case ScriptOp::Snap:
            editor_.grid().snap = s.count != 0;
            return ok();
        case ScriptOp::Lock:
        case ScriptOp::Unlock:
        case ScriptOp::Hide:
        case ScriptOp::Show:
            for (int id : s.ids) {
                if (!editor_.level().find(id)) return Error("no entity with id " + std::to_string(id));
                if (s.op == ScriptOp::Lock || s.op == ScriptOp::Unlock)
                    editor_.set_locked(id, s.op == ScriptOp::Lock);
                else
                    editor_.set_hidden(id, s.op == ScriptOp::Hide);
            }
            return ok();
        case ScriptOp::Begin:
            editor_.begin_transaction(s.text);
            return ok();
        case ScriptOp::Commit:
            if (!editor_.history().in_transaction()) return Error("commit without begin");
            editor_.commit_transaction();
            return ok();
        case ScriptOp::Cancel:
            if (!editor_.history().in_transaction()) return Error("cancel without begin");
            editor_.cancel_transaction();
            return ok();
        case ScriptOp::Fix:
            return fix(*rule_from_name(s.text));
        case ScriptOp::Recover:
            if (s.count) return editor_.accept_recovery();
            editor_.decline_recovery();
            return ok();
        case ScriptOp::ExpectCount: {
            int n = 0;
            for (const auto& e : editor_.level().entities) n += e.type() == s.type;
            return expect(n == s.count, std::string(level::type_name(s.type)) + " count is " +
                                            std::to_string(n) + ", expected " + std::to_string(s.count));
        }
        case ScriptOp::ExpectValid: {
            const auto& issues = editor_.issues();
            return expect(count_errors(issues) == 0, "the level has design errors:" + issue_list(issues));
        }
        case ScriptOp::ExpectIssue:
        case ScriptOp::ExpectNoIssue: {
            const Rule rule = *rule_from_name(s.text);
            std::vector<Issue> matching;
            for (const auto& i : editor_.issues())
                if (i.rule == rule && (s.count == 0 || i.entity_id == s.count)) matching.push_back(i);
            if (s.op == ScriptOp::ExpectIssue)
                return expect(!matching.empty(),
                              std::string("no ") + rule_name(rule) + " issue" +
                                  (s.count ? " for entity " + std::to_string(s.count) : "") +
                                  "; issues:" + issue_list(editor_.issues()));
            return expect(matching.empty(),
                          std::string("unexpected ") + rule_name(rule) + " issue:" + issue_list(matching));
        }
        case ScriptOp::ExpectSelected:
            return expect(static_cast<int>(editor_.doc().selection.size()) == s.count,
                          std::to_string(editor_.doc().selection.size()) + " selected, expected " +
                              std::to_string(s.count));
        case ScriptOp::ExpectField: {
            const level::Entity* e = editor_.level().find(s.count);
            if (!e) return Error("no entity with id " + std::to_string(s.count));
            auto actual = get_entity_field(*e, s.text);
            if (!actual) return actual.error();
            for (const auto& field : describe_entity_fields(*e)) {
                if (field.name != s.text) continue;
                auto wanted = parse_field_value(field, s.text2);
                if (!wanted) return wanted.error();
                return expect(*wanted == *actual, "entity " + std::to_string(s.count) + " " + s.text +
                                                      " is " + format_field_value(*actual) + ", expected " +
                                                      s.text2);
            }
            return Error("no field " + s.text);
        }
        case ScriptOp::ExpectDirty:
            return expect(editor_.has_unsaved_changes(), "the document is clean");
        case ScriptOp::ExpectClean:
            return expect(!editor_.has_unsaved_changes(), "the document has unsaved changes");
        }
        return ok();
    }

    // Applies every quick fix of one rule, re-validating after each (a fix may resolve other issues).
    Result<void> fix(Rule rule) {
        for (int guard = 0; guard < 10000; ++guard) {
            std::optional<Issue> next;
            for (const auto& i : editor_.issues())
                if (i.rule == rule && i.fix.kind != QuickFix::Kind::None) {
                    next = i;
                    break;
                }
            if (!next) return ok();
            if (auto r = editor_.apply_quick_fix(*next); !r) return r;
        }
        return Error(std::string("fix ") + rule_name(rule) + ": the fixes do not settle");
    }

    const Script& script_;
    Editor& editor_;
    ScriptReport report_;
};

} // namespace

Result<Script> parse_script(std::string_view text, const std::string& file_name) {
    Script script;
    script.file_name = file_name;
    std::vector<Error> errors;
    int line_no = 0;
    while (!text.empty() || line_no == 0) {
        ++line_no;
        size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        line = strip_comment(line);
        auto tokens = tokenize(line);
        if (tokens.empty()) {
            if (text.empty()) break;
            continue;
        }
        auto step = LineParser(line, std::move(tokens), line_no, file_name).parse();
        if (step)
            script.steps.push_back(std::move(*step));
        else
            errors.push_back(step.error());
        if (text.empty()) break;
    }
    if (!errors.empty()) return errors.size() == 1 ? errors.front() : combine_errors(errors);
    return script;
}

Result<ScriptReport> run_parsed_script(const Script& script, Editor& editor) {
    return Runner(script, editor).run();
}

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
