#pragma once
// The document's file: New, Open, Save, Save As, the window title, external-change detection and autosave
// recovery. Tests: tests/editor/test_edit_files.cpp.
#include "model/editor.h"

#include <filesystem>
#include <string>

namespace ks::editor {

struct SaveOptions {
    bool overwrite_existing = false;         // Save As onto a file that exists (the UI asked first)
    bool overwrite_external_changes = false; // Save over a file someone changed since it was opened
};

struct SaveReport {
    std::filesystem::path path;
    bool draft = false; // saved with design errors: the level loads but should not ship
    int error_count = 0;
    int warning_count = 0;
};

enum class DiskStatus { NoFile, Unchanged, Modified, Deleted };

void new_document(Editor& editor);
// Warnings of the level reader go to the log; prefab instances follow prefabs changed since the level was
// saved (one undoable step); an autosave newer than the file is offered (Editor::recovery_offer).
Result<void> open(Editor& editor, const std::filesystem::path& path);
Result<SaveReport> save(Editor& editor, const SaveOptions& options = {});
Result<SaveReport> save_as(Editor& editor, const std::filesystem::path& path,
                           const SaveOptions& options = {});
// "main.json* [draft] - Killswitch Editor"
std::string title(Editor& editor);
DiskStatus disk_status(const Editor& editor);
// The offered autosave replaces the level in one undoable step: undo returns to the file as it is on disk.
Result<void> accept_recovery(Editor& editor);

} // namespace ks::editor
