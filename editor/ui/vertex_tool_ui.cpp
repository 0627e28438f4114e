// The vertex tool in the window: vertex_tool_ui.h.
#include "ui/vertex_tool_ui.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace ks::editor::ui {
namespace {

bool is_selected(const VertexTool& tool, const DVec3& at) {
    return std::any_of(tool.selected().begin(), tool.selected().end(),
                       [&](const DVec3& p) { return glm::length(p - at) <= 1e-6; });
}

nlohmann::json point_json(const DVec3& v) {
    return {v.x, v.y, v.z};
}

} // namespace

void VertexToolUi::reset() {
    tool_.cancel();
    tool_.clear_selection();
    hover_.reset();
    box_from_.reset();
}

void VertexToolUi::options(UiSpots& spots) {
    for (VertexMode mode : {VertexMode::vertex, VertexMode::edge, VertexMode::face}) {
        ImGui::SameLine();
        const char* name = mode == VertexMode::vertex ? "Vertex" : mode == VertexMode::edge ? "Edge" : "Face";
        if (ImGui::RadioButton(name, tool_.mode() == mode)) tool_.set_mode(mode);
        spots.here(std::string("tool.vertex_mode.") + vertex_mode_name(mode));
    }
}

void VertexToolUi::mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse, bool hovered) {
    const Document& doc = editor.doc();
    if (tool_.dragging()) {
        if (const auto delta = vertex_drag_delta(doc, view, mouse, drag_)) {
            if (*delta != tool_.delta())
                tool_.drag(doc, *delta); // the hull only when the snapped point moves
        }
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left))
            if (auto released = tool_.release(editor); !released) log.line(released.error().str(), true);
        return;
    }
    if (box_from_) {
        box_to_ = mouse;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
        const auto handles = tool_.handles(doc);
        for (const DVec3& at : handles_in_rect(handles, view, *box_from_, mouse))
            if (!is_selected(tool_, at)) (void)tool_.select(doc, at, true);
        box_from_.reset();
        return;
    }
    hover_.reset();
    if (!hovered) return;
    hover_ = handle_under(tool_.handles(doc), view, mouse);
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    const bool add = ImGui::GetIO().KeyShift;
    if (!hover_) { // a box select, from empty space
        if (!add) tool_.clear_selection();
        box_from_ = mouse;
        box_to_ = mouse;
        view_id_ = static_cast<int>(view.mode);
        return;
    }
    if (add && !hover_->split && is_selected(tool_, hover_->at)) { // Shift-click drops a selected handle
        (void)tool_.select(doc, hover_->at, true);
        return;
    }
    if (auto grabbed = tool_.grab(doc, hover_->at, add); !grabbed) {
        log.line(grabbed.error().str(), true);
        return;
    }
    drag_ = start_vertex_drag(doc, view, mouse, hover_->at, tool_.mode() == VertexMode::vertex);
}

bool VertexToolUi::keys(Editor& editor, EditorLog& log, bool v_pressed) {
    if (v_pressed) {
        tool_.cycle_mode();
        return true;
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_DELETE, false)) {
        if (auto removed = tool_.remove_selected(editor); !removed) log.line(removed.error().str(), true);
        return true;
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false) && (tool_.dragging() || !tool_.selected().empty())) {
        if (tool_.dragging())
            tool_.cancel();
        else
            tool_.clear_selection();
        return true;
    }
    return false;
}

void VertexToolUi::draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Document& doc) const {
    for (const VertexHandle& h : tool_.handles(doc)) {
        Vec2 s;
        if (!view.project(Vec3(h.at), s)) continue;
        const ImVec2 at(origin.x + s.x, origin.y + s.y);
        if (h.split) {
            draw->AddCircle(at, 3.0f, IM_COL32(160, 200, 255, 220), 8, 1.5f);
        } else if (is_selected(tool_, h.at)) {
            draw->AddCircleFilled(at, 5.0f, IM_COL32(255, 80, 60, 255), 12);
        } else {
            draw->AddCircleFilled(at, 4.0f, IM_COL32(235, 240, 250, 235), 12);
            draw->AddCircle(at, 4.0f, IM_COL32(20, 20, 28, 255), 12, 1.0f);
        }
    }
    Vec2 s;
    if (hover_ && view.project(Vec3(hover_->at), s))
        draw->AddCircle(ImVec2(origin.x + s.x, origin.y + s.y), 8.0f, IM_COL32(255, 225, 90, 255), 16, 2.0f);
    if (box_from_ && view_id_ == static_cast<int>(view.mode)) {
        const ImVec2 a(origin.x + box_from_->x, origin.y + box_from_->y),
            b(origin.x + box_to_.x, origin.y + box_to_.y);
        draw->AddRectFilled(a, b, IM_COL32(255, 120, 90, 40));
        draw->AddRect(a, b, IM_COL32(255, 120, 90, 200));
    }
}

void VertexToolUi::status(nlohmann::json& tool, const Document& doc) const {
    nlohmann::json selected = nlohmann::json::array();
    for (const DVec3& p : tool_.selected()) selected.push_back(point_json(p));
    tool["vertex"] = {{"mode", vertex_mode_name(tool_.mode())},
                      {"handles", tool_.handles(doc).size()},
                      {"selected", selected},
                      {"dragging", tool_.dragging()},
                      {"delta", point_json(tool_.delta())},
                      {"moved", tool_.moved().size()}};
}

void VertexToolUi::status_on_screen(nlohmann::json& tool, const Document& doc, const ViewCamera& view,
                                    Vec2 origin) const {
    nlohmann::json screen = nlohmann::json::array();
    for (const VertexHandle& h : tool_.handles(doc)) {
        Vec2 s;
        if (screen.size() >= 64 || !view.project(Vec3(h.at), s)) continue;
        screen.push_back(
            {{"at", point_json(h.at)}, {"screen", {origin.x + s.x, origin.y + s.y}}, {"split", h.split}});
    }
    tool["vertex"]["screen"] = screen;
}

} // namespace ks::editor::ui
