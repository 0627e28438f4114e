// The script language's level commands for files, selection and entity edits (script_level.h): each
// command's parser, its steps' `run`, and the table entry that registers it (script_command.h).
#include "model/campaign_add.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/script_level_words.h"

#include "core/log.h"

namespace ks::editor {
namespace {
using namespace script_tokens;
using namespace level_words;
using steps::Select;

// ---- files and recovery -------------------------------------------------------------------------------

constexpr const char* kSaveUsage = "save PATH [overwrite]";
constexpr const char* kCampaignUsage = "campaign add FILE [title TEXT...]";

Result<ScriptStep> parse_open(const LineWords& w) {
    if (w.size() < 2) return w.fail(1, "expected a file path", w.word(0) + " levels/x.json");
    return level_step(steps::Open{w.rest(1)});
}

Result<ScriptStep> parse_save(const LineWords& w) {
    if (w.size() == 1) return level_step(steps::Save{});
    if (w.size() == 3 && w.text(2) != "overwrite")
        return w.fail(2, "unexpected '" + w.word(2) + "'", kSaveUsage);
    if (w.size() > 3) return w.fail(3, "too many words", kSaveUsage);
    return level_step(steps::SaveAs{w.word(1), w.size() == 3});
}

Result<ScriptStep> parse_recover(const LineWords& w) {
    if (auto r = w.need(2, 2, "recover accept|decline"); !r) return r.error();
    if (w.text(1) != "accept" && w.text(1) != "decline")
        return w.fail(1, "expected accept or decline", "recover accept");
    return level_step(steps::Recover{w.text(1) == "accept"});
}

Result<ScriptStep> parse_campaign(const LineWords& w) {
    if (w.size() < 2 || w.text(1) != "add") return w.fail(1, "expected 'add'", kCampaignUsage);
    if (w.size() < 3) return w.fail(2, "expected the campaign file", kCampaignUsage);
    if (w.size() > 3 && w.text(3) != "title")
        return w.fail(3, "unexpected '" + w.word(3) + "'", kCampaignUsage);
    if (w.size() == 4) return w.fail(4, "expected the title after 'title'", kCampaignUsage);
    return level_step(steps::CampaignAdd{w.word(2), w.size() > 4 ? w.rest(4) : std::string()});
}

// ---- placing and selecting ----------------------------------------------------------------------------

constexpr const char* kPlaceUsage = "place TYPE at X,Y,Z [yaw D] [name TEXT]";
constexpr const char* kSelectUsage = "select [add|toggle|remove] ID|player_start... | select all [TYPE] | "
                                     "select none | select box X,Y,Z X,Y,Z";

Result<ScriptStep> parse_place(const LineWords& w) {
    steps::Place step;
    if (w.size() < 4) return w.fail(w.size(), "missing words", kPlaceUsage);
    if (auto r = entity_type(w, 1, step.type); !r) return r.error();
    if (w.text(2) != "at") return w.fail(2, "expected 'at'", kPlaceUsage);
    if (auto r = w.vec(3, step.position); !r) return r.error();
    size_t i = 4;
    if (i < w.size() && w.text(i) == "yaw") {
        if (i + 1 >= w.size() || !to_float(w.text(i + 1), step.yaw))
            return w.fail(i + 1, "expected degrees after 'yaw'", kPlaceUsage);
        i += 2;
    }
    if (i < w.size()) {
        if (w.text(i) != "name" || i + 1 >= w.size())
            return w.fail(i, "expected 'yaw D' or 'name TEXT'", kPlaceUsage);
        step.name = w.rest(i + 1);
    }
    return level_step(std::move(step));
}

Result<ScriptStep> parse_select(const LineWords& w) {
    if (w.size() < 2) return w.fail(1, "missing words", kSelectUsage);
    const std::string_view word = w.text(1);
    if (word == "none") return nothing_after(w, 2, steps::SelectNone{});
    if (word == "all") {
        if (w.size() == 2) return nothing_after(w, 2, steps::SelectAll{});
        steps::SelectType step;
        if (auto r = w.need(3, 3, kSelectUsage); !r) return r.error();
        if (auto r = entity_type(w, 2, step.type); !r) return r.error();
        return level_step(step);
    }
    if (word == "box") {
        steps::SelectBox step;
        if (auto r = w.need(4, 4, kSelectUsage); !r) return r.error();
        if (auto r = w.vec(2, step.a); !r) return r.error();
        if (auto r = w.vec(3, step.b); !r) return r.error();
        return level_step(step);
    }
    Select step;
    size_t first = 1;
    if (word == "add")
        step.mode = SelectMode::Add, first = 2;
    else if (word == "toggle")
        step.mode = SelectMode::Toggle, first = 2;
    else if (word == "remove")
        step.mode = SelectMode::Remove, first = 2;
    if (auto r = ids_from(w, kSelectUsage, first, step.ids, true); !r) return r.error();
    return level_step(std::move(step));
}

// ---- transforms ---------------------------------------------------------------------------------------

constexpr const char* kMoveUsage = "move DX,DY,DZ [snap]";
constexpr const char* kRotateUsage = "rotate [x|y|z] DEGREES [world|local]";
constexpr const char* kNudgeUsage = "nudge +x|-x|+y|-y|+z|-z";
constexpr const char* kScaleUsage = "scale S or scale SX,SY,SZ";
constexpr const char* kDuplicateUsage = "duplicate [DX,DY,DZ]";

Result<ScriptStep> parse_move(const LineWords& w) {
    steps::Move step;
    if (auto r = w.need(2, 3, kMoveUsage); !r) return r.error();
    if (auto r = w.vec(1, step.delta); !r) return r.error();
    if (w.size() == 3 && w.text(2) != "snap") return w.fail(2, "expected 'snap'", kMoveUsage);
    step.snap = w.size() == 3;
    return level_step(step);
}

Result<ScriptStep> parse_rotate(const LineWords& w) {
    steps::Rotate step;
    if (auto r = w.need(2, 4, kRotateUsage); !r) return r.error();
    size_t i = 1;
    if (const std::string_view a = w.text(1); a == "x" || a == "y" || a == "z") {
        step.axis = a[0] - 'x';
        ++i;
    }
    if (i >= w.size() || !to_float(w.text(i), step.degrees))
        return w.fail(i, "expected the angle in degrees", kRotateUsage);
    if (++i < w.size()) {
        if (w.text(i) != "world" && w.text(i) != "local")
            return w.fail(i, "expected world or local", kRotateUsage);
        step.space = w.text(i) == "local" ? RotationSpace::Local : RotationSpace::World;
        ++i;
    }
    if (i < w.size()) return w.fail(i, "unexpected '" + w.word(i) + "'", kRotateUsage);
    return level_step(step);
}

Result<ScriptStep> parse_nudge(const LineWords& w) {
    if (auto r = w.need(2, 2, kNudgeUsage); !r) return r.error();
    const std::string_view d = w.text(1);
    if (d.size() != 2 || (d[0] != '+' && d[0] != '-') || d[1] < 'x' || d[1] > 'z')
        return w.fail(1, "expected a direction like +x or -z", kNudgeUsage);
    return level_step(steps::Nudge{d[1] - 'x', d[0] == '+' ? 1 : -1});
}

Result<ScriptStep> parse_scale(const LineWords& w) {
    steps::Scale step;
    if (auto r = w.need(2, 2, kScaleUsage); !r) return r.error();
    float s = 0;
    if (to_float(w.text(1), s))
        step.factors = Vec3(s);
    else if (auto r = w.vec(1, step.factors); !r)
        return r.error();
    return level_step(step);
}

Result<ScriptStep> parse_duplicate(const LineWords& w) {
    steps::Duplicate step;
    if (auto r = w.need(1, 2, kDuplicateUsage); !r) return r.error();
    if (w.size() == 2) {
        Vec3 offset{0.0f};
        if (auto r = w.vec(1, offset); !r) return r.error();
        step.offset = offset;
    }
    return level_step(step);
}

// An edit's result without its value.
Result<void> done(const auto& r) {
    if (!r) return r.error();
    return ok();
}

constexpr CommandSpec kCommands[] = {
    {"new", false, "new", "a new, untitled level (File > New)", no_arguments<steps::New>},
    {"open", false, "open PATH", "open a level file (File > Open)", parse_open},
    {"save", false, kSaveUsage, "save, or save as PATH (an existing other file needs overwrite)", parse_save},
    {"place", false, kPlaceUsage, "place an entity (snapped) and select it", parse_place},
    {"select", false, kSelectUsage, "select by id, all (of a type), none, or in a box", parse_select},
    {"move", false, kMoveUsage, "move the selection", parse_move},
    {"nudge", false, kNudgeUsage, "move the selection one grid step", parse_nudge},
    {"rotate", false, kRotateUsage, "turn the selection", parse_rotate},
    {"scale", false, kScaleUsage, "scale the selection's size fields", parse_scale},
    {"delete", false, "delete", "delete the selection", no_arguments<steps::Delete>},
    {"duplicate", false, kDuplicateUsage, "duplicate the selection (default offset: one grid step)",
     parse_duplicate},
    {"copy", false, "copy", "copy the selection", no_arguments<steps::Copy>},
    {"paste", false, "paste", "paste what copy copied", no_arguments<steps::Paste>},
    {"recover", false, "recover accept|decline", "answer the autosave recovery offer after open",
     parse_recover},
    {"campaign", false, kCampaignUsage, "append the open, saved level to a campaign file", parse_campaign},

};

} // namespace

std::span<const CommandSpec> level_edit_commands() {
    return kCommands;
}

// ---- running ------------------------------------------------------------------------------------------

namespace steps {

Result<void> New::run(ScriptContext& c) const {
    new_document(c.editor);
    return ok();
}
Result<void> Open::run(ScriptContext& c) const {
    return open(c.editor, c.resolve(path));
}
Result<void> Save::run(ScriptContext& c) const {
    auto r = save(c.editor);
    if (!r) return r.error();
    c.report.saved.push_back(r->path);
    return ok();
}
Result<void> SaveAs::run(ScriptContext& c) const {
    SaveOptions options;
    options.overwrite_existing = overwrite;
    auto r = save_as(c.editor, c.resolve(path), options);
    if (!r) return r.error();
    c.report.saved.push_back(r->path);
    if (r->draft) log::warn(c.file_name, ":", c.line, ": saved a draft with ", r->error_count, " error(s)");
    return ok();
}
Result<void> Recover::run(ScriptContext& c) const {
    if (accept) return accept_recovery(c.editor);
    c.editor.decline_recovery();
    return ok();
}
Result<void> CampaignAdd::run(ScriptContext& c) const {
    auto added = add_to_campaign(c.editor, c.resolve(campaign), title);
    if (!added) return added.error();
    log::info(c.file_name, ":", c.line, ": added ", added->file, " to ", campaign, " as level ",
              added->position, " (\"", added->title, "\")");
    return ok();
}

Result<void> Select::run(ScriptContext& c) const {
    return select(c.editor, ids, mode);
}
Result<void> SelectAll::run(ScriptContext& c) const {
    select_all(c.editor);
    return ok();
}
Result<void> SelectType::run(ScriptContext& c) const {
    select_all_of_type(c.editor, type);
    return ok();
}
Result<void> SelectNone::run(ScriptContext& c) const {
    c.editor.clear_selection();
    return ok();
}
Result<void> SelectBox::run(ScriptContext& c) const {
    select_in_box(c.editor, {glm::min(a, b), glm::max(a, b)});
    return ok();
}

Result<void> Place::run(ScriptContext& c) const {
    return done(place(c.editor, type, position, yaw, name));
}
Result<void> Move::run(ScriptContext& c) const {
    return move_selection(c.editor, delta, snap);
}
Result<void> Nudge::run(ScriptContext& c) const {
    return nudge(c.editor, axis, direction);
}
Result<void> Rotate::run(ScriptContext& c) const {
    return rotate_selection_about(c.editor, axis, degrees, space);
}
Result<void> Scale::run(ScriptContext& c) const {
    return scale_selection(c.editor, factors);
}
Result<void> Delete::run(ScriptContext& c) const {
    return delete_selection(c.editor);
}
Result<void> Duplicate::run(ScriptContext& c) const {
    return duplicate(c.editor, offset);
}
Result<void> Copy::run(ScriptContext& c) const {
    if (c.editor.doc().selection.empty())
        return Error("copy: nothing is selected", Location{}, "select entities first");
    copy(c.editor);
    return ok();
}
Result<void> Paste::run(ScriptContext& c) const {
    return paste(c.editor);
}

} // namespace steps
} // namespace ks::editor
