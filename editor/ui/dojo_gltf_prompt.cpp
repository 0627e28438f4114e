#include "ui/dojo_gltf_prompt.h"

#include "core/paths.h"
#include "model/dojo_gltf.h"

#include <imgui.h>

#include <array>
#include <cstring>
#include <system_error>

namespace ks::editor::ui {

void DojoGltfPrompt::open(Ask ask) {
    ask_ = ask;
    open_ = true;
    error_.clear();
}

void DojoGltfPrompt::buttons(const DojoContext& dojo) {
    const anim::ClipDef* shown = dojo.shown_def();
    ImGui::SameLine();
    if (ImGui::Button("Export clip to glTF...")) {
        open(Ask::Export);
        const std::filesystem::path folder = paths::user_data_dir();
        path_ = ((folder.empty() ? std::filesystem::path() : folder / "gltf") /
                 ((shown ? shown->name : "clips") + ".glb"))
                    .string();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Write the shown clip (or every clip) with the robot's rig as glTF 2.0 for Blender");
    ImGui::SameLine();
    if (ImGui::Button("Import clips from glTF...")) open(Ask::Import);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Read a glTF's node animations as clips (nodes named as the rig's); one undo step");
}

void DojoGltfPrompt::run(const DojoContext& dojo) {
    const std::filesystem::path path(path_);
    const anim::Rig& rig = dojo.playback.rig();
    if (ask_ == Ask::Export) {
        std::error_code ec;
        if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
        std::vector<std::size_t> clips;
        if (!all_clips_ && dojo.shown_def() != nullptr) clips.push_back(dojo.clip_index());
        auto written = export_clips_gltf(dojo.edits.file(), rig, clips, path);
        if (!written) {
            error_ = written.error().str();
            return;
        }
        dojo.log("dojo: exported " + std::string(clips.empty() ? "every clip" : "the clip") + " to " +
                     path.string() + " (keys at " + std::to_string(static_cast<int>(kGltfExportFps)) +
                     " frames a second)",
                 false);
    } else {
        // Imported into a copy first, so a refused file leaves the clips as they were and says where it
        // failed.
        anim::AnimationFile imported = dojo.edits.file();
        auto report = import_clips_gltf(imported, rig, path);
        if (!report) {
            error_ = report.error().str();
            return;
        }
        const std::string summary = report->summary();
        const bool unmapped = !report->unmapped.empty();
        dojo.edits.apply("import glTF", [&](anim::AnimationFile& file) -> Result<void> {
            file = std::move(imported);
            return ok();
        });
        if (unmapped) dojo.edits.show_message("glTF: " + summary); // in red under the clip list
        dojo.log("dojo: " + path.string() + ": " + summary, false);
    }
    ask_ = Ask::None;
    ImGui::CloseCurrentPopup();
}

void DojoGltfPrompt::prompt(const DojoContext& dojo) {
    const char* title = ask_ == Ask::Export ? "Export clip to glTF" : "Import clips from glTF";
    if (open_) ImGui::OpenPopup(title);
    open_ = false;
    if (ask_ == Ask::None || !ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    ImGui::TextUnformatted(ask_ == Ask::Export ? "Write to (.glb or .gltf):" : "Read from (.glb or .gltf):");
    std::array<char, 1024> buffer{};
    std::strncpy(buffer.data(), path_.c_str(), buffer.size() - 1);
    ImGui::SetNextItemWidth(420);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    const bool enter =
        ImGui::InputText("##gltf_path", buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    path_ = buffer.data();
    if (ask_ == Ask::Export) ImGui::Checkbox("Every clip (one animation each)", &all_clips_);
    if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.35f, 1), "%s", error_.c_str());
    if (ImGui::Button(ask_ == Ask::Export ? "Export" : "Import") || enter) run(dojo);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        ask_ = Ask::None;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace ks::editor::ui
