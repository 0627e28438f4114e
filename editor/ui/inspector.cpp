// The inspector: its tabs, the Properties tab's sections in order (inspector_sections.cpp), the field value
// widgets and the texture browser the texture field opens.
#include "ui/inspector.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"

#include "ui/field_typing.h"
#include "ui/panel_style.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

std::optional<InspectorTab> parse_inspector_tab(std::string_view name) {
    if (name == "properties") return InspectorTab::Properties;
    if (name == "links") return InspectorTab::Links;
    if (name == "objectives") return InspectorTab::Objectives;
    return std::nullopt;
}

const char* inspector_tab_name(InspectorTab tab) {
    constexpr const char* kNames[] = {"properties", "links", "objectives"};
    return kNames[static_cast<int>(tab)];
}

std::optional<SelectionTexture> selection_texture(const Editor& editor) {
    const auto selected = selected_entities(editor);
    if (selected.empty()) return std::nullopt;
    for (const FieldDescriptor& field : common_fields(selected))
        if (field.kind == FieldKind::Texture)
            if (auto value = get_entity_field(*selected.front(), field.name))
                return SelectionTexture{field.name, std::get<std::string>(*value)};
    return std::nullopt;
}

namespace {
// What each number of a vector field is, shown in it ("yaw 90"), for the field whose order is not x, y, z:
// a rotation is yaw, pitch, roll (about y, x, z), so 90 typed into what looked like "y" laid a wall flat.
const char* const* component_labels(const FieldDescriptor& field) {
    static const char* const kRotation[] = {"yaw", "pitch", "roll"};
    return field.kind == FieldKind::Vec3 && field.name == "rotation" ? kRotation : nullptr;
}

// A vector's numbers, each labelled, as one group (like DragFloat3, with the same ids): side by side where
// each shows its label and value whole, else one under the other (a robot's long field names leave the
// numbers too little room for "yaw -90" in a row). Each number's centre is the spot `spot`.N.
bool labelled_drag(const char* id, float* v, int n, const char* const* labels, float speed, float lo,
                   float hi, UiSpots& spots, const std::string& spot) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float full = ImGui::CalcItemWidth();
    const float each = (full - style.ItemInnerSpacing.x * static_cast<float>(n - 1)) / static_cast<float>(n);
    bool in_a_row = true;
    for (int i = 0; i < n; ++i) {
        char text[64];
        std::snprintf(text, sizeof text, "%s %g", labels[i], static_cast<double>(v[i]));
        in_a_row = in_a_row && ImGui::CalcTextSize(text).x + style.FramePadding.x * 2 <= each;
    }
    bool changed = false;
    ImGui::BeginGroup();
    ImGui::PushID(id);
    if (in_a_row) ImGui::PushMultiItemsWidths(n, full);
    for (int i = 0; i < n; ++i) {
        ImGui::PushID(i);
        if (i > 0 && in_a_row) ImGui::SameLine(0, style.ItemInnerSpacing.x);
        if (!in_a_row) ImGui::SetNextItemWidth(full);
        char format[32];
        std::snprintf(format, sizeof format, "%s %%g", labels[i]);
        changed |= ImGui::DragFloat("", &v[i], speed, lo, hi, format, ImGuiSliderFlags_AlwaysClamp);
        spots.here(spot + "." + std::to_string(i));
        ImGui::PopID();
        if (in_a_row) ImGui::PopItemWidth();
    }
    ImGui::PopID();
    ImGui::EndGroup();
    return changed;
}

// The spots `spot`.N of the numbers of the vector widget just drawn (equal thirds or halves of it).
void vector_spots(UiSpots& spots, const std::string& spot, int n) {
    if (!spots.enabled) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    for (int i = 0; i < n; ++i)
        spots.set(spot + "." + std::to_string(i),
                  Vec2(lo.x + (hi.x - lo.x) * (static_cast<float>(i) + 0.5f) / static_cast<float>(n),
                       (lo.y + hi.y) * 0.5f));
}

bool is_number(FieldKind kind) {
    return kind == FieldKind::Float || kind == FieldKind::Int || kind == FieldKind::Vec2 ||
           kind == FieldKind::Vec3;
}
} // namespace

bool FieldWidgets::edit(const PanelContext& ctx, const FieldDescriptor& field, FieldValue& value,
                        bool mixed) {
    const char* id = "##value";
    const ImGuiID widget = ImGui::GetID(id);
    bool changed = false;
    typed_commit_ = false;
    if (mixed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.6f, 0.65f, 1));
    // Inside the field's range as doubles: a float 0.01 is below 0.01 and would be refused.
    const float lo = float_at_least(field.min), hi = float_at_most(field.max);
    const float speed = std::clamp((hi - lo) / 400.0f, 0.01f, 0.25f);
    switch (field.kind) {
    case FieldKind::Float: {
        float v = static_cast<float>(std::get<double>(value));
        // A slider's range spanning decades (a radius) is logarithmic, so small values stay reachable.
        if (field.slider)
            changed = ImGui::SliderFloat(id, &v, lo, hi, "%.2f",
                                         ImGuiSliderFlags_AlwaysClamp |
                                             (lo > 0 && hi >= lo * 100 ? ImGuiSliderFlags_Logarithmic : 0));
        else
            changed = ImGui::DragFloat(id, &v, speed, lo, hi, "%.3f", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = static_cast<double>(v);
        break;
    }
    case FieldKind::Int: {
        int v = static_cast<int>(std::get<double>(value));
        const int low = static_cast<int>(field.min), high = static_cast<int>(field.max);
        changed = field.slider ? ImGui::SliderInt(id, &v, low, high, "%d", ImGuiSliderFlags_AlwaysClamp)
                               : ImGui::DragInt(id, &v, 0.2f, low, high, "%d", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = static_cast<double>(v);
        break;
    }
    case FieldKind::Bool: {
        bool v = std::get<bool>(value);
        changed = ImGui::Checkbox(id, &v);
        if (changed) value = v;
        break;
    }
    case FieldKind::String: {
        char buffer[256];
        std::snprintf(buffer, sizeof(buffer), "%s", std::get<std::string>(value).c_str());
        changed = ImGui::InputText(id, buffer, sizeof(buffer), ImGuiInputTextFlags_EnterReturnsTrue);
        if (changed) value = std::string(buffer);
        break;
    }
    case FieldKind::Vec2: {
        Vec2 v = std::get<Vec2>(value);
        // %g: "55" and "-90" instead of "55.00" and "-90.00", so three components fit a narrow inspector.
        changed = ImGui::DragFloat2(id, &v.x, speed, lo, hi, "%g", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = v;
        break;
    }
    case FieldKind::Vec3: {
        Vec3 v = std::get<Vec3>(value);
        if (const char* const* labels = component_labels(field))
            changed = labelled_drag(id, &v.x, 3, labels, speed, lo, hi, ctx.spots, "field." + field.name);
        else
            changed = ImGui::DragFloat3(id, &v.x, speed, lo, hi, "%g", ImGuiSliderFlags_AlwaysClamp);
        if (changed) value = v;
        break;
    }
    case FieldKind::Color: {
        level::Color c = std::get<level::Color>(value);
        float rgb[3] = {c.r, c.g, c.b};
        changed = ImGui::ColorEdit3(id, rgb, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_DisplayHex);
        if (changed) value = level::Color{rgb[0], rgb[1], rgb[2]};
        break;
    }
    case FieldKind::Choice: {
        const std::string current = std::get<std::string>(value);
        if (ImGui::BeginCombo(id, current.c_str())) {
            for (const auto& option : field.options)
                if (ImGui::Selectable(option.c_str(), option == current)) value = option, changed = true;
            ImGui::EndCombo();
        }
        break;
    }
    case FieldKind::Sound: {
        std::string name = std::get<std::string>(value);
        changed = sound_name_widget(id, name, sound_names_);
        if (changed) value = name;
        break;
    }
    case FieldKind::Texture:
        changed = texture_field(ctx, value);
        break;
    }
    if (mixed) ImGui::PopStyleColor();
    if (field.kind != FieldKind::Texture) ctx.spots.here("field." + field.name);
    if ((field.kind == FieldKind::Vec2 || field.kind == FieldKind::Vec3) && !component_labels(field))
        vector_spots(ctx.spots, "field." + field.name, field.kind == FieldKind::Vec2 ? 2 : 3);
    if (!is_number(field.kind)) return changed;
    // Typed numbers are set once, when the typing ends (field_typing.h); dragged ones as they change.
    changed = typed_.filter(widget, ctx.editor.doc().selection, changed, value);
    // A drag changes only while it is held; a Tab from one number of a vector to the next sets the first
    // while the next is being typed into.
    typed_commit_ = changed && (!ImGui::IsItemActive() || typed_.typing(widget));
    if (typed_.typing(widget)) typing_hint(field);
    return changed;
}

// The material's thumbnail (a click opens the browser) and its name, typed freely.
bool FieldWidgets::texture_field(const PanelContext& ctx, FieldValue& value) {
    std::string name = std::get<std::string>(value);
    const ImTextureID thumb = TextureBrowser::thumbnail(ctx.assets, name);
    const float size = ImGui::GetFrameHeight() - 2.0f;
    const bool clicked = thumb ? ImGui::ImageButton(thumb, ImVec2(size, size), ImVec2(0, 0), ImVec2(1, 1), 1)
                               : ImGui::Button("?", ImVec2(size + 2.0f, size + 2.0f));
    ctx.spots.here("inspector.texture");
    if (clicked) texture_browser_.open();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(thumb ? "Browse the textures" : "Not a surface material: browse the textures");
    ImGui::SameLine(0, 4);
    ImGui::SetNextItemWidth(-1);
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "%s", name.c_str());
    if (!ImGui::InputText("##texture", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue))
        return false;
    value = std::string(buffer);
    return true;
}

Inspector::Inspector() : sections_(make_inspector_sections()) {}

void Inspector::texture_browser_window(const PanelContext& ctx, Vec2 position) {
    TextureBrowser& browser = widgets_.texture_browser();
    if (!browser.is_open()) return;
    const auto current = selection_texture(ctx.editor);
    if (!current) { // nothing to pick for
        browser.close();
        return;
    }
    if (auto picked = browser.draw(ctx.assets, current->name, position, ctx.spots)) {
        ctx.report(set_field(ctx.editor, current->field, *picked), "texture");
        ctx.editor.end_merging(); // each pick is its own step
    }
}

void Inspector::draw(const PanelContext& ctx, const Rect& rect) {
    place_panel(rect.x, rect.y, rect.w, rect.h);
    ImGui::Begin("Inspector", nullptr, kPanelFlags);
    if (ImGui::BeginTabBar("inspector_tabs")) {
        auto flags = [this](InspectorTab tab) {
            return select_tab_ == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
        };
        const bool properties = ImGui::BeginTabItem("Properties", nullptr, flags(InspectorTab::Properties));
        ctx.spots.here("tab.properties");
        if (properties) {
            shown_tab_ = InspectorTab::Properties;
            properties_tab(ctx, rect.w);
            ImGui::EndTabItem();
        }
        const Editor& editor = ctx.editor;
        const auto selected = selected_entities(editor);
        char links_title[48];
        std::snprintf(links_title, sizeof links_title, "Links (%zu)###links",
                      selected.size() == 1 ? selected.front()->links.size() : editor.level().links.size());
        const bool links = ImGui::BeginTabItem(links_title, nullptr, flags(InspectorTab::Links));
        ctx.spots.here("tab.links");
        if (links) {
            shown_tab_ = InspectorTab::Links;
            ctx.window.links_tab();
            ImGui::EndTabItem();
        }
        char objectives_title[48];
        std::snprintf(objectives_title, sizeof objectives_title, "Objectives (%zu)###objectives",
                      editor.level().objectives.size());
        const bool objectives =
            ImGui::BeginTabItem(objectives_title, nullptr, flags(InspectorTab::Objectives));
        ctx.spots.here("tab.objectives");
        if (objectives) {
            shown_tab_ = InspectorTab::Objectives;
            ctx.window.objectives_tab();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
        select_tab_.reset();
    }
    ImGui::End();
}

void Inspector::properties_tab(const PanelContext& ctx, float width) {
    InspectorSelection selection;
    selection.entities = selected_entities(ctx.editor);
    selection.player_start = ctx.editor.doc().player_start_selected();
    selection.width = width;
    for (const auto& section : sections_)
        if (section->applies(selection)) section->draw(ctx, selection, widgets_);
}

} // namespace ks::editor::ui
