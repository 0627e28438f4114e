// The script language's parser: every line to a ScriptStep, or an error at the offending word.
#include "model/script.h"
#include "model/script_dojo.h"
#include "model/script_logic.h"
#include "model/script_structure.h"
#include "model/script_tokens.h"

namespace ks::editor {
namespace {
using namespace script_tokens;

// Parses one line's tokens into a step; errors carry the column of the offending token.
class LineParser {
  public:
    LineParser(std::string_view line, std::vector<Token> tokens, int line_no, const std::string& file)
        : line_(line), tokens_(std::move(tokens)), line_no_(line_no), file_(file) {}

    Result<ScriptStep> parse() {
        // Each command's parser gets the op it produces (select, save and expect choose among several) and
        // the usage shown when the words do not fit (null where the parser builds its hint from the word).
        using CommandParser = Result<ScriptStep> (LineParser::*)(ScriptOp op, const char* usage);
        struct Command {
            std::string_view word;
            ScriptOp op;
            CommandParser parse;
            const char* usage;
        };
        static constexpr Command kCommands[] = {
            {"new", ScriptOp::New, &LineParser::no_arguments, nullptr},
            {"open", ScriptOp::Open, &LineParser::path_argument, nullptr},
            {"save", ScriptOp::Save, &LineParser::save, "save PATH [overwrite]"},
            {"place", ScriptOp::Place, &LineParser::place, "place TYPE at X,Y,Z [yaw D] [name TEXT]"},
            {"select", ScriptOp::Select, &LineParser::select,
             "select [add|toggle|remove] ID|player_start... | select all [TYPE] | select none | select box "
             "X,Y,Z X,Y,Z"},
            {"move", ScriptOp::Move, &LineParser::move, "move DX,DY,DZ [snap]"},
            {"nudge", ScriptOp::Nudge, &LineParser::nudge, "nudge +x|-x|+y|-y|+z|-z"},
            {"rotate", ScriptOp::Rotate, &LineParser::rotate, "rotate [x|y|z] DEGREES [world|local]"},
            {"scale", ScriptOp::Scale, &LineParser::scale, "scale S or scale SX,SY,SZ"},
            {"set", ScriptOp::Set, &LineParser::field_and_value, "set FIELD VALUE"},
            {"setting", ScriptOp::Setting, &LineParser::field_and_value, "setting FIELD VALUE"},
            {"reset", ScriptOp::Reset, &LineParser::word_argument, "reset FIELD"},
            {"player_start", ScriptOp::PlayerStart, &LineParser::player_start, "player_start X,Y,Z [yaw D]"},
            {"level_name", ScriptOp::LevelName, &LineParser::rest_of_line, "level_name Two Rooms"},
            {"delete", ScriptOp::Delete, &LineParser::no_arguments, nullptr},
            {"duplicate", ScriptOp::Duplicate, &LineParser::duplicate, "duplicate [DX,DY,DZ]"},
            {"copy", ScriptOp::Copy, &LineParser::no_arguments, nullptr},
            {"paste", ScriptOp::Paste, &LineParser::no_arguments, nullptr},
            {"undo", ScriptOp::Undo, &LineParser::step_count, "undo [N|all]"},
            {"redo", ScriptOp::Redo, &LineParser::step_count, "redo [N|all]"},
            {"grid", ScriptOp::Grid, &LineParser::grid, "grid STEP [ROTATION_STEP]"},
            {"snap", ScriptOp::Snap, &LineParser::snap, "snap on|off"},
            {"lock", ScriptOp::Lock, &LineParser::ids_argument, "lock ID..."},
            {"unlock", ScriptOp::Unlock, &LineParser::ids_argument, "unlock ID..."},
            {"hide", ScriptOp::Hide, &LineParser::ids_argument, "hide ID..."},
            {"show", ScriptOp::Show, &LineParser::ids_argument, "show ID..."},
            {"begin", ScriptOp::Begin, &LineParser::begin, nullptr},
            {"commit", ScriptOp::Commit, &LineParser::no_arguments, nullptr},
            {"cancel", ScriptOp::Cancel, &LineParser::no_arguments, nullptr},
            {"fix", ScriptOp::Fix, &LineParser::fix, "fix RULE"},
            {"patrol", ScriptOp::Patrol, &LineParser::patrol,
             "patrol ID add X,Y,Z [after INDEX] | patrol ID move INDEX X,Y,Z | patrol ID remove INDEX | "
             "patrol ID mode loop|ping_pong | patrol ID wait SECONDS"},
            {"recover", ScriptOp::Recover, &LineParser::recover, "recover accept|decline"},
            {"campaign", ScriptOp::CampaignAdd, &LineParser::campaign_add,
             "campaign add FILE [title TEXT...]"},
            {"expect", ScriptOp::ExpectValid, &LineParser::expect,
             "expect count TYPE N | valid | issue RULE [ID] | no_issue RULE | selected N | "
             "field ID FIELD VALUE | patrol ID POINTS | player_start X,Y,Z [yaw D] | dirty | clean | "
             "campaign "
             "FILE N; level logic: expect links | link | "
             "objectives ...; clip files: expect clip | blend | events | event | key | curve | dojo ..."},
        };
        step_.line = line_no_;
        const std::string_view word = tokens_[0].text;
        if (is_dojo_command(word) ||
            (word == "expect" && tokens_.size() > 1 && is_dojo_expectation(tokens_[1].text)))
            return parse_dojo_line(line_, tokens_, line_no_, file_);
        if (is_structure_command(word) ||
            (word == "expect" && tokens_.size() > 1 && is_structure_expectation(tokens_[1].text)))
            return parse_structure_line(line_, tokens_, line_no_, file_);
        if (is_logic_command(word) ||
            (word == "expect" && tokens_.size() > 1 && is_logic_expectation(tokens_[1].text)))
            return parse_logic_line(line_, tokens_, line_no_, file_);
        for (const Command& command : kCommands)
            if (word == command.word) return (this->*command.parse)(command.op, command.usage);
        return fail(
            0, "unknown command '" + std::string(word) + "'",
            "commands: new open save place select move nudge rotate scale set reset setting player_start "
            "level_name delete duplicate copy paste undo redo grid snap lock unlock hide show begin commit "
            "cancel fix patrol recover campaign expect; groups, layers, prefabs: group ungroup enter exit "
            "pick "
            "layer prefab; level logic: name link objective; clip files: dojo "
            "clip blend "
            "event key");
    }

  private:
    // ---- helpers --------------------------------------------------------------------------------------

    Error fail(size_t token, std::string message, std::string hint) const {
        return error_at(tokens_, line_, token, file_, line_no_, std::move(message), std::move(hint));
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
    Result<ScriptStep> entity_type(size_t token) {
        if (token >= tokens_.size()) return fail(token, "expected an entity type", "types: " + type_names());
        if (!level::type_from_name(tokens_[token].text, step_.type))
            return fail(token, "unknown entity type '" + std::string(tokens_[token].text) + "'",
                        "types: " + type_names());
        return step_;
    }
    // With `player_start`, the word player_start stands for the player start (kPlayerStartId).
    Result<ScriptStep> ids_from(ScriptOp op, const char* usage, size_t first, bool player_start = false) {
        step_.op = op;
        if (tokens_.size() <= first) return fail(first, "expected entity ids", usage);
        for (size_t i = first; i < tokens_.size(); ++i) {
            if (player_start && tokens_[i].text == "player_start") {
                step_.ids.push_back(kPlayerStartId);
                continue;
            }
            int id = 0;
            if (!to_int(tokens_[i].text, id) || id < 1)
                return fail(i, "expected an entity id (a positive whole number)", usage);
            step_.ids.push_back(id);
        }
        return step_;
    }
    // A two-word command ("select none", "expect valid") that takes nothing more.
    Result<ScriptStep> nothing_after(ScriptOp op, size_t words) {
        step_.op = op;
        if (tokens_.size() > words)
            return fail(words, "unexpected '" + std::string(tokens_[words].text) + "'", "");
        return step_;
    }

    // ---- commands that share a shape ------------------------------------------------------------------

    Result<ScriptStep> no_arguments(ScriptOp op, const char*) {
        step_.op = op;
        if (tokens_.size() > 1)
            return fail(1, "unexpected '" + std::string(tokens_[1].text) + "'",
                        std::string(tokens_[0].text) + " takes no arguments");
        return step_;
    }
    Result<ScriptStep> path_argument(ScriptOp op, const char*) {
        step_.op = op;
        if (tokens_.size() < 2)
            return fail(1, "expected a file path", std::string(tokens_[0].text) + " levels/x.json");
        step_.text = rest(1);
        return step_;
    }
    Result<ScriptStep> word_argument(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        step_.text = std::string(tokens_[1].text);
        return step_;
    }
    Result<ScriptStep> number_argument(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        if (!to_float(tokens_[1].text, step_.number)) return fail(1, "expected a number", usage);
        return step_;
    }
    Result<ScriptStep> ids_argument(ScriptOp op, const char* usage) { return ids_from(op, usage, 1); }
    Result<ScriptStep> field_and_value(ScriptOp op, const char* usage) {
        step_.op = op;
        if (tokens_.size() < 3) return fail(0, "expected a field and a value", usage);
        step_.text = std::string(tokens_[1].text);
        step_.text2 = rest(2);
        return step_;
    }
    Result<ScriptStep> rest_of_line(ScriptOp op, const char* usage) {
        step_.op = op;
        if (tokens_.size() < 2) return fail(0, "expected a name", usage);
        step_.text = rest(1);
        return step_;
    }
    Result<ScriptStep> step_count(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(1, 2, usage); !r) return r.error();
        step_.count = 1;
        if (tokens_.size() == 2) {
            const std::string word(tokens_[0].text);
            if (tokens_[1].text == "all")
                step_.count = -1;
            else if (!to_int(tokens_[1].text, step_.count) || step_.count < 1)
                return fail(1, "expected a count of steps", word + " 3, or " + word + " all");
        }
        return step_;
    }

    // ---- files and recovery ---------------------------------------------------------------------------

    Result<ScriptStep> save(ScriptOp op, const char* usage) {
        if (tokens_.size() == 1) return no_arguments(op, usage);
        if (tokens_.size() == 3 && tokens_[2].text != "overwrite")
            return fail(2, "unexpected '" + std::string(tokens_[2].text) + "'", usage);
        if (tokens_.size() > 3) return fail(3, "too many words", usage);
        step_.op = ScriptOp::SaveAs;
        step_.text = std::string(tokens_[1].text);
        step_.count = tokens_.size() == 3;
        return step_;
    }
    Result<ScriptStep> recover(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        if (tokens_[1].text != "accept" && tokens_[1].text != "decline")
            return fail(1, "expected accept or decline", "recover accept");
        step_.count = tokens_[1].text == "accept";
        return step_;
    }

    // campaign add FILE [title TEXT...]: text is the campaign file, text2 the title (empty: the level's
    // name).
    Result<ScriptStep> campaign_add(ScriptOp op, const char* usage) {
        step_.op = op;
        if (tokens_.size() < 2 || tokens_[1].text != "add") return fail(1, "expected 'add'", usage);
        if (tokens_.size() < 3) return fail(2, "expected the campaign file", usage);
        if (tokens_.size() > 3 && tokens_[3].text != "title")
            return fail(3, "unexpected '" + std::string(tokens_[3].text) + "'", usage);
        if (tokens_.size() == 4) return fail(4, "expected the title after 'title'", usage);
        step_.text = std::string(tokens_[2].text);
        if (tokens_.size() > 4) step_.text2 = rest(4);
        return step_;
    }

    // ---- placing and selecting ------------------------------------------------------------------------

    Result<ScriptStep> place(ScriptOp op, const char* usage) {
        step_.op = op;
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
    Result<ScriptStep> select(ScriptOp op, const char* usage) {
        if (tokens_.size() < 2) return fail(1, "missing words", usage);
        const std::string_view w = tokens_[1].text;
        if (w == "none") return nothing_after(ScriptOp::SelectNone, 2);
        if (w == "all") {
            if (tokens_.size() == 2) return nothing_after(ScriptOp::SelectAll, 2);
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
        return ids_from(op, usage, first, true);
    }

    // ---- transforms -----------------------------------------------------------------------------------

    Result<ScriptStep> move(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 3, usage); !r) return r.error();
        if (auto r = vec(1, step_.vec); !r) return r.error();
        if (tokens_.size() == 3 && tokens_[2].text != "snap") return fail(2, "expected 'snap'", usage);
        step_.count = tokens_.size() == 3;
        return step_;
    }
    // count: the axis (0 x, 1 y, 2 z; y when none is given), number: degrees, text: "world" or "local".
    Result<ScriptStep> rotate(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 4, usage); !r) return r.error();
        size_t i = 1;
        step_.count = 1;
        if (const std::string_view w = tokens_[1].text; w == "x" || w == "y" || w == "z") {
            step_.count = w[0] - 'x';
            ++i;
        }
        if (i >= tokens_.size() || !to_float(tokens_[i].text, step_.number))
            return fail(i, "expected the angle in degrees", usage);
        step_.text = "world";
        if (++i < tokens_.size()) {
            if (tokens_[i].text != "world" && tokens_[i].text != "local")
                return fail(i, "expected world or local", usage);
            step_.text = std::string(tokens_[i].text);
            ++i;
        }
        if (i < tokens_.size()) return fail(i, "unexpected '" + std::string(tokens_[i].text) + "'", usage);
        return step_;
    }
    Result<ScriptStep> nudge(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        const std::string_view d = tokens_[1].text;
        if (d.size() != 2 || (d[0] != '+' && d[0] != '-') || d[1] < 'x' || d[1] > 'z')
            return fail(1, "expected a direction like +x or -z", usage);
        step_.count = d[1] - 'x';
        step_.number = d[0] == '+' ? 1.0f : -1.0f;
        return step_;
    }
    Result<ScriptStep> scale(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        float s = 0;
        if (to_float(tokens_[1].text, s))
            step_.vec = Vec3(s);
        else if (auto r = vec(1, step_.vec); !r)
            return r.error();
        return step_;
    }
    Result<ScriptStep> duplicate(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(1, 2, usage); !r) return r.error();
        if (tokens_.size() == 2) {
            if (auto r = vec(1, step_.vec); !r) return r.error();
            step_.has_vec = true;
        }
        return step_;
    }

    // ---- level settings, editing aids and transactions ------------------------------------------------

    Result<ScriptStep> player_start(ScriptOp op, const char* usage) {
        step_.op = op;
        if (tokens_.size() != 2 && tokens_.size() != 4) return fail(0, "wrong number of words", usage);
        if (auto r = vec(1, step_.vec); !r) return r.error();
        if (tokens_.size() == 4) {
            if (tokens_[2].text != "yaw") return fail(2, "expected 'yaw'", usage);
            if (!to_float(tokens_[3].text, step_.number)) return fail(3, "expected degrees", "yaw 90");
        }
        return step_;
    }
    Result<ScriptStep> grid(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 3, usage); !r) return r.error();
        if (!to_float(tokens_[1].text, step_.number) || step_.number <= 0)
            return fail(1, "expected a positive grid step", "grid 0.5");
        step_.vec.x = 15.0f;
        if (tokens_.size() == 3 && (!to_float(tokens_[2].text, step_.vec.x) || step_.vec.x <= 0))
            return fail(2, "expected a positive rotation step in degrees", "grid 1 15");
        return step_;
    }
    Result<ScriptStep> snap(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        if (tokens_[1].text != "on" && tokens_[1].text != "off")
            return fail(1, "expected on or off", "snap off");
        step_.count = tokens_[1].text == "on";
        return step_;
    }
    Result<ScriptStep> begin(ScriptOp op, const char*) {
        step_.op = op;
        step_.text = tokens_.size() > 1 ? rest(1) : "Script transaction";
        return step_;
    }
    Result<ScriptStep> fix(ScriptOp op, const char* usage) {
        step_.op = op;
        if (auto r = need(2, 2, usage); !r) return r.error();
        if (!rule_from_name(tokens_[1].text)) return fail(1, "unknown rule", "rules: " + rule_names());
        step_.text = std::string(tokens_[1].text);
        return step_;
    }

    // ---- robot patrols: ids[0] is the robot, text the action, count the point index, vec the point;
    // for add, has_number says an "after INDEX" was given (in count) ---------------------------------------

    Result<ScriptStep> patrol(ScriptOp op, const char* usage) {
        step_.op = op;
        if (tokens_.size() < 3) return fail(tokens_.size(), "missing words", usage);
        if (!to_int(tokens_[1].text, step_.count) || step_.count < 1)
            return fail(1, "expected the robot's id", usage);
        step_.ids = {step_.count};
        step_.count = 0;
        const std::string_view action = tokens_[2].text;
        step_.text = std::string(action);
        if (action == "add") {
            if (tokens_.size() != 4 && tokens_.size() != 6)
                return fail(tokens_.size(), "wrong number of words", usage);
            if (auto r = vec(3, step_.vec); !r) return r.error();
            if (tokens_.size() == 6) {
                if (tokens_[4].text != "after") return fail(4, "expected 'after'", usage);
                if (!to_int(tokens_[5].text, step_.count) || step_.count < -1)
                    return fail(5, "expected a point index (-1 puts the point first)", usage);
                step_.has_number = true;
            }
            return step_;
        }
        if (action == "move" || action == "remove") {
            if (auto r = need(action == "move" ? 5 : 4, action == "move" ? 5 : 4, usage); !r)
                return r.error();
            if (!to_int(tokens_[3].text, step_.count) || step_.count < 0)
                return fail(3, "expected a point index (0 is the first)", usage);
            if (action == "move")
                if (auto r = vec(4, step_.vec); !r) return r.error();
            return step_;
        }
        if (action == "mode") {
            if (auto r = need(4, 4, usage); !r) return r.error();
            step_.text2 = std::string(tokens_[3].text);
            if (step_.text2 != "loop" && step_.text2 != "ping_pong")
                return fail(3, "unknown patrol mode '" + step_.text2 + "'", "modes: loop, ping_pong");
            return step_;
        }
        if (action == "wait") {
            if (auto r = need(4, 4, usage); !r) return r.error();
            if (!to_float(tokens_[3].text, step_.number) || step_.number < 0)
                return fail(3, "expected seconds (0 or more)", usage);
            return step_;
        }
        return fail(2, "unknown patrol action '" + step_.text + "'",
                    "actions: add, move, remove, mode, wait");
    }

    // ---- expectations ---------------------------------------------------------------------------------

    Result<ScriptStep> expect(ScriptOp, const char* usage) {
        if (tokens_.size() < 2) return fail(1, "missing words", usage);
        const std::string_view w = tokens_[1].text;
        if (w == "valid") return nothing_after(ScriptOp::ExpectValid, 2);
        if (w == "dirty") return nothing_after(ScriptOp::ExpectDirty, 2);
        if (w == "clean") return nothing_after(ScriptOp::ExpectClean, 2);
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
        if (w == "issue" || w == "no_issue") return expect_issue(w == "issue", usage);
        if (w == "player_start") {
            step_.op = ScriptOp::ExpectPlayerStart;
            if (tokens_.size() != 3 && tokens_.size() != 5)
                return fail(tokens_.size(), "wrong number of words", usage);
            if (auto r = vec(2, step_.vec); !r) return r.error();
            if (tokens_.size() == 5) {
                if (tokens_[3].text != "yaw") return fail(3, "expected 'yaw'", usage);
                if (!to_float(tokens_[4].text, step_.number)) return fail(4, "expected degrees", "yaw 90");
                step_.has_number = true;
            }
            return step_;
        }
        if (w == "patrol") {
            step_.op = ScriptOp::ExpectPatrol;
            if (auto r = need(4, 4, usage); !r) return r.error();
            int id = 0;
            if (!to_int(tokens_[2].text, id) || id < 1) return fail(2, "expected an entity id", usage);
            step_.ids = {id};
            if (!to_int(tokens_[3].text, step_.count) || step_.count < 0)
                return fail(3, "expected a count of points", usage);
            return step_;
        }
        if (w == "campaign") {
            step_.op = ScriptOp::ExpectCampaign;
            if (auto r = need(4, 4, usage); !r) return r.error();
            step_.text = std::string(tokens_[2].text);
            if (!to_int(tokens_[3].text, step_.count) || step_.count < 0)
                return fail(3, "expected a count of levels", usage);
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
    Result<ScriptStep> expect_issue(bool wanted, const char* usage) {
        step_.op = wanted ? ScriptOp::ExpectIssue : ScriptOp::ExpectNoIssue;
        if (auto r = need(3, wanted ? 4 : 3, usage); !r) return r.error();
        if (!rule_from_name(tokens_[2].text)) return fail(2, "unknown rule", "rules: " + rule_names());
        step_.text = std::string(tokens_[2].text);
        if (tokens_.size() == 4) {
            if (!to_int(tokens_[3].text, step_.count) || step_.count < 1)
                return fail(3, "expected an entity id", usage);
        }
        return step_;
    }

    std::string_view line_;
    std::vector<Token> tokens_;
    int line_no_;
    const std::string& file_;
    ScriptStep step_;
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

} // namespace ks::editor
