// The dojo's clip file: its problems, Save (validated, atomic) and Reload, and changes made outside the
// editor: the file is looked at once a second (size and time first, the content hash only when those
// moved), a notice offers to reload it, and reloading over unsaved edits or saving over outside changes
// asks first.
#include "ui/dojo_panel.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <system_error>

namespace ks::editor::ui {

namespace {
constexpr double kDiskCheckSeconds = 1.0;
const ImVec4 kNoticeColour(1.0f, 0.78f, 0.35f, 1.0f);
} // namespace

void DojoPanel::remember_disk() {
    disk_ = fingerprint_file(clip_file_);
    changed_on_disk_ = false;
}

void DojoPanel::watch_disk() {
    const double now = ImGui::GetTime();
    if (now < next_disk_check_ || changed_on_disk_) return;
    next_disk_check_ = now + kDiskCheckSeconds;
    std::error_code size_error, time_error;
    const auto size = std::filesystem::file_size(clip_file_, size_error);
    const auto mtime = std::filesystem::last_write_time(clip_file_, time_error);
    const bool exists = !size_error && !time_error;
    if (exists == disk_.exists && (!exists || (size == disk_.size && mtime == disk_.mtime))) return;
    const DiskFingerprint seen = fingerprint_file(clip_file_);
    if (seen.same_content(disk_))
        disk_.mtime = seen.mtime; // touched, not changed
    else
        changed_on_disk_ = true;
}

void DojoPanel::write_file() {
    if (auto r = save_dojo_file(clip_file_, file_); !r) {
        log_("dojo: " + r.error().str(), true);
        return;
    }
    dirty_ = false;
    remember_disk();
    log_("dojo: saved " + clip_file_.string() + " (the runtime's Dojo and robots load it)", false);
}

void DojoPanel::reload() {
    if (dirty_) {
        ask_reload_ = true;
        return;
    }
    load();
    log_("dojo: reloaded " + clip_file_.string(), false);
}

void DojoPanel::save() {
    if (!issues_.empty()) {
        log_("dojo: not saved: the clip file has " + std::to_string(issues_.size()) +
                 " issues (listed in the Dojo tab)",
             true);
        return;
    }
    if (changed_on_disk_)
        ask_overwrite_ = true;
    else
        write_file();
}

// The issues, the outside-change notice, Save and Reload.
void DojoPanel::file_row() {
    for (const auto& issue : issues_)
        ImGui::TextColored(kErrorColour, "%s: %s (%s)", issue.path.str().c_str(), issue.message.c_str(),
                           issue.hint.c_str());
    if (!compile_error_.empty()) ImGui::TextColored(kErrorColour, "%s", compile_error_.c_str());
    const std::string name = clip_file_.filename().string();
    if (changed_on_disk_) {
        ImGui::TextColored(kNoticeColour, "%s was changed outside the editor.", name.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Reload it")) reload();
        mark(DojoSpot::ReloadNotice);
        ImGui::SameLine();
        if (ImGui::SmallButton("Keep mine")) remember_disk();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Ignore the outside change; the next Save will overwrite it");
    }
    ImGui::BeginDisabled(!issues_.empty());
    if (ImGui::Button(("Save " + name + (dirty_ ? " *" : "")).c_str())) save();
    mark(DojoSpot::Save);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(issues_.empty() ? "Ctrl+S: validate and write %s"
                                          : "Fix the issues listed above first (%s)",
                          clip_file_.string().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Reload")) reload();
    mark(DojoSpot::Reload);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Read %s again from disk", clip_file_.string().c_str());
}

DojoPanel::QuitAnswer DojoPanel::take_quit_answer() {
    const QuitAnswer answer = quit_answer_;
    quit_answer_ = QuitAnswer::Pending;
    return answer;
}

void DojoPanel::quit_prompt() {
    if (ask_quit_) ImGui::OpenPopup("Unsaved clip edits");
    ask_quit_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Unsaved clip edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s has unsaved edits from the Dojo tab (%zu undo steps).",
                clip_file_.filename().string().c_str(), history_.undo_count());
    ImGui::Text("Save them before quitting?");
    if (ImGui::Button("Save", ImVec2(100, 0))) {
        save(); // refused (issues) or waiting on the overwrite question: quitting stops, the edits kept
        quit_answer_ = dirty_ ? QuitAnswer::Stay : QuitAnswer::Go;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(100, 0))) quit_answer_ = QuitAnswer::Go, ImGui::CloseCurrentPopup();
    mark(DojoSpot::QuitDiscard);
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100, 0))) quit_answer_ = QuitAnswer::Stay, ImGui::CloseCurrentPopup();
    mark(DojoSpot::QuitCancel);
    ImGui::EndPopup();
}

void DojoPanel::prompts() {
    quit_prompt();
    if (ask_reload_) ImGui::OpenPopup("Reload clip file?");
    if (ask_overwrite_) ImGui::OpenPopup("Overwrite clip file?");
    ask_reload_ = ask_overwrite_ = false;
    const std::string name = clip_file_.filename().string();
    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Reload clip file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s has unsaved edits (%zu undo steps).", name.c_str(), history_.undo_count());
        ImGui::Text("Reloading drops them and reads the file from disk.");
        if (ImGui::Button("Discard and reload")) {
            load();
            log_("dojo: reloaded " + clip_file_.string() + ", unsaved edits dropped", false);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Overwrite clip file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s was changed outside the editor since it was loaded.", name.c_str());
        ImGui::Text("Saving overwrites those changes with the dojo's clips.");
        if (ImGui::Button("Overwrite")) {
            write_file();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

} // namespace ks::editor::ui
