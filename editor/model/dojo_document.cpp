#include "model/dojo_document.h"

#include "anim/clip_io.h"

namespace ks::editor {

Result<void> DojoDocument::open(const std::filesystem::path& path) {
    auto loaded = anim::load_animation_file(path);
    if (!loaded) return loaded.error();
    file_ = std::move(loaded).value();
    make_keys_absolute(file_); // independent keys (dojo_keys.h); the next save writes them
    path_ = path;
    history_.clear();
    open_ = true;
    dirty_ = false;
    return ok();
}

Result<void> DojoDocument::save(const std::filesystem::path& path) {
    if (!open_) return Error("no clip file is open", {}, "open one first");
    const std::filesystem::path target = path.empty() ? path_ : path;
    if (auto saved = save_dojo_file(target, file_); !saved) return saved;
    path_ = target;
    dirty_ = false;
    return ok();
}

bool DojoDocument::undo() {
    if (!history_.undo(file_)) return false;
    dirty_ = true;
    return true;
}

bool DojoDocument::redo() {
    if (!history_.redo(file_)) return false;
    dirty_ = true;
    return true;
}

} // namespace ks::editor
