// Pick mode: a link row's Pick button (or an objective's kill list's) makes the next left click on an entity
// in the viewport the link's target (naming the entity if it has no name) or a name to kill, in one undo
// step. Esc or a right click cancels; a click on something that cannot be the target says why and leaves
// everything as it was, still picking. The cursor is a crosshair meanwhile.
#include "ui/logic_panels.h"
#include "view/link_options.h"

#include <nlohmann/json.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace ks::editor::ui {

LogicPanels::~LogicPanels() {
    if (crosshair_) glfwDestroyCursor(crosshair_);
}

void LogicPanels::begin_pick(PickRequest request) {
    pick_ = std::move(request); // the window stops placing while picking (EditorApp::build_ui)
    pick_message_ = pick_->purpose == PickPurpose::LinkTarget
                        ? "Click the link's target in the viewport  (Esc or right click: cancel)"
                        : "Click a robot or spawner to kill in the viewport  (Esc or right click: cancel)";
    if (!crosshair_) crosshair_ = glfwCreateStandardCursor(GLFW_CROSSHAIR_CURSOR);
    ImGui::GetIO().ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange; // ImGui's backend leaves ours alone
    if (crosshair_) glfwSetCursor(window_, crosshair_);
}

void LogicPanels::end_pick() {
    if (!pick_) return;
    pick_.reset();
    pick_message_.clear();
    ImGui::GetIO().ConfigFlags &= ~ImGuiConfigFlags_NoMouseCursorChange;
    glfwSetCursor(window_, nullptr);
}

void LogicPanels::pick_click(int entity_id) {
    if (!pick_) return;
    const level::Level& level = editor_.level();
    if (entity_id == 0) {
        pick_message_ = "Nothing there: click an entity  (Esc or right click: cancel)";
        return;
    }
    const level::Entity* e = level.find(entity_id);
    if (pick_->purpose == PickPurpose::LinkTarget) {
        if (auto refusal = pick_refusal(level, entity_id)) {
            pick_message_ = *refusal + "  (Esc: cancel)";
            log_line("pick: " + *refusal + "; the link is unchanged");
            return;
        }
        const Result<void> r = apply_link_target(pick_->owner, pick_->index,
                                                 {level::TargetKind::Entity, e->name, entity_id, {}});
        report(r, "pick target");
    } else {
        if (auto refusal = kill_refusal(level, entity_id)) {
            pick_message_ = *refusal + "  (Esc: cancel)";
            log_line("pick: " + *refusal + "; the kill list is unchanged");
            return;
        }
        report(add_kill_name(pick_->index, entity_id), "pick to kill");
    }
    end_pick();
}

// While picking: the hint over the viewport and the crosshair (set again each frame: leaving the window
// and coming back resets the cursor).
void LogicPanels::pick_hint(ImDrawList* draw, Vec2 origin) {
    if (!pick_) return;
    if (crosshair_) glfwSetCursor(window_, crosshair_);
    const ImVec2 at(origin.x + 12, origin.y + 8);
    const ImVec2 extent = ImGui::CalcTextSize(pick_message_.c_str());
    draw->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + extent.x + 4, at.y + extent.y + 2),
                        IM_COL32(15, 17, 22, 200), 4.0f);
    draw->AddText(at, IM_COL32(255, 210, 90, 255), pick_message_.c_str());
}

void LogicPanels::pick_status(nlohmann::json& s) const {
    s["pick"] = {{"active", pick_.has_value()},
                 {"purpose", !pick_                                      ? ""
                             : pick_->purpose == PickPurpose::LinkTarget ? "link_target"
                                                                         : "kill"},
                 {"message", pick_message_}};
}

} // namespace ks::editor::ui
