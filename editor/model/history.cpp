#include "model/history.h"

namespace ks::editor {

void History::execute(Document& doc, std::unique_ptr<Command> command) {
    command->selection_before = doc.selection;
    command->apply(doc);
    ++revision_;
    if (in_transaction()) {
        transaction_->children.push_back(std::move(command));
        return;
    }
    record(std::move(command));
}

void History::record(std::unique_ptr<Command> command) {
    redo_.clear();
    auto* change = dynamic_cast<LevelChange*>(command.get());
    // Never merge into the saved state: that step must stay recognisable as the save point.
    if (change && !sealed_ && !undo_.empty() && undo_.back().serial != saved_serial_) {
        if (auto* top = dynamic_cast<LevelChange*>(undo_.back().command.get());
            top && top->try_merge(*change)) {
            undo_.back().serial = next_serial_++;
            return;
        }
    }
    sealed_ = !change || change->merge_key.empty();
    undo_.push_back({std::move(command), next_serial_++});
}

bool History::undo(Document& doc) {
    if (!can_undo()) return false;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    step.command->revert(doc);
    redo_.push_back(std::move(step));
    sealed_ = true;
    ++revision_;
    return true;
}

bool History::redo(Document& doc) {
    if (!can_redo()) return false;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    step.command->apply(doc);
    undo_.push_back(std::move(step));
    sealed_ = true;
    ++revision_;
    return true;
}

void History::begin_transaction(std::string name) {
    if (depth_++ == 0) {
        transaction_ = std::make_unique<CompoundCommand>();
        transaction_->set_name(std::move(name));
    }
}

void History::commit_transaction() {
    if (depth_ == 0 || --depth_ > 0) return;
    auto compound = std::move(transaction_);
    if (compound->children.empty()) return;
    compound->selection_before = compound->children.front()->selection_before;
    compound->selection_after = compound->children.back()->selection_after;
    sealed_ = true;
    record(std::move(compound));
    sealed_ = true;
}

void History::cancel_transaction(Document& doc) {
    if (depth_ == 0) return;
    depth_ = 0;
    auto compound = std::move(transaction_);
    if (!compound->children.empty()) {
        compound->revert(doc);
        ++revision_;
    }
}

std::vector<std::string> History::step_names() const {
    std::vector<std::string> names;
    for (const auto& s : undo_) names.push_back(s.command->name());
    for (auto it = redo_.rbegin(); it != redo_.rend(); ++it) names.push_back(it->command->name());
    return names;
}

void History::clear() {
    undo_.clear();
    redo_.clear();
    transaction_.reset();
    depth_ = 0;
    sealed_ = true;
    saved_serial_ = current_serial();
    ++revision_;
}

} // namespace ks::editor
