#pragma once
// The level file's actions and the questions they ask first: New, Open, Open Recent, Save, Save As and Quit
// (unsaved changes, a path, overwriting, recovering an autosave; file_prompts.cpp) and File > Add to
// Campaign... (campaign_prompt.cpp). Works through the document, the log and the recent files; the window
// asks the dojo about its clip edits before it passes on a Quit.
#include "model/editor.h"
#include "model/recent_files.h"
#include "ui/editor_log.h"

#include <filesystem>
#include <functional>
#include <string>

namespace ks::editor::ui {

// A question the user must answer before an action goes on (unsaved changes, overwrite, recovery).
enum class PendingAction { None, New, Open, OpenRecent, Quit };

class FilePrompts {
  public:
    // `opened`: called after a level file was opened (the viewport returns to its perspective view).
    FilePrompts(Editor& editor, EditorLog& log, RecentFiles& recent, std::function<void()> opened)
        : editor_(editor), log_(log), recent_(recent), opened_(std::move(opened)) {}

    // Asks about unsaved changes first, then performs the action (Open asks for the path).
    void request(PendingAction action, std::filesystem::path path = {});
    void save(bool save_as); // Save As, or Save of an untitled level, asks for the path
    void open_campaign_prompt();
    void draw(); // the modal questions, whichever tab is shown
    bool quit() const { return quit_; }

  private:
    void perform(PendingAction action);
    void open_file(const std::filesystem::path& path);
    void campaign_prompt();
    void log_line(std::string line, bool error = false) { log_.line(std::move(line), error); }
    void report(const Result<void>& result, const char* what) { log_.report(result, what); }

    Editor& editor_;
    EditorLog& log_;
    RecentFiles& recent_;
    std::function<void()> opened_;
    PendingAction pending_ = PendingAction::None;
    std::filesystem::path pending_path_;
    bool ask_unsaved_ = false;
    bool ask_path_ = false;
    bool path_for_save_ = false;
    bool ask_overwrite_ = false;
    char path_input_[512] = {};
    bool ask_campaign_ = false;
    char campaign_input_[512] = {};
    char campaign_title_[256] = {};
    bool quit_ = false;
};

} // namespace ks::editor::ui
