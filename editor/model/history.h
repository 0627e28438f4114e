#pragma once
// Unlimited undo/redo over commands, with transactions (several commands as one step: a gizmo drag, a quick
// fix that moves and renames) and a save point for the dirty marker: undoing or redoing back to the state
// that was saved makes the document clean again.
#include "model/command.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ks::editor {

class History {
  public:
    // Applies the command to the document and records it (inside an open transaction, as part of it).
    // Consecutive LevelChanges with the same merge key fold into one step.
    void execute(Document& doc, std::unique_ptr<Command> command);

    bool can_undo() const { return !undo_.empty() && !in_transaction(); }
    bool can_redo() const { return !redo_.empty() && !in_transaction(); }
    bool undo(Document& doc);
    bool redo(Document& doc);

    // A transaction collects every command executed until commit (one history step named `name`) or cancel
    // (everything reverted, nothing recorded). Transactions nest; only the outermost one records.
    void begin_transaction(std::string name);
    void commit_transaction();
    void cancel_transaction(Document& doc);
    bool in_transaction() const { return depth_ > 0; }

    // Ends merging: the next command starts a new step even if its merge key matches (mouse released).
    void seal() { sealed_ = true; }

    // History panel: step names, oldest first; steps [0, undo_count) are done, the rest can be redone.
    std::vector<std::string> step_names() const;
    size_t undo_count() const { return undo_.size(); }
    size_t redo_count() const { return redo_.size(); }
    std::string undo_name() const { return undo_.empty() ? std::string() : undo_.back().command->name(); }
    std::string redo_name() const { return redo_.empty() ? std::string() : redo_.back().command->name(); }

    void mark_saved() { saved_serial_ = current_serial(); }
    bool at_save_point() const { return !in_transaction() && current_serial() == saved_serial_; }
    // Forgets everything (New / Open); the fresh state is the save point.
    void clear();

    // Bumps on every change to the document through history (execute, undo, redo, cancel).
    std::uint64_t revision() const { return revision_; }

  private:
    struct Step {
        std::unique_ptr<Command> command;
        std::uint64_t serial = 0; // identifies the document state after this step
    };
    std::uint64_t current_serial() const { return undo_.empty() ? 0 : undo_.back().serial; }
    void record(std::unique_ptr<Command> command);

    std::vector<Step> undo_, redo_;
    std::unique_ptr<CompoundCommand> transaction_;
    int depth_ = 0;
    bool sealed_ = true;
    std::uint64_t next_serial_ = 1;
    std::uint64_t saved_serial_ = 0;
    std::uint64_t revision_ = 0;
};

} // namespace ks::editor
