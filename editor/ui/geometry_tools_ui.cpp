// The geometry tools in the window: geometry_tools_ui.h.
#include "ui/geometry_tools_ui.h"

#include "model/bounds.h"
#include "model/edit_selection.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <vector>

namespace ks::editor::ui {
namespace {

const char* tool_name(GeometryTool tool) {
    switch (tool) {
    case GeometryTool::draw:
        return "draw";
    case GeometryTool::clip:
        return "clip";
    case GeometryTool::measure:
        return "measure";
    case GeometryTool::vertex:
        return "vertex";
    case GeometryTool::none:
        return "none";
    }
    return "none";
}

const char* stage_name(DrawStage stage) {
    switch (stage) {
    case DrawStage::idle:
        return "idle";
    case DrawStage::dragging:
        return "dragging";
    case DrawStage::placing_points:
        return "placing_points";
    case DrawStage::extruding:
        return "extruding";
    }
    return "idle";
}

ImU32 line_colour(ToolLine kind) {
    switch (kind) {
    case ToolLine::shape:
        return IM_COL32(120, 255, 140, 235);
    case ToolLine::cut:
        return IM_COL32(255, 90, 200, 255);
    case ToolLine::guide:
        return IM_COL32(255, 225, 90, 235);
    }
    return IM_COL32(255, 255, 255, 255);
}

nlohmann::json vec_json(const DVec3& v) {
    return {v.x, v.y, v.z};
}

// Text on a dark box, so a label reads over any picture.
void label(ImDrawList* draw, ImVec2 at, const std::string& text, ImU32 colour) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    draw->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2),
                        IM_COL32(15, 17, 22, 200), 3.0f);
    draw->AddText(at, colour, text.c_str());
}

// The selected entities' bounds, the range a brush drawn in an axis view takes along the view's axis.
std::optional<std::array<DVec3, 2>> selection_range(const Editor& editor) {
    const auto selected = selected_entities(editor);
    if (selected.empty()) return std::nullopt;
    const geometry::Aabb box = selection_bounds(selected);
    return std::array<DVec3, 2>{DVec3(box.min), DVec3(box.max)};
}

} // namespace

void GeometryToolsUi::choose(GeometryTool tool) {
    active_ = tool == active_ ? GeometryTool::none : tool;
    draw_.cancel();
    clip_.reset();
    measure_.reset();
    vertex_.reset();
    match_face_ = false;
}

void GeometryToolsUi::buttons(UiSpots& spots) {
    static constexpr std::pair<GeometryTool, const char*> kButtons[] = {{GeometryTool::draw, "Draw"},
                                                                        {GeometryTool::clip, "Clip"},
                                                                        {GeometryTool::measure, "Measure"},
                                                                        {GeometryTool::vertex, "Vertex"}};
    static constexpr const char* kTips[] = {
        "Draw a brush: drag a box, or click a polygon and extrude it (B; B again: box / polygon)",
        "Clip the selected brushes by 2 or 3 points or a face (C; Tab: side kept, Enter: clip)",
        "Measure between two points on vertices, faces or the grid (M)",
        "Edit the selected brushes' vertices, edges or faces: drag, split, merge (V; V again: the next "
        "mode)"};
    for (size_t i = 0; i < 4; ++i) {
        const auto [tool, text] = kButtons[i];
        const bool on = active_ == tool;
        if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.26f, 0.45f, 0.75f, 1));
        if (ImGui::SmallButton(text)) choose(tool);
        if (on) ImGui::PopStyleColor();
        spots.here(std::string("tool.") + tool_name(tool));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kTips[i]);
        if (i < 3) ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    }
}

void GeometryToolsUi::bar(Editor& editor, EditorLog& log, Vec2 origin, Vec2 size, UiSpots& spots) {
    // Kept off the crowded tool bar at the top: over the picture's bottom right (the status line holds the
    // bottom left), growing left and upward: the buttons, then the active tool's options and what it says.
    ImGui::SetNextWindowPos(ImVec2(origin.x + size.x - 8, origin.y + size.y - 32), ImGuiCond_Always,
                            ImVec2(1.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
    ImGui::Begin("##geometry_tools", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PopStyleVar();
    buttons(spots);
    if (active_ == GeometryTool::draw) {
        draw_.grid = editor.doc().grid.step;
        for (DrawShape shape : {DrawShape::box, DrawShape::polygon}) {
            ImGui::SameLine();
            if (ImGui::RadioButton(shape == DrawShape::box ? "Box" : "Polygon", draw_.shape == shape)) {
                draw_.cancel();
                draw_.shape = shape;
            }
            spots.here(shape == DrawShape::box ? "tool.box" : "tool.polygon");
        }
        ImGui::SameLine();
        double height = draw_.height();
        ImGui::SetNextItemWidth(80);
        if (ImGui::InputDouble("height", &height, 0.0, 0.0, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue))
            draw_.set_height(height);
        spots.here("tool.height");
    } else if (active_ == GeometryTool::clip) {
        ImGui::SameLine();
        const std::string keep = std::string("Keep: ") + clip_keep_name(clip_.keep());
        if (ImGui::SmallButton(keep.c_str())) clip_.cycle_keep();
        spots.here("tool.keep");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The side of the plane kept: back, front or both (Tab)");
        ImGui::SameLine();
        if (ImGui::Checkbox("Match face", &match_face_) && match_face_) clip_.reset();
        spots.here("tool.match_face");
        ImGui::SameLine();
        if (ImGui::SmallButton("Apply")) enter(editor, log); // not "Clip": the tool button above has that id
        spots.here("tool.apply");
        ImGui::SameLine();
        if (ImGui::SmallButton("Reset")) clip_.reset();
    } else if (active_ == GeometryTool::vertex) {
        vertex_.options(spots);
    }
    if (active_ != GeometryTool::none) {
        const ToolPreview shown = preview(editor.doc());
        if (!shown.problem.empty())
            ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s", shown.problem.c_str());
        ImGui::TextDisabled("%s", shown.hint.c_str());
    }
    ImGui::End();
}

ToolPreview GeometryToolsUi::preview(const Document& doc) const {
    switch (active_) {
    case GeometryTool::draw:
        return draw_.preview();
    case GeometryTool::clip:
        return clip_.preview(doc);
    case GeometryTool::measure:
        return measure_.preview();
    case GeometryTool::vertex:
        return vertex_.tool().preview(doc);
    case GeometryTool::none:
        break;
    }
    return {};
}

void GeometryToolsUi::draw_mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse,
                                 bool hovered, const ShownFn& shown) {
    draw_.grid = editor.doc().grid.step;
    const bool axis_view = view_axis(view).has_value();
    if (draw_.stage() == DrawStage::dragging) {
        if (auto p = point_on_plane(editor.doc(), view, mouse, draw_.plane())) draw_.move(*p);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            auto placed = draw_.release(editor);
            if (!placed) log.line(placed.error().str(), true);
        }
        return;
    }
    if (draw_.stage() == DrawStage::extruding) {
        if (!axis_view) draw_.extrude_toward(view.ray(mouse));
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) enter(editor, log);
        return;
    }
    if (!hovered || !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    if (draw_.stage() == DrawStage::placing_points) {
        // A click near the first corner (its vertex snap) closes; others land on the polygon's plane.
        const auto p = point_on_plane(editor.doc(), view, mouse, draw_.plane());
        if (!p) return;
        Vec2 first;
        const bool near_first =
            view.project(Vec3(draw_.points().front()), first) && glm::length(first - mouse) < 8.0f;
        auto added = draw_.add_point(draw_.plane(), near_first ? draw_.points().front() : *p);
        if (!added) log.line(added.error().str(), true);
        return;
    }
    const auto at = tool_point(editor.doc(), view, mouse, shown, {!axis_view, !axis_view});
    if (!at) return;
    const DrawPlane plane = draw_plane_at(*at, view);
    draw_.reference = selection_range(editor);
    if (draw_.shape == DrawShape::box) {
        draw_.press(plane, at->point);
    } else if (auto added = draw_.add_point(plane, at->point); !added) {
        log.line(added.error().str(), true);
    }
}

void GeometryToolsUi::mouse(Editor& editor, EditorLog& log, const ViewCamera& view, Vec2 mouse, bool hovered,
                            const ShownFn& shown) {
    hover_.reset();
    if (active_ == GeometryTool::vertex) return vertex_.mouse(editor, log, view, mouse, hovered);
    if (hovered) hover_ = tool_point(editor.doc(), view, mouse, shown);
    switch (active_) {
    case GeometryTool::draw:
        draw_mouse(editor, log, view, mouse, hovered, shown);
        return;
    case GeometryTool::clip:
        clip_.set_view_direction(view_axis(view) ? std::optional<DVec3>(DVec3(view.forward()))
                                                 : std::nullopt);
        if (!hovered || !hover_ || !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
        if (match_face_) {
            if (!hover_->face) {
                log.line("Clip: no face under the mouse to match (click a brush's face)", true);
                return;
            }
            clip_.match_face(*hover_->face);
            match_face_ = false;
            return;
        }
        if (auto added = clip_.add_point(hover_->point); !added) log.line(added.error().str(), true);
        return;
    case GeometryTool::measure:
        measure_.hover(hover_ ? std::optional<DVec3>(hover_->point) : std::nullopt);
        if (hovered && hover_ && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
            measure_.add_point(hover_->point);
            if (measure_.finished()) log.line("Measure: " + measurement_text(*measure_.measurement()));
        }
        return;
    case GeometryTool::vertex:
    case GeometryTool::none:
        return;
    }
}

void GeometryToolsUi::enter(Editor& editor, EditorLog& log) {
    if (active_ == GeometryTool::draw && draw_.shape == DrawShape::polygon && draw_.busy()) {
        auto placed = draw_.commit(editor);
        if (!placed) log.line(placed.error().str(), true);
    } else if (active_ == GeometryTool::clip) {
        if (auto clipped = clip_.apply(editor); !clipped) log.line(clipped.error().str(), true);
    }
}

bool GeometryToolsUi::keys(Editor& editor, EditorLog& log, bool ctrl) {
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (ctrl) return false;
    if (pressed(GLFW_KEY_B)) {
        if (active_ == GeometryTool::draw && !draw_.busy()) // B again: box or polygon
            draw_.shape = draw_.shape == DrawShape::box ? DrawShape::polygon : DrawShape::box;
        else
            choose(GeometryTool::draw);
        return true;
    }
    if (pressed(GLFW_KEY_C)) return choose(GeometryTool::clip), true;
    if (pressed(GLFW_KEY_M)) return choose(GeometryTool::measure), true;
    const bool v = pressed(GLFW_KEY_V);
    if (v && active_ != GeometryTool::vertex) return choose(GeometryTool::vertex), true;
    if (active_ == GeometryTool::vertex && vertex_.keys(editor, log, v)) return true;
    if (active_ == GeometryTool::none) return false;
    if (pressed(GLFW_KEY_ESCAPE)) { // the step under way first, then the tool
        const bool busy = active_ == GeometryTool::draw      ? draw_.busy()
                          : active_ == GeometryTool::clip    ? clip_.busy() || match_face_
                          : active_ == GeometryTool::measure ? measure_.busy()
                                                             : false; // the vertex tool's Esc: its keys()
        if (busy) {
            draw_.cancel(), clip_.reset(), measure_.reset();
            match_face_ = false;
        } else {
            choose(GeometryTool::none);
        }
        return true;
    }
    if (pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_KP_ENTER)) return enter(editor, log), true;
    if (active_ == GeometryTool::clip && pressed(GLFW_KEY_TAB)) return clip_.cycle_keep(), true;
    if (active_ == GeometryTool::draw) {
        if (pressed(GLFW_KEY_BACKSPACE)) return draw_.remove_last_point(), true;
        if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET, true)) return draw_.step_height(+1), true;
        if (ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET, true)) return draw_.step_height(-1), true;
    }
    return false;
}

void GeometryToolsUi::draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Document& doc) const {
    if (active_ == GeometryTool::none) return;
    const ToolPreview shown = preview(doc);
    if (active_ == GeometryTool::vertex) vertex_.draw(draw, origin, view, doc);
    auto screen = [&](const DVec3& p, ImVec2& out) {
        Vec2 s;
        if (!view.project(Vec3(p), s)) return false;
        out = ImVec2(origin.x + s.x, origin.y + s.y);
        return true;
    };
    for (const ToolSegment& s : shown.segments) {
        ImVec2 a, b;
        if (screen(s.a, a) && screen(s.b, b)) draw->AddLine(a, b, line_colour(s.kind), 2.0f);
    }
    // Labels of a small box crowd one spot: each moves down past those drawn before it.
    std::vector<std::pair<ImVec2, ImVec2>> taken;
    for (const ToolLabel& l : shown.labels) {
        ImVec2 at;
        if (!screen(l.at, at)) continue;
        at = ImVec2(at.x + 6, at.y - 16);
        const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
        for (bool moved = true; moved;) {
            moved = false;
            for (const auto& [lo, hi] : taken)
                if (at.x < hi.x && at.x + size.x + 6 > lo.x && at.y < hi.y && at.y + size.y + 4 > lo.y)
                    at.y = hi.y + 1, moved = true;
        }
        taken.push_back({ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2)});
        label(draw, at, l.text, IM_COL32(255, 255, 255, 255));
    }
    ImVec2 at;
    if (hover_ && screen(hover_->point, at)) { // the point a click would take, shaped by its kind
        const ImU32 colour = IM_COL32(255, 225, 90, 255);
        if (hover_->kind == PointKind::vertex)
            draw->AddCircle(at, 6.0f, colour, 12, 2.0f);
        else if (hover_->kind == PointKind::face)
            draw->AddRect(ImVec2(at.x - 5, at.y - 5), ImVec2(at.x + 5, at.y + 5), colour, 0.0f, 0, 2.0f);
        else
            draw->AddLine(ImVec2(at.x - 6, at.y), ImVec2(at.x + 6, at.y), colour, 2.0f),
                draw->AddLine(ImVec2(at.x, at.y - 6), ImVec2(at.x, at.y + 6), colour, 2.0f);
    }
}

void GeometryToolsUi::status(nlohmann::json& status, const Document& doc) const {
    nlohmann::json tool = {{"active", tool_name(active_)}};
    const ToolPreview shown = preview(doc);
    tool["problem"] = shown.problem;
    tool["hint"] = shown.hint;
    nlohmann::json labels = nlohmann::json::array();
    for (const ToolLabel& l : shown.labels) labels.push_back(l.text);
    tool["labels"] = labels;
    tool["segments"] = shown.segments.size();
    tool["draw"] = {{"shape", draw_.shape == DrawShape::box ? "box" : "polygon"},
                    {"stage", stage_name(draw_.stage())},
                    {"points", draw_.points().size()},
                    {"height", draw_.height()}};
    if (const auto d = draw_.dimensions()) tool["draw"]["dimensions"] = vec_json(*d);
    tool["clip"] = {{"keep", clip_keep_name(clip_.keep())},
                    {"points", clip_.points().size()},
                    {"match_face", match_face_}};
    if (const auto plane = clip_.plane())
        tool["clip"]["plane"] = {plane->normal.x, plane->normal.y, plane->normal.z, plane->distance};
    if (const auto m = measure_.measurement())
        tool["measure"] = {
            {"distance", m->distance}, {"angle", m->rise_degrees}, {"text", measurement_text(*m)}};
    vertex_.status(tool, doc);
    if (hover_) tool["hover"] = {{"kind", point_kind_name(hover_->kind)}, {"point", vec_json(hover_->point)}};
    status["tool"] = tool;
}

void GeometryToolsUi::status_on_screen(nlohmann::json& status, const Document& doc, const ViewCamera& view,
                                       Vec2 origin) const {
    if (active_ == GeometryTool::vertex) vertex_.status_on_screen(status["tool"], doc, view, origin);
}

} // namespace ks::editor::ui
