// The level logic in the viewport: markers for the logic entities the game does not draw (a trigger's box,
// filled faintly; a spawner's ring and post; a message's speech bubble) and the link arrows between
// entities (view/link_arrows.h): faint for every link, bright with their labels for the selection's outgoing
// links, a second colour for its incoming ones. Links to objectives and the level are in the inspector.
#include "ui/logic_overlay.h"
#include "level/entity_shapes.h"
#include "model/bounds.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace ks::editor::ui {

namespace {
const Vec4 kSpawnerMarker(1.0f, 0.45f, 0.3f, 1.0f);
const Vec4 kMessageMarker(0.65f, 0.85f, 1.0f, 1.0f);
const Vec4 kTriggerDisabled(0.6f, 0.6f, 0.65f, 1.0f);
const ImU32 kArrowFaint = IM_COL32(225, 230, 245, 150);
const ImU32 kArrowOutgoing = IM_COL32(255, 200, 60, 255);
const ImU32 kArrowIncoming = IM_COL32(80, 215, 255, 235);
constexpr int kArrowSegments = 16;

// Who sets a trigger off, by colour: the player green, robots red, both yellow.
Vec4 trigger_colour(const level::TriggerProps& trigger) {
    if (!trigger.enabled) return kTriggerDisabled;
    if (trigger.who.value == "robots") return Vec4(1.0f, 0.4f, 0.35f, 1.0f);
    if (trigger.who.value == "both") return Vec4(1.0f, 0.85f, 0.3f, 1.0f);
    return Vec4(0.35f, 1.0f, 0.5f, 1.0f);
}

ImU32 to_imgui(const Vec4& c, float alpha) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}
} // namespace

void LogicOverlay::draw_marker(render::DebugDraw& debug, const ViewCamera& view, const level::Entity& e,
                               bool selected) {
    const float alpha = selected ? 1.0f : 0.8f;
    marker_lines_.clear();
    Vec4 colour(1.0f);
    switch (e.type()) {
    case level::EntityType::Trigger: {
        colour = trigger_colour(e.as<level::TriggerProps>());
        const geometry::Obb box = entity_obb(e);
        Mat4 m(box.axes);
        m[3] = Vec4(box.center, 1.0f);
        debug.box(m, box.half, Vec4(Vec3(colour), alpha));
        return; // the faces are filled on screen (logic_overlay)
    }
    case level::EntityType::Spawner:
        colour = kSpawnerMarker;
        spawner_marker(e.position, e.rotation.x, marker_lines_);
        break;
    case level::EntityType::Message:
        colour = kMessageMarker;
        message_marker(e.position + Vec3(0, level::kLogicMarkerHalfSize, 0), view.camera.right(),
                       view.camera.up(), level::kLogicMarkerHalfSize, marker_lines_);
        break;
    default:
        return;
    }
    for (const MarkerLine& line : marker_lines_) debug.line(line.a, line.b, Vec4(Vec3(colour), alpha));
}

void LogicOverlay::update_link_arrows(const Editor& editor, bool ceilings, const Shown& shown) {
    const Document& doc = editor.doc();
    const std::uint64_t key = editor.revision() ^ (static_cast<std::uint64_t>(doc.hidden.size()) << 48) ^
                              (static_cast<std::uint64_t>(ceilings) << 63);
    if (key == arrows_key_ && doc.selection == arrows_selection_) return;
    link_arrows_ = link_arrows(editor.level(), doc.selection, shown);
    arrow_labels_.clear();
    for (const LinkArrow& arrow : link_arrows_) {
        std::string text;
        for (const auto& label : arrow.labels) text += (text.empty() ? "" : "\n") + label;
        arrow_labels_.push_back(std::move(text));
    }
    arrows_key_ = key;
    arrows_selection_ = doc.selection;
}

void LogicOverlay::draw(ImDrawList* draw, Vec2 origin, const ViewCamera& view, const Editor& editor,
                        bool links, bool ceilings, const Shown& shown) {
    const Vec2 size = view.viewport();
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    auto screen = [&](const Vec3& p, ImVec2& out) {
        Vec2 s;
        if (!view.project(p, s)) return false;
        out = ImVec2(origin.x + s.x, origin.y + s.y);
        return true;
    };
    // Trigger boxes: the faces toward the camera, filled faintly over the picture.
    for (const auto& e : editor.level().entities) {
        if (e.type() != level::EntityType::Trigger || !shown(e)) continue;
        const geometry::Obb box = entity_obb(e);
        const auto faces = box_faces(box);
        const ImU32 fill = to_imgui(trigger_colour(e.as<level::TriggerProps>()),
                                    editor.doc().is_selected(e.id) ? 0.16f : 0.09f);
        for (size_t f = 0; f < faces.size(); ++f) {
            const Vec3 normal = box.axes[static_cast<int>(f / 2)] * (f % 2 == 0 ? -1.0f : 1.0f);
            const Vec3 face_centre = (faces[f][0] + faces[f][2]) * 0.5f;
            const Vec3 toward = view.orthographic() ? -view.forward() : view.camera.position - face_centre;
            if (glm::dot(normal, toward) <= 0.0f) continue;
            ImVec2 q[4];
            if (!screen(faces[f][0], q[0]) || !screen(faces[f][1], q[1]) || !screen(faces[f][2], q[2]) ||
                !screen(faces[f][3], q[3]))
                continue;
            draw->AddQuadFilled(q[0], q[1], q[2], q[3], fill);
        }
    }
    if (links) {
        update_link_arrows(editor, ceilings, shown);
        for (int pass = 0; pass < 2; ++pass) // the faint ones first, the selection's over them
            for (const LinkArrow& arrow : link_arrows_) {
                const bool bright = arrow.role != ArrowRole::Other;
                if (bright != (pass == 1)) continue;
                const ImU32 colour = arrow.role == ArrowRole::Outgoing   ? kArrowOutgoing
                                     : arrow.role == ArrowRole::Incoming ? kArrowIncoming
                                                                         : kArrowFaint;
                marker_lines_.clear();
                arrow_lines(arrow, kArrowSegments, marker_lines_);
                for (const MarkerLine& line : marker_lines_) {
                    ImVec2 a, b;
                    if (screen(line.a, a) && screen(line.b, b))
                        draw->AddLine(a, b, colour, bright ? 2.5f : 1.5f);
                }
            }
        for (size_t i = 0; i < link_arrows_.size(); ++i) { // labels last: over every line
            ImVec2 at;
            if (link_arrows_[i].role != ArrowRole::Outgoing || !screen(link_arrows_[i].middle(), at))
                continue;
            const std::string& text = arrow_labels_[i];
            const ImVec2 extent = ImGui::CalcTextSize(text.c_str());
            const ImVec2 corner(at.x - extent.x * 0.5f, at.y - extent.y - 6.0f);
            draw->AddRectFilled(ImVec2(corner.x - 4, corner.y - 2),
                                ImVec2(corner.x + extent.x + 4, corner.y + extent.y + 2),
                                IM_COL32(15, 17, 22, 200), 4.0f);
            draw->AddText(corner, kArrowOutgoing, text.c_str());
        }
    }
    draw->PopClipRect();
}

} // namespace ks::editor::ui
