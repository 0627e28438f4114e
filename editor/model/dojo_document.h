#pragma once
// The dojo's editing session without a window: the clip file being edited, where it came from, its undo
// history and whether it has unsaved edits. The script language's dojo commands (`dojo open`, `clip new`,
// ...) run on one; every edit goes through edit(), so it is one undo step and the file is unchanged when the
// edit fails.
#include "anim/clip.h"
#include "core/result.h"
#include "model/dojo_clips.h"
#include "model/dojo_keys.h"

#include <filesystem>
#include <string>
#include <utility>

namespace ks::editor {

class DojoDocument {
  public:
    // Loads a clip file (anim::load_animation_file: every problem located) with its relative keys made
    // absolute (make_keys_absolute: the same poses); the history starts empty.
    Result<void> open(const std::filesystem::path& path);
    // Checks (dojo_file_issues) and writes atomically to `path`, or to the opened file when empty; the
    // document then belongs to the path written and is clean.
    Result<void> save(const std::filesystem::path& path = {});

    bool is_open() const { return open_; }
    const anim::AnimationFile& file() const { return file_; }
    const std::filesystem::path& path() const { return path_; }
    bool dirty() const { return dirty_; }
    const DojoHistory& history() const { return history_; }

    // Runs `change(file)`, one of the dojo's edit functions bound to its arguments; on success it is one
    // undo step named `name`. Returns what the edit returns.
    template <class Change>
    auto edit(std::string name, Change&& change) -> decltype(change(std::declval<anim::AnimationFile&>())) {
        auto result = apply_dojo_edit(file_, history_, std::move(name), [&] { return change(file_); });
        if (result) dirty_ = true;
        return result;
    }
    bool undo();
    bool redo();

  private:
    anim::AnimationFile file_;
    std::filesystem::path path_;
    DojoHistory history_;
    bool open_ = false;
    bool dirty_ = false;
};

} // namespace ks::editor
