// The dojo's clip file on disk (dojo_file.h).
#include "ui/dojo_file.h"

#include "model/dojo_keys.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <system_error>

namespace ks::editor::ui {

namespace {
constexpr double kDiskCheckSeconds = 1.0;
const ImVec4 kNoticeColour(1.0f, 0.78f, 0.35f, 1.0f);
} // namespace

DojoFile::DojoFile(std::filesystem::path path, std::function<void()> load)
    : path_(std::move(path)), load_(std::move(load)) {}

void DojoFile::remember_disk() {
    disk_ = fingerprint_file(path_);
    changed_on_disk_ = false;
}

void DojoFile::watch_disk() {
    const double now = ImGui::GetTime();
    if (now < next_disk_check_ || changed_on_disk_) return;
    next_disk_check_ = now + kDiskCheckSeconds;
    std::error_code size_error, time_error;
    const auto size = std::filesystem::file_size(path_, size_error);
    const auto mtime = std::filesystem::last_write_time(path_, time_error);
    const bool exists = !size_error && !time_error;
    if (exists == disk_.exists && (!exists || (size == disk_.size && mtime == disk_.mtime))) return;
    const DiskFingerprint seen = fingerprint_file(path_);
    if (seen.same_content(disk_))
        disk_.mtime = seen.mtime; // touched, not changed
    else
        changed_on_disk_ = true;
}

void DojoFile::write(const DojoContext& dojo) {
    if (auto r = save_dojo_file(path_, dojo.edits.file()); !r) {
        dojo.log("dojo: " + r.error().str(), true);
        return;
    }
    dojo.edits.mark_saved();
    remember_disk();
    dojo.log("dojo: saved " + path_.string() + " (the runtime's Dojo and robots load it)", false);
}

void DojoFile::reload(const DojoContext& dojo) {
    if (dojo.edits.dirty()) {
        ask_reload_ = true;
        return;
    }
    load_();
    dojo.log("dojo: reloaded " + path_.string(), false);
}

void DojoFile::save(const DojoContext& dojo) {
    if (const auto& issues = dojo.edits.issues(); !issues.empty()) {
        dojo.log("dojo: not saved: the clip file has " + std::to_string(issues.size()) +
                     " issues (listed in the Dojo tab)",
                 true);
        return;
    }
    if (changed_on_disk_)
        ask_overwrite_ = true;
    else
        write(dojo);
}

// The issues, the outside-change notice, Save and Reload.
void DojoFile::row(const DojoContext& dojo) {
    const auto& issues = dojo.edits.issues();
    const std::string& compile_error = dojo.edits.compile_error();
    for (const auto& issue : issues)
        ImGui::TextColored(kErrorColour, "%s: %s (%s)", issue.path.str().c_str(), issue.message.c_str(),
                           issue.hint.c_str());
    if (!compile_error.empty()) ImGui::TextColored(kErrorColour, "%s", compile_error.c_str());
    const std::string name = path_.filename().string();
    if (changed_on_disk_) {
        ImGui::TextColored(kNoticeColour, "%s was changed outside the editor.", name.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Reload it")) reload(dojo);
        dojo.mark(DojoSpot::ReloadNotice);
        ImGui::SameLine();
        if (ImGui::SmallButton("Keep mine")) remember_disk();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Ignore the outside change; the next Save will overwrite it");
    }
    ImGui::BeginDisabled(!issues.empty());
    if (ImGui::Button(("Save " + name + (dojo.edits.dirty() ? " *" : "")).c_str())) save(dojo);
    dojo.mark(DojoSpot::Save);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(issues.empty() ? "Ctrl+S: validate and write %s"
                                         : "Fix the issues listed above first (%s)",
                          path_.string().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Reload")) reload(dojo);
    dojo.mark(DojoSpot::Reload);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Read %s again from disk", path_.string().c_str());
}

DojoQuitAnswer DojoFile::take_quit_answer() {
    const DojoQuitAnswer answer = quit_answer_;
    quit_answer_ = DojoQuitAnswer::Pending;
    return answer;
}

void DojoFile::quit_prompt(const DojoContext& dojo) {
    if (ask_quit_) ImGui::OpenPopup("Unsaved clip edits");
    ask_quit_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Unsaved clip edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("%s has unsaved edits from the Dojo tab (%zu undo steps).", path_.filename().string().c_str(),
                dojo.edits.history().undo_count());
    ImGui::Text("Save them before quitting?");
    if (ImGui::Button("Save", ImVec2(100, 0))) {
        save(dojo); // refused (issues) or waiting on the overwrite question: quitting stops, the edits kept
        quit_answer_ = dojo.edits.dirty() ? DojoQuitAnswer::Stay : DojoQuitAnswer::Go;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(100, 0)))
        quit_answer_ = DojoQuitAnswer::Go, ImGui::CloseCurrentPopup();
    dojo.mark(DojoSpot::QuitDiscard);
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100, 0)))
        quit_answer_ = DojoQuitAnswer::Stay, ImGui::CloseCurrentPopup();
    dojo.mark(DojoSpot::QuitCancel);
    ImGui::EndPopup();
}

void DojoFile::prompts(const DojoContext& dojo) {
    quit_prompt(dojo);
    if (ask_reload_) ImGui::OpenPopup("Reload clip file?");
    if (ask_overwrite_) ImGui::OpenPopup("Overwrite clip file?");
    ask_reload_ = ask_overwrite_ = false;
    const std::string name = path_.filename().string();
    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Reload clip file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s has unsaved edits (%zu undo steps).", name.c_str(),
                    dojo.edits.history().undo_count());
        ImGui::Text("Reloading drops them and reads the file from disk.");
        if (ImGui::Button("Discard and reload")) {
            load_();
            dojo.log("dojo: reloaded " + path_.string() + ", unsaved edits dropped", false);
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
            write(dojo);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

} // namespace ks::editor::ui
