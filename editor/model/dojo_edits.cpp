#include "model/dojo_edits.h"

namespace ks::editor {

DojoEdits::DojoEdits(DojoPlayback& playback, DojoLogFn log) : playback_(playback), log_(std::move(log)) {
    if (!log_) log_ = [](const std::string&, bool) {};
}

void DojoEdits::reset(anim::AnimationFile file) {
    file_ = std::move(file);
    dirty_ = false;
    history_.clear();
    drag_open_ = false;
    message_.clear();
    recompile();
}

void DojoEdits::begin_drag(const std::string& name) {
    if (!drag_open_) history_.record(file_, name);
    drag_open_ = true;
}

void DojoEdits::record_drag(const anim::AnimationFile& before, const std::string& name) {
    if (!drag_open_) history_.record(before, name);
    drag_open_ = true;
}

void DojoEdits::replace(anim::AnimationFile edited) {
    file_ = std::move(edited);
    changed();
}

void DojoEdits::changed() {
    dirty_ = true;
    recompile();
}

void DojoEdits::refuse(const Error& error) {
    message_ = error.message + (error.hint.empty() ? "" : " (" + error.hint + ")");
    log_("dojo: " + error.str(), true);
}

bool DojoEdits::undo() {
    if (!history_.undo(file_)) return false;
    changed();
    return true;
}

bool DojoEdits::redo() {
    if (!history_.redo(file_)) return false;
    changed();
    return true;
}

void DojoEdits::recompile() {
    ++revision_; // the file changed: what is cached from it is stale, compiled or not
    issues_ = dojo_file_issues(file_);
    compile_error_.clear();
    if (!issues_.empty()) return; // keep the last good clips playing until the file is valid again
    auto compiled = anim::compile(file_, playback_.rig());
    if (!compiled) {
        compile_error_ = compiled.error().str();
        return;
    }
    playback_.set_clips(std::move(*compiled));
}

} // namespace ks::editor
