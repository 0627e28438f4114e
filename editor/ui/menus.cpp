// The editor window's menu bar: File, Edit, Brush (face_inspector.cpp), View, Play, Help and the Level / Dojo
// tabs.
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "ui/dojo_panel.h"
#include "ui/editor_app.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace ks::editor::ui {

namespace {
Vec2 item_centre() {
    return Vec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f,
                (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f);
}
} // namespace

void EditorApp::menu_bar() {
    if (!ImGui::BeginMainMenuBar()) return;
    const bool file_menu = ImGui::BeginMenu("File");
    menu_spots_[0] = item_centre();
    menu_spots_[1] = Vec2(0.0f);
    if (file_menu) {
        if (ImGui::MenuItem("New", "Ctrl+N")) request(PendingAction::New);
        if (ImGui::MenuItem("Open...", "Ctrl+O")) request(PendingAction::Open);
        if (ImGui::BeginMenu("Open Recent", !recent_.entries().empty())) {
            for (const auto& entry : recent_.entries())
                if (ImGui::MenuItem(entry.string().c_str())) request(PendingAction::OpenRecent, entry);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) files_.save(false);
        if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) files_.save(true);
        if (ImGui::MenuItem("Add to Campaign...")) files_.open_campaign_prompt();
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) request(PendingAction::Quit);
        menu_spots_[1] = item_centre();
        ImGui::EndMenu();
    }
    const bool edit_menu = ImGui::BeginMenu("Edit");
    spots_.here("menu.edit");
    if (edit_menu) {
        if (dojo_tab_) { // the clip file's history, as Ctrl+Z in the tab
            const auto& h = dojo_->history();
            if (ImGui::MenuItem(("Undo " + h.undo_name()).c_str(), "Ctrl+Z", false, h.can_undo()))
                dojo_->undo();
            if (ImGui::MenuItem(("Redo " + h.redo_name()).c_str(), "Ctrl+Shift+Z", false, h.can_redo()))
                dojo_->redo();
        } else {
            const auto& h = editor_.history();
            if (ImGui::MenuItem(("Undo " + h.undo_name()).c_str(), "Ctrl+Z", false, h.can_undo()))
                editor_.undo();
            if (ImGui::MenuItem(("Redo " + h.redo_name()).c_str(), "Ctrl+Shift+Z", false, h.can_redo()))
                editor_.redo();
        }
        ImGui::Separator();
        const bool any = !editor_.doc().selection.empty();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any)) report(duplicate(editor_), "duplicate");
        if (ImGui::MenuItem("Delete", "Del", false, any)) report(delete_selection(editor_), "delete");
        if (ImGui::MenuItem("Copy", "Ctrl+C", false, any))
            glfwSetClipboardString(shell_.window(), copy(editor_).c_str());
        if (ImGui::MenuItem("Paste", "Ctrl+V")) {
            const char* text = glfwGetClipboardString(shell_.window());
            report(text ? paste_text(editor_, text) : paste(editor_), "paste");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Select All", "Ctrl+A")) select_all(editor_);
        if (ImGui::BeginMenu("Select All of Type")) {
            for (auto type : level::all_types())
                if (ImGui::MenuItem(std::string(level::type_name(type)).c_str()))
                    select_all_of_type(editor_, type);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Select None", "Esc")) editor_.clear_selection();
        ImGui::Separator();
        structure_menu_items();
        ImGui::Separator();
        auto& grid = editor_.grid();
        ImGui::Checkbox("Snap to grid", &grid.snap);
        ImGui::SetNextItemWidth(90);
        ImGui::DragFloat("Grid step", &grid.step, 0.05f, 0.05f, 16.0f, "%.2f");
        ImGui::SetNextItemWidth(90);
        ImGui::DragFloat("Rotation step", &grid.rotation_step, 0.5f, 1.0f, 90.0f, "%.0f deg");
        ImGui::EndMenu();
    }
    brush_menu_.draw(context());
    if (ImGui::BeginMenu("View")) {
        viewport_.view_menu();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Play")) {
        if (ImGui::MenuItem("Play from start", "F5", false, !play_.running()))
            play_.start(editor_.level(), nullptr);
        if (ImGui::MenuItem("Play from camera", "Shift+F5", false, !play_.running()))
            play_.start(editor_.level(), &viewport_.camera());
        if (ImGui::MenuItem("Stop play-test", nullptr, false, play_.running())) play_.stop();
        ImGui::Separator();
        if (ImGui::MenuItem("Analyze (bot play-tests)", nullptr, false, !analysis_.running()))
            analysis_.start(editor_.level(), editor_.file_path());
        if (ImGui::MenuItem("Cancel analysis", nullptr, false, analysis_.running())) analysis_.cancel();
        ImGui::MenuItem("Show play-test report", nullptr, &analysis_.overlay, analysis_.report() != nullptr);
        ImGui::EndMenu();
    }
    about_.menu(spots_);
    ImGui::Separator();
    if (ImGui::RadioButton("Level", !dojo_tab_)) dojo_tab_ = false;
    spots_.here("tab.level");
    if (ImGui::RadioButton("Dojo", dojo_tab_)) {
        dojo_tab_ = true;
        logic_.end_pick(); // the level's viewport, where the pick would land, is gone
    }
    spots_.here("tab.dojo");
    ImGui::Separator();
    const std::string status = title(editor_);
    ImGui::TextDisabled("%s", status.c_str());
    ImGui::EndMainMenuBar();
}
} // namespace ks::editor::ui
