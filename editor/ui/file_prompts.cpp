// New, Open, Save and Quit, and the questions they ask first (unsaved changes, a path, overwriting,
// recovering an autosave).
#include "ui/file_prompts.h"
#include "core/paths.h"
#include "model/edit_files.h"

#include <imgui.h>

#include <cstdio>

namespace ks::editor::ui {
namespace fs = std::filesystem;

namespace {
// Where an untitled level is offered to be saved: the player's levels folder (created here), which the
// game's Custom level... lists; the shipped levels/ folder when there is no home or it cannot be made.
fs::path new_level_folder() {
    const fs::path user = paths::ensure_user_levels_dir();
    return user.empty() ? paths::level("") : user;
}
} // namespace

void FilePrompts::request(PendingAction action, fs::path path) {
    pending_ = action;
    pending_path_ = std::move(path);
    if (editor_.has_unsaved_changes())
        ask_unsaved_ = true;
    else
        perform(action);
}

void FilePrompts::perform(PendingAction action) {
    switch (action) {
    case PendingAction::New:
        new_document(editor_);
        log_line("new level");
        break;
    case PendingAction::Open:
        path_for_save_ = false;
        ask_path_ = true;
        std::snprintf(path_input_, sizeof(path_input_), "%s",
                      editor_.file_path().empty() ? paths::level("").string().c_str()
                                                  : editor_.file_path().string().c_str());
        return; // pending_ stays until the path is given
    case PendingAction::OpenRecent:
        open_file(pending_path_);
        break;
    case PendingAction::Quit:
        quit_ = true;
        break;
    case PendingAction::None:
        break;
    }
    pending_ = PendingAction::None;
}

void FilePrompts::open_file(const fs::path& path) {
    if (auto r = open(editor_, path); !r) {
        log_line(r.error().str(), true);
        if (!fs::exists(path)) recent_.remove(path);
        return;
    }
    log_line("opened " + path.string());
    if (editor_.recovery_offer()) log_line("an autosave newer than the file exists: recover it?");
    if (opened_) opened_();
}

void FilePrompts::save(bool save_as) {
    if (save_as || editor_.file_path().empty()) {
        path_for_save_ = true;
        ask_path_ = true;
        std::snprintf(path_input_, sizeof(path_input_), "%s",
                      editor_.file_path().empty() ? (new_level_folder() / "untitled.json").string().c_str()
                                                  : editor_.file_path().string().c_str());
        return;
    }
    auto r = editor::save(editor_);
    if (!r) {
        log_line(r.error().str(), true);
        if (disk_status(editor_) == DiskStatus::Modified) ask_overwrite_ = true;
        return;
    }
    log_line((r->draft ? "saved as DRAFT (" + std::to_string(r->error_count) + " design errors): "
                       : std::string("saved ")) +
                 r->path.string(),
             r->draft);
}

void FilePrompts::draw() {
    if (ask_unsaved_) ImGui::OpenPopup("Unsaved changes");
    if (ask_path_) ImGui::OpenPopup(path_for_save_ ? "Save level as" : "Open level");
    if (ask_overwrite_) ImGui::OpenPopup("Overwrite?");
    if (editor_.recovery_offer() && !ask_unsaved_ && !ask_path_) ImGui::OpenPopup("Recover autosave");
    ask_unsaved_ = ask_path_ = ask_overwrite_ = false;

    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s has unsaved changes.", editor_.file_path().empty()
                                                   ? "The untitled level"
                                                   : editor_.file_path().filename().string().c_str());
        ImGui::Text("Save them before going on?");
        if (ImGui::Button("Save")) {
            ImGui::CloseCurrentPopup();
            save(false);
            if (!editor_.has_unsaved_changes()) perform(pending_);
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard")) {
            ImGui::CloseCurrentPopup();
            perform(pending_);
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            ImGui::CloseCurrentPopup();
            pending_ = PendingAction::None;
        }
        ImGui::EndPopup();
    }
    for (const char* title : {"Open level", "Save level as"}) {
        ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) continue;
        ImGui::Text("Level file (JSON):");
        ImGui::SetNextItemWidth(520);
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        const bool entered = ImGui::InputText("##path", path_input_, sizeof(path_input_),
                                              ImGuiInputTextFlags_EnterReturnsTrue);
        if (!recent_.entries().empty()) {
            ImGui::TextDisabled("Recent:");
            for (const auto& entry : recent_.entries())
                if (ImGui::Selectable(entry.string().c_str()))
                    std::snprintf(path_input_, sizeof(path_input_), "%s", entry.string().c_str());
        }
        if (entered || ImGui::Button(path_for_save_ ? "Save" : "Open")) {
            const fs::path path = paths::resolve_user_path(path_input_);
            ImGui::CloseCurrentPopup();
            if (path_for_save_) {
                auto r = save_as(editor_, path);
                if (!r && fs::exists(path)) {
                    pending_path_ = path;
                    ask_overwrite_ = true;
                } else if (!r) {
                    log_line(r.error().str(), true);
                } else {
                    log_line((r->draft ? "saved as DRAFT: " : "saved ") + r->path.string(), r->draft);
                    if (pending_ != PendingAction::None) perform(pending_);
                }
            } else {
                open_file(path);
                pending_ = PendingAction::None;
            }
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            ImGui::CloseCurrentPopup();
            pending_ = PendingAction::None;
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Overwrite?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const fs::path target = pending_path_.empty() ? editor_.file_path() : pending_path_;
        ImGui::Text("%s exists or was changed on disk since it was opened.", target.string().c_str());
        ImGui::Text("Overwrite it?");
        if (ImGui::Button("Overwrite")) {
            SaveOptions options;
            options.overwrite_existing = true;
            options.overwrite_external_changes = true;
            auto r = pending_path_.empty() ? editor::save(editor_, options)
                                           : save_as(editor_, pending_path_, options);
            if (r)
                log_line((r->draft ? "saved as DRAFT: " : "saved ") + r->path.string(), r->draft);
            else
                log_line(r.error().str(), true);
            pending_path_.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) {
            pending_path_.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Recover autosave", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const auto& offer = editor_.recovery_offer();
        if (offer) {
            ImGui::Text("An autosave is newer than %s:", offer->level_file.empty()
                                                             ? "the untitled level"
                                                             : offer->level_file.string().c_str());
            ImGui::TextDisabled("%s", offer->autosave.string().c_str());
            ImGui::Text("The editor may have closed without saving. Recover it? (Undo returns to the file.)");
        }
        if (ImGui::Button("Recover")) {
            report(accept_recovery(editor_), "recover");
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Keep the file")) {
            editor_.decline_recovery();
            ImGui::CloseCurrentPopup();
        }
        if (!offer) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    campaign_prompt();
}

} // namespace ks::editor::ui
