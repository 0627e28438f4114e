// The script language's runner: each parsed step applied to an Editor, expectations checked.
#include "model/campaign_add.h"
#include "model/script.h"
#include "model/script_dojo.h"
#include "model/script_logic.h"
#include "model/script_structure.h"
#include "model/script_tokens.h"

#include "core/log.h"
#include "level/campaign.h"

#include <optional>

namespace ks::editor {
namespace fs = std::filesystem;
namespace {
using script_tokens::rule_from_name;

// run_step sends each op to the function for its family; a family's `default` is never taken.
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
    Result<void> run_step(const ScriptStep& s) {
        switch (s.op) {
        case ScriptOp::New:
        case ScriptOp::Open:
        case ScriptOp::Save:
        case ScriptOp::SaveAs:
        case ScriptOp::Recover:
        case ScriptOp::CampaignAdd:
            return run_file_step(s);
        case ScriptOp::Select:
        case ScriptOp::SelectAll:
        case ScriptOp::SelectType:
        case ScriptOp::SelectNone:
        case ScriptOp::SelectBox:
            return run_selection_step(s);
        case ScriptOp::Place:
        case ScriptOp::Move:
        case ScriptOp::Nudge:
        case ScriptOp::Rotate:
        case ScriptOp::Scale:
        case ScriptOp::Delete:
        case ScriptOp::Duplicate:
        case ScriptOp::Copy:
        case ScriptOp::Paste:
            return run_entity_edit(s);
        case ScriptOp::Set:
        case ScriptOp::Reset:
        case ScriptOp::Setting:
        case ScriptOp::PlayerStart:
        case ScriptOp::LevelName:
        case ScriptOp::Fix:
            return run_field_edit(s);
        case ScriptOp::Patrol:
            return run_patrol_edit(s);
        case ScriptOp::Undo:
        case ScriptOp::Redo:
        case ScriptOp::Begin:
        case ScriptOp::Commit:
        case ScriptOp::Cancel:
            return run_history_step(s);
        case ScriptOp::Grid:
        case ScriptOp::Snap:
        case ScriptOp::Lock:
        case ScriptOp::Unlock:
        case ScriptOp::Hide:
        case ScriptOp::Show:
            return run_editing_aid(s);
        case ScriptOp::ExpectCount:
        case ScriptOp::ExpectValid:
        case ScriptOp::ExpectIssue:
        case ScriptOp::ExpectNoIssue:
        case ScriptOp::ExpectSelected:
        case ScriptOp::ExpectField:
        case ScriptOp::ExpectPatrol:
        case ScriptOp::ExpectDirty:
        case ScriptOp::ExpectClean:
        case ScriptOp::ExpectCampaign:
        case ScriptOp::ExpectPlayerStart:
            return run_expectation(s);
        case ScriptOp::Dojo:
            return run_dojo_step(s.dojo, dojo_, script_.base_dir, report_);
        case ScriptOp::Logic:
            return run_logic_step(s.logic, editor_, report_);
        case ScriptOp::Structure:
            return run_structure_step(s.structure, editor_, script_.base_dir, report_);
        }
        return ok();
    }

    // ---- files and recovery ---------------------------------------------------------------------------

    Result<void> run_file_step(const ScriptStep& s) {
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
        case ScriptOp::SaveAs:
            return save_as(s);
        case ScriptOp::Recover:
            if (s.count) return editor_.accept_recovery();
            editor_.decline_recovery();
            return ok();
        case ScriptOp::CampaignAdd: {
            auto added = add_to_campaign(editor_, resolve(s.text), s.text2);
            if (!added) return added.error();
            log::info(script_.file_name, ":", s.line, ": added ", added->file, " to ", s.text, " as level ",
                      added->position, " (\"", added->title, "\")");
            return ok();
        }
        default:
            break;
        }
        return ok();
    }

    Result<void> save_as(const ScriptStep& s) {
        SaveOptions options;
        options.overwrite_existing = s.count != 0;
        auto r = editor_.save_as(resolve(s.text), options);
        if (!r) return r.error();
        report_.saved.push_back(r->path);
        if (r->draft)
            log::warn(script_.file_name, ":", s.line, ": saved a draft with ", r->error_count, " error(s)");
        return ok();
    }

    fs::path resolve(const std::string& p) const {
        fs::path path(p);
        return path.is_absolute() || script_.base_dir.empty() ? path : script_.base_dir / path;
    }

    // ---- selection ------------------------------------------------------------------------------------

    Result<void> run_selection_step(const ScriptStep& s) {
        switch (s.op) {
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
        default:
            break;
        }
        return ok();
    }

    // ---- edits ----------------------------------------------------------------------------------------

    // Placing, transforming, deleting and copying entities.
    Result<void> run_entity_edit(const ScriptStep& s) {
        switch (s.op) {
        case ScriptOp::Place: {
            auto r = editor_.place(s.type, s.vec, s.number, s.text);
            if (!r) return r.error();
            return ok();
        }
        case ScriptOp::Move:
            return editor_.move_selection(s.vec, s.count != 0);
        case ScriptOp::Nudge:
            return editor_.nudge(s.count, static_cast<int>(s.number));
        case ScriptOp::Rotate:
            return editor_.rotate_selection_about(
                s.count, s.number, s.text == "local" ? RotationSpace::Local : RotationSpace::World);
        case ScriptOp::Scale:
            return editor_.scale_selection(s.vec);
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
        default:
            break;
        }
        return ok();
    }

    // Entity fields, level settings and quick fixes.
    Result<void> run_field_edit(const ScriptStep& s) {
        switch (s.op) {
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
        case ScriptOp::Fix:
            return fix(*rule_from_name(s.text));
        default:
            break;
        }
        return ok();
    }

    // A robot's patrol route (the parser checked the action's words).
    Result<void> run_patrol_edit(const ScriptStep& s) {
        const int id = s.ids.front();
        if (s.text == "add")
            return editor_.patrol_add(id, s.vec, s.has_number ? std::optional<int>(s.count) : std::nullopt);
        if (s.text == "move") return editor_.patrol_move(id, s.count, s.vec);
        if (s.text == "remove") return editor_.patrol_remove(id, s.count);
        if (s.text == "mode") return editor_.patrol_set_mode(id, s.text2);
        return editor_.patrol_set_wait(id, s.number);
    }

    // Applies every quick fix of one rule, re-validating after each (a fix may resolve other issues).
    Result<void> fix(Rule rule) {
        for (int guard = 0; guard < 10000; ++guard) {
            std::optional<Issue> next;
            for (const auto& i : editor_.issues())
                if (i.rule == rule && i.fix.available()) {
                    next = i;
                    break;
                }
            if (!next) return ok();
            if (auto r = editor_.apply_quick_fix(*next); !r) return r;
        }
        return Error(std::string("fix ") + rule_name(rule) + ": the fixes do not settle");
    }

    // ---- history --------------------------------------------------------------------------------------

    Result<void> run_history_step(const ScriptStep& s) {
        switch (s.op) {
        case ScriptOp::Undo:
        case ScriptOp::Redo:
            return undo_or_redo(s);
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
        default:
            break;
        }
        return ok();
    }

    // count < 0 means "all": stop quietly when history runs out.
    Result<void> undo_or_redo(const ScriptStep& s) {
        const bool undo = s.op == ScriptOp::Undo;
        for (int i = 0; s.count < 0 || i < s.count; ++i) {
            if (undo ? editor_.undo() : editor_.redo()) continue;
            if (s.count < 0) break;
            return Error(std::string("nothing to ") + (undo ? "undo" : "redo") + " (step " +
                         std::to_string(i + 1) + " of " + std::to_string(s.count) + ")");
        }
        return ok();
    }

    // ---- editing aids: grid, snapping, locking and hiding ---------------------------------------------

    Result<void> run_editing_aid(const ScriptStep& s) {
        switch (s.op) {
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
            return set_lock_or_visibility(s);
        default:
            break;
        }
        return ok();
    }

    Result<void> set_lock_or_visibility(const ScriptStep& s) {
        for (int id : s.ids) {
            if (!editor_.level().find(id)) return Error("no entity with id " + std::to_string(id));
            auto done = s.op == ScriptOp::Lock || s.op == ScriptOp::Unlock
                            ? editor_.set_locked(id, s.op == ScriptOp::Lock)
                            : editor_.set_hidden(id, s.op == ScriptOp::Hide);
            if (!done) return done;
        }
        return ok();
    }

    // ---- expectations ---------------------------------------------------------------------------------

    Result<void> run_expectation(const ScriptStep& s) {
        switch (s.op) {
        case ScriptOp::ExpectCount:
            return expect_count(s);
        case ScriptOp::ExpectValid: {
            const auto& issues = editor_.issues();
            return expect(count_errors(issues) == 0, "the level has design errors:" + issue_list(issues));
        }
        case ScriptOp::ExpectIssue:
        case ScriptOp::ExpectNoIssue:
            return expect_issue(s);
        case ScriptOp::ExpectSelected:
            return expect(static_cast<int>(editor_.doc().selection.size()) == s.count,
                          std::to_string(editor_.doc().selection.size()) + " selected, expected " +
                              std::to_string(s.count));
        case ScriptOp::ExpectField:
            return expect_field(s);
        case ScriptOp::ExpectPatrol:
            return expect_patrol(s);
        case ScriptOp::ExpectDirty:
            return expect(editor_.has_unsaved_changes(), "the document is clean");
        case ScriptOp::ExpectClean:
            return expect(!editor_.has_unsaved_changes(), "the document has unsaved changes");
        case ScriptOp::ExpectCampaign: {
            auto campaign = level::load_campaign(resolve(s.text));
            if (!campaign) return campaign.error();
            const int n = static_cast<int>(campaign->levels.size());
            return expect(n == s.count, s.text + " lists " + std::to_string(n) + " level(s), expected " +
                                            std::to_string(s.count));
        }
        case ScriptOp::ExpectPlayerStart:
            return expect_player_start(s);
        default:
            break;
        }
        return ok();
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

    Result<void> expect_count(const ScriptStep& s) {
        int n = 0;
        for (const auto& e : editor_.level().entities) n += e.type() == s.type;
        return expect(n == s.count, std::string(level::type_name(s.type)) + " count is " + std::to_string(n) +
                                        ", expected " + std::to_string(s.count));
    }

    // count is the entity the issue must be about, or 0 for any.
    Result<void> expect_issue(const ScriptStep& s) {
        const Rule rule = *rule_from_name(s.text);
        std::vector<Issue> matching;
        for (const auto& i : editor_.issues())
            if (i.rule == rule && (s.count == 0 || i.entity_id == s.count)) matching.push_back(i);
        if (s.op == ScriptOp::ExpectIssue)
            return expect(!matching.empty(), std::string("no ") + rule_name(rule) + " issue" +
                                                 (s.count ? " for entity " + std::to_string(s.count) : "") +
                                                 "; issues:" + issue_list(editor_.issues()));
        return expect(matching.empty(),
                      std::string("unexpected ") + rule_name(rule) + " issue:" + issue_list(matching));
    }

    // Compared as values of the field's type, not as text, so a script need not spell a value the way the
    // formatter does.
    Result<void> expect_field(const ScriptStep& s) {
        const level::Entity* e = editor_.level().find(s.count);
        if (!e) return Error("no entity with id " + std::to_string(s.count));
        auto actual = get_entity_field(*e, s.text);
        if (!actual) return actual.error();
        for (const auto& field : describe_entity_fields(*e)) {
            if (field.name != s.text) continue;
            auto wanted = parse_field_value(field, s.text2);
            if (!wanted) return wanted.error();
            return expect(*wanted == *actual, "entity " + std::to_string(s.count) + " " + s.text + " is " +
                                                  format_field_value(*actual) + ", expected " + s.text2);
        }
        return Error("no field " + s.text);
    }

    // Within a ten-thousandth: positions and angles that went through a turn carry float rounding.
    Result<void> expect_player_start(const ScriptStep& s) {
        const level::PlayerStart& start = editor_.level().player_start;
        const bool at = glm::all(glm::lessThanEqual(glm::abs(start.position - s.vec), Vec3(1e-4f)));
        const bool facing = !s.has_number || std::abs(start.yaw - s.number) <= 1e-4f;
        const auto text = [](const Vec3& p, float yaw) {
            return format_field_value(p) + " yaw " + format_field_value(static_cast<double>(yaw));
        };
        return expect(at && facing, "the player start is at " + text(start.position, start.yaw) +
                                        ", expected " + text(s.vec, s.has_number ? s.number : start.yaw));
    }

    Result<void> expect_patrol(const ScriptStep& s) {
        const level::Entity* e = editor_.level().find(s.ids.front());
        if (!e) return Error("no entity with id " + std::to_string(s.ids.front()));
        const auto* robot = e->try_as<level::RobotProps>();
        if (!robot) return Error("entity " + std::to_string(e->id) + " is not a robot");
        const size_t n = robot->patrol.points.size();
        return expect(n == static_cast<size_t>(s.count), "robot " + std::to_string(e->id) + " has " +
                                                             std::to_string(n) + " patrol points, expected " +
                                                             std::to_string(s.count));
    }

    const Script& script_;
    Editor& editor_;
    DojoDocument dojo_; // the clip file the dojo lines edit (`dojo open`)
    ScriptReport report_;
};

} // namespace

Result<ScriptReport> run_parsed_script(const Script& script, Editor& editor) {
    return Runner(script, editor).run();
}

} // namespace ks::editor
