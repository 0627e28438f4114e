#pragma once
// The dojo's clip file: its problems, Save (validated, atomic) and Reload, and changes made outside the
// editor: the file is looked at once a second (size and time first, the content hash only when those
// moved), a notice offers to reload it, and reloading over unsaved edits, saving over outside changes and
// quitting with unsaved edits ask first.
#include "model/disk_fingerprint.h"
#include "ui/dojo_context.h"

#include <filesystem>
#include <functional>

namespace ks::editor::ui {

// Quitting with unsaved clip edits: Go once they are saved or dropped, Stay when cancelled (or the save
// refused), Pending until answered.
enum class DojoQuitAnswer : std::uint8_t { Pending, Go, Stay };

class DojoFile {
  public:
    // `load` reads the file (and the rig) again into the dojo.
    DojoFile(std::filesystem::path path, std::function<void()> load);

    const std::filesystem::path& path() const { return path_; }
    bool changed_on_disk() const { return changed_on_disk_; }
    void remember_disk(); // the file as it is now is the one loaded (or saved)
    void watch_disk();    // once a second at most

    void row(const DojoContext& dojo); // the issues, the outside-change notice, Save and Reload
    void save(const DojoContext& dojo);
    void reload(const DojoContext& dojo);
    void prompts(const DojoContext& dojo); // the questions, drawn whichever tab is shown
    void ask_before_quit() { ask_quit_ = true; }
    DojoQuitAnswer take_quit_answer();

  private:
    void quit_prompt(const DojoContext& dojo);
    void write(const DojoContext& dojo);

    std::filesystem::path path_;
    std::function<void()> load_;
    DiskFingerprint disk_;
    double next_disk_check_ = 0.0; // ImGui time of the next look at the file
    bool changed_on_disk_ = false;
    bool ask_reload_ = false, ask_overwrite_ = false, ask_quit_ = false;
    DojoQuitAnswer quit_answer_ = DojoQuitAnswer::Pending;
};

} // namespace ks::editor::ui
