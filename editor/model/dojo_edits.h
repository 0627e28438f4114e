#pragma once
// The dojo window's clip file while it is edited, free of any window: the file, its undo history, the live
// check (dojo_file_issues) and compile, and the last refused edit's reason. Every change goes through
// apply() (one undo step through the model's edit functions) or, for a drag, begin_drag() ahead of direct
// changes; after each, the file is checked and, when valid, compiled into the playback's clips (the last
// good clips keep playing while it is not). The dojo's panels share one (editor/ui/dojo_context.h).
#include "anim/clip.h"
#include "core/result.h"
#include "model/dojo_clips.h"
#include "model/dojo_keys.h"
#include "model/dojo_playback.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ks::editor {

// The editor's log: a line, and whether it is an error.
using DojoLogFn = std::function<void(const std::string&, bool error)>;

class DojoEdits {
  public:
    DojoEdits(DojoPlayback& playback, DojoLogFn log);

    const anim::AnimationFile& file() const { return file_; }
    // The file for a widget that changes it in place: call begin_drag() first, then changed().
    anim::AnimationFile& file_in_place() { return file_; }
    const DojoHistory& history() const { return history_; }
    const std::vector<anim::Issue>& issues() const { return issues_; }
    const std::string& compile_error() const { return compile_error_; }
    const std::string& message() const { return message_; } // the last refused edit's reason
    bool dirty() const { return dirty_; }
    // Counts the changes to the file: what is cached from it (ghosts, curves) follows it.
    std::uint64_t revision() const { return revision_; }

    // A freshly read file: the history is cleared, the file clean, then checked and compiled.
    void reset(anim::AnimationFile file);
    // The file could not be read (or its rig): the reason is shown where the clips would be.
    void set_load_error(std::string error) { compile_error_ = std::move(error); }
    void mark_saved() { dirty_ = false; }

    // One undo step through the model: runs `edit(file)`; on success records it and recompiles, on an
    // error keeps the file and shows (and logs) the model's message. True when it was applied.
    template <class Edit>
    bool apply(std::string name, Edit&& edit) {
        auto result = apply_dojo_edit(file_, history_, std::move(name), [&] { return edit(file_); });
        if (!result) {
            refuse(result.error());
            return false;
        }
        message_.clear();
        changed();
        return true;
    }
    // A drag (or any continuous edit) is one undo step: the first call records the file as it is now, the
    // next ones until end_drag() record nothing.
    void begin_drag(const std::string& name);
    // Records `before` (the file when the drag began) unless this drag is recorded already.
    void record_drag(const anim::AnimationFile& before, const std::string& name);
    void end_drag() { drag_open_ = false; }
    // Replaces the file with one the model edited (a drag computed from its origin), then changed().
    void replace(anim::AnimationFile edited);
    // After a change to the file: dirty, checked, compiled into the playback.
    void changed();
    // An edit refused: its message and hint show until the next edit succeeds, and go to the log.
    void refuse(const Error& error);
    // A message shown without logging (a drag refused frame after frame), or cleared.
    void show_message(std::string message) { message_ = std::move(message); }

    bool undo();
    bool redo();

  private:
    void recompile();

    DojoPlayback& playback_;
    DojoLogFn log_;
    anim::AnimationFile file_;
    DojoHistory history_;
    std::vector<anim::Issue> issues_;
    std::string compile_error_;
    std::string message_;
    std::uint64_t revision_ = 0;
    bool dirty_ = false;
    bool drag_open_ = false; // a drag in progress (already recorded)
};

} // namespace ks::editor
