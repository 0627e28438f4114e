// The selected brush faces in the editor window (face_inspector.h): the inspector's Faces section, the Brush
// menu and the status file's face selection. Every button is one edit of edit_faces.h or edit_brushes.h;
// a dragged number merges into one step until the drag ends.
#include "ui/face_inspector.h"

#include "brush/texture_mapping.h"
#include "level/entity_shapes.h"
#include "model/edit_brushes.h"
#include "model/edit_faces.h"
#include "ui/texture_browser.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {
namespace {

// Ends a dragged number's step when the drag or the typing ends (one drag = one undo step).
void end_step_after(Editor& editor) {
    if (ImGui::IsItemDeactivatedAfterEdit()) editor.end_merging();
}

class FaceSection final : public InspectorSection {
  public:
    // Always asked: the face selection lives in the document, not in InspectorSelection; draw() shows
    // nothing while no face is selected.
    bool applies(const InspectorSelection&) const override { return true; }
    void draw(const PanelContext& ctx, InspectorSelection&, FieldWidgets&) override {
        const auto faces = selected_faces(ctx.editor.doc());
        if (faces.empty()) {
            browser_.close();
            return;
        }
        const SelectedFace& primary = faces.front();
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "Faces: %zu selected", faces.size());
        ImGui::SameLine();
        if (ImGui::SmallButton("Clear")) clear_face_selection(ctx.editor);
        ctx.spots.here("face.clear");
        ImGui::TextDisabled("brush #%d face %d (Ctrl+Shift+click picks faces)", primary.entity->id,
                            primary.index);
        material_row(ctx, primary);
        numbers(ctx, primary.face.attributes);
        actions(ctx);
        replace_row(ctx, primary.face.attributes.material);
        ImGui::Separator();
        if (auto picked = browser_.draw(
                ctx.assets, primary.face.attributes.material,
                Vec2(ImGui::GetWindowPos().x - TextureBrowser::width() - 8.0f, ImGui::GetWindowPos().y),
                ctx.spots)) {
            ctx.report(set_face_material(ctx.editor, *picked), "face material");
            ctx.editor.end_merging();
        }
    }

  private:
    void material_row(const PanelContext& ctx, const SelectedFace& primary) {
        const std::string& material = primary.face.attributes.material;
        if (ImTextureID thumb = TextureBrowser::thumbnail(ctx.assets, material)) {
            if (ImGui::ImageButton(thumb, ImVec2(32, 32))) browser_.open();
        } else if (ImGui::Button("?", ImVec2(40, 40))) {
            browser_.open();
        }
        ctx.spots.here("face.material");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Pick the material from the texture browser");
        ImGui::SameLine();
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(material.c_str());
    }

    static void numbers(const PanelContext& ctx, const brush::FaceAttributes& at) {
        Editor& editor = ctx.editor;
        float offset[2] = {static_cast<float>(at.offset.x), static_cast<float>(at.offset.y)};
        ImGui::SetNextItemWidth(-90);
        if (ImGui::DragFloat2("offset", offset, 0.01f, 0.0f, 0.0f, "%.3f"))
            ctx.report(set_face_offset(editor, {offset[0], offset[1]}, "face:offset"), "face offset");
        end_step_after(editor);
        float scale[2] = {static_cast<float>(at.scale.x), static_cast<float>(at.scale.y)};
        ImGui::SetNextItemWidth(-90);
        if (ImGui::DragFloat2("scale", scale, 0.01f, 0.0f, 0.0f, "%.3f"))
            ctx.report(set_face_scale(editor, {scale[0], scale[1]}, "face:scale"), "face scale");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("World units per texture repeat along u and v");
        end_step_after(editor);
        float rotation = static_cast<float>(at.rotation_degrees);
        ImGui::SetNextItemWidth(-90);
        if (ImGui::DragFloat("rotation", &rotation, 0.5f, 0.0f, 0.0f, "%.1f deg"))
            ctx.report(set_face_rotation(editor, rotation, "face:rotation"), "face rotation");
        end_step_after(editor);
    }

    void actions(const PanelContext& ctx) {
        Editor& editor = ctx.editor;
        if (ImGui::Button("Fit")) ctx.report(fit_face_texture(editor), "fit");
        ctx.spots.here("face.fit");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The texture once across each selected face");
        ImGui::SameLine();
        if (ImGui::Button("Align to edge")) ctx.report(align_face_texture_to_edge(editor, edge_), "align");
        ctx.spots.here("face.align");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(80);
        ImGui::InputInt("edge", &edge_);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Which edge of the face, counting its corners counter-clockwise from 0");
        if (ImGui::Button("Copy")) ctx.report(copy_face_attributes(editor), "copy face");
        ctx.spots.here("face.copy");
        ImGui::SameLine();
        const bool copied = editor.face_session().copied.has_value();
        ImGui::BeginDisabled(!copied);
        if (ImGui::Button("Paste")) ctx.report(paste_face_attributes(editor), "paste face");
        ImGui::EndDisabled();
        ctx.spots.here("face.paste");
        if (!copied && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("Copy a face's attributes first");
        ImGui::SameLine();
        bool lock = editor.face_session().texture_lock;
        if (ImGui::Checkbox("Pin to world", &lock)) set_texture_lock(editor, lock);
        ctx.spots.here("face.lock");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "On: moving or turning a brush keeps its textures where they are on the world.\n"
                "Off: textures travel with the brush.");
    }

    void replace_row(const PanelContext& ctx, const std::string& current) {
        if (!ImGui::CollapsingHeader("Replace texture across the level")) return;
        if (from_[0] == '\0') std::snprintf(from_, sizeof from_, "%s", current.c_str());
        ImGui::SetNextItemWidth(-90);
        ImGui::InputText("replace", from_, sizeof from_);
        ImGui::SetNextItemWidth(-90);
        ImGui::InputText("with", to_, sizeof to_);
        if (ImGui::Button("Replace everywhere")) {
            auto n = replace_texture(ctx.editor, from_, to_);
            if (n)
                ctx.log.line("replace texture: " + std::to_string(*n) + " faces and fields now " + to_,
                             false);
            else
                ctx.report(n.error(), "replace texture");
        }
        ctx.spots.here("face.replace");
    }

    TextureBrowser browser_;
    int edge_ = 0;
    char from_[64] = {}, to_[64] = {};
};

// A CSG item: greyed with the reason as its tooltip when it does not apply.
bool csg_item(const Document& doc, const char* label, CsgOp op) {
    const std::string why = csg_unavailable(doc, op);
    const bool chosen = ImGui::MenuItem(label, nullptr, false, why.empty());
    if (!why.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", why.c_str());
    return chosen;
}

} // namespace

std::unique_ptr<InspectorSection> make_face_section() {
    return std::make_unique<FaceSection>();
}

void BrushMenu::draw(const PanelContext& ctx) {
    const bool open = ImGui::BeginMenu("Brush");
    ctx.spots.here("menu.brush"); // the menu's title, where a click opens it
    if (!open) return;
    Editor& editor = ctx.editor;
    const Document& doc = editor.doc();
    if (csg_item(doc, "Subtract (cut the selected from the others)", CsgOp::subtract))
        ctx.report(subtract_selected_brushes(editor), "subtract");
    ctx.spots.here("brush.subtract");
    const std::string hollow_why = csg_unavailable(doc, CsgOp::hollow);
    const bool hollow_open = ImGui::BeginMenu("Hollow", hollow_why.empty());
    ctx.spots.here("brush.hollow");
    if (hollow_open) {
        ImGui::SetNextItemWidth(100);
        float thickness = thickness_ ? *thickness_ : std::clamp(doc.grid.step, 0.01f, 64.0f);
        if (ImGui::DragFloat("wall thickness", &thickness, 0.05f, 0.01f, 64.0f, "%.2f"))
            thickness_ = thickness;
        if (ImGui::Button("Hollow")) {
            ctx.report(hollow_selected_brushes(editor, thickness), "hollow");
            ImGui::CloseCurrentPopup();
        }
        ctx.spots.here("brush.hollow_apply");
        ImGui::EndMenu();
    }
    if (!hollow_why.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", hollow_why.c_str());
    if (csg_item(doc, "Merge", CsgOp::merge)) ctx.report(merge_selected_brushes(editor), "merge");
    ctx.spots.here("brush.merge");
    if (csg_item(doc, "Intersect (keep the common part)", CsgOp::intersect))
        ctx.report(intersect_selected_brushes(editor), "intersect");
    ctx.spots.here("brush.intersect");
    ImGui::Separator();
    if (ImGui::MenuItem("Select faces of selected brushes", nullptr, false, !doc.selection.empty()))
        ctx.report(select_faces_of_selection(editor), "select faces");
    ctx.spots.here("brush.select_faces");
    if (ImGui::MenuItem("Clear face selection", nullptr, false, !doc.faces.empty()))
        clear_face_selection(editor);
    bool lock = editor.face_session().texture_lock;
    if (ImGui::MenuItem("Pin to world", nullptr, &lock)) set_texture_lock(editor, lock);
    ImGui::EndMenu();
}

void draw_selected_faces(render::DebugDraw& draw, const Document& doc) {
    const Vec4 outline(1.0f, 0.62f, 0.1f, 1.0f), axis(1.0f, 0.25f, 0.2f, 1.0f);
    for (const FaceRef& ref : doc.faces) {
        const level::Entity* e = doc.level.find(ref.entity);
        if (!e) continue;
        const auto world = level::world_brush(*e);
        if (!world || ref.face < 0 || ref.face >= static_cast<int>(world->faces().size())) continue;
        const brush::Face& face = world->faces()[static_cast<size_t>(ref.face)];
        const DVec3 lift = face.plane.normal * 0.02;
        const auto& polygon = world->polygons()[static_cast<size_t>(ref.face)];
        DVec3 centre(0.0);
        for (size_t k = 0; k < polygon.size(); ++k) {
            const DVec3 a = world->vertices()[static_cast<size_t>(polygon[k])];
            const DVec3 b = world->vertices()[static_cast<size_t>(polygon[(k + 1) % polygon.size()])];
            draw.line(Vec3(a + lift), Vec3(b + lift), outline);
            centre += a / double(polygon.size());
        }
        const DVec3 u = brush::texture_axes(face).u * std::abs(face.attributes.scale.x);
        draw.line(Vec3(centre + lift), Vec3(centre + lift + u), axis);
    }
}

nlohmann::json face_status(const Editor& editor) {
    nlohmann::json faces = nlohmann::json::array();
    for (const SelectedFace& f : selected_faces(editor.doc())) {
        const brush::FaceAttributes& at = f.face.attributes;
        faces.push_back({{"entity", f.entity->id},
                         {"face", f.index},
                         {"material", at.material},
                         {"offset", {at.offset.x, at.offset.y}},
                         {"scale", {at.scale.x, at.scale.y}},
                         {"rotation", at.rotation_degrees}});
    }
    return {{"selected", faces}, {"texture_lock", editor.face_session().texture_lock}};
}

} // namespace ks::editor::ui
