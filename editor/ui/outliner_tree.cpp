// The Outliner (outliner.h): the player start's row, groups as a tree (a prefab instance labelled with its
// prefab, in its own colour), their members under them, the entities in no group after them; with a type
// filter or a search, a flat list of the matching entities. Only what is open or on screen is drawn (tree
// nodes closed by default, ImGuiListClipper over the long lists), so a 2 000-entity level costs a few rows a
// frame. The Layers tab: each layer's eye, lock, active radio, name (double-click renames), count and delete.
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "ui/outliner.h"
#include "ui/panel_style.h"
#include "ui/structure_actions.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace ks::editor::ui {

namespace {
const ImVec4 kGroupText(0.6f, 0.8f, 1.0f, 1);
const ImVec4 kPrefabText(0.55f, 1.0f, 0.8f, 1);
const ImVec4 kDimText(0.45f, 0.45f, 0.5f, 1);
const ImVec4 kOutlinerStartText(0.45f, 1.0f, 0.55f, 1.0f); // the player start's green

bool mentions(const std::string& haystack, const char* needle) {
    if (!*needle) return true;
    auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
    const auto it = std::search(haystack.begin(), haystack.end(), needle, needle + std::strlen(needle),
                                [&](char a, char b) { return lower(a) == lower(b); });
    return it != haystack.end();
}

bool sorted_has(const std::vector<int>& ids, int id) {
    return std::binary_search(ids.begin(), ids.end(), id);
}

SelectMode click_mode() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.KeyCtrl ? SelectMode::Toggle : io.KeyShift ? SelectMode::Add : SelectMode::Replace;
}
} // namespace

void Outliner::refresh(Editor& editor) {
    const auto& issues = editor.issues();
    const level::Level& level = editor.level();
    const bool changed = tree_.revision != editor.revision() || tree_.issue_count != issues.size();
    if (changed) {
        tree_.revision = editor.revision();
        tree_.issue_count = issues.size();
        tree_.filter_type = -2; // the flat list too
        const level::EditorData& data = level.editor;
        tree_.top_groups.clear();
        for (const level::Group& g : data.groups)
            if (parent_group_of_group(data, g.id) == 0) tree_.top_groups.push_back(g.id);
        std::unordered_map<int, int> grouped;
        for (const level::Group& g : data.groups)
            for (int id : g.entities) grouped[id] = g.id;
        std::unordered_map<int, int> index_of;
        tree_.loose.clear();
        for (size_t i = 0; i < level.entities.size(); ++i) {
            index_of[level.entities[i].id] = static_cast<int>(i);
            if (!grouped.contains(level.entities[i].id)) tree_.loose.push_back(static_cast<int>(i));
        }
        tree_.issues.assign(level.entities.size(), {0, 0});
        for (const Issue& issue : issues)
            if (auto it = index_of.find(issue.entity_id); it != index_of.end()) {
                auto& counts = tree_.issues[static_cast<size_t>(it->second)];
                (issue.severity == IssueSeverity::Error ? counts.first : counts.second)++;
            }
        tree_.layer_counts.assign(std::max<size_t>(1, data.layers.size()), 0);
        const auto layers = layer_table(data);
        for (const level::Entity& e : level.entities) {
            auto it = layers.find(e.id);
            const size_t layer = it == layers.end() ? 0 : static_cast<size_t>(it->second);
            if (layer < tree_.layer_counts.size()) ++tree_.layer_counts[layer];
        }
    }
    if (tree_.filter_type != type_filter_ || tree_.filter_search != search_) {
        tree_.filter_type = type_filter_;
        tree_.filter_search = search_;
        tree_.filtered.clear();
        for (size_t i = 0; i < level.entities.size(); ++i) {
            const level::Entity& e = level.entities[i];
            if (type_filter_ >= 0 && static_cast<int>(e.type()) != type_filter_) continue;
            const std::string type(level::type_name(e.type()));
            if (!mentions(e.name, search_) && !mentions(type, search_)) continue;
            tree_.filtered.push_back(static_cast<int>(i));
        }
    }
}

void Outliner::entity_row(const PanelContext& ctx, int index) {
    const Document& doc = ctx.editor.doc();
    const level::Entity& e = doc.level.entities[static_cast<size_t>(index)];
    ImGui::PushID(e.id);
    // Greyed when hidden, by its own eye or its layer; the eye and the lock show and toggle its own flag.
    const bool hidden = doc.hidden.contains(e.id), locked = doc.locked.contains(e.id);
    const bool own_hidden = sorted_has(doc.level.editor.hidden, e.id);
    const bool own_locked = sorted_has(doc.level.editor.locked, e.id);
    ImGui::PushStyleColor(ImGuiCol_Text, own_hidden ? kDimText : ImVec4(0.8f, 0.85f, 0.95f, 1));
    if (ImGui::SmallButton(own_hidden ? "-" : "o"))
        ctx.report(set_hidden(ctx.editor, e.id, !own_hidden), "Hide");
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(own_hidden ? "Hidden: click to show"
                          : hidden   ? "Hidden by its layer (click to hide it on its own too)"
                                     : "Visible: click to hide");
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, own_locked ? ImVec4(1.0f, 0.7f, 0.3f, 1)
                                         : locked   ? ImVec4(0.7f, 0.55f, 0.35f, 1)
                                                    : kDimText);
    if (ImGui::SmallButton(own_locked ? "L" : locked ? "l" : "."))
        ctx.report(set_locked(ctx.editor, e.id, !own_locked), "Lock");
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(own_locked ? "Locked: click to unlock"
                          : locked   ? "Locked by its layer"
                                     : "Click to lock (no picking)");
    ImGui::SameLine();
    const auto [errors, warnings] = tree_.issues[static_cast<size_t>(index)];
    char row[160];
    std::snprintf(row, sizeof(row), "%-4d %s", e.id, e.name.empty() ? type_label(e.type()) : e.name.c_str());
    ImVec4 colour = type_colour(e.type());
    if (hidden) colour.w = 0.45f;
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    const float badge_w = (errors || warnings) ? 22.0f : 0.0f;
    const bool row_clicked =
        ImGui::Selectable(row, doc.is_selected(e.id), ImGuiSelectableFlags_AllowDoubleClick,
                          ImVec2(ImGui::GetContentRegionAvail().x - badge_w, 0));
    ctx.spots.here("outliner.entity:" + std::to_string(e.id));
    if (row_clicked) {
        // A row is the entity itself, wherever its group is: the group it is in is entered.
        const int parent = parent_group_of_entity(doc.level.editor, e.id);
        if (parent != 0 && parent != ctx.editor.open_group())
            ctx.report(enter_group(ctx.editor, parent), "enter");
        if (parent == 0)
            while (ctx.editor.open_group() != 0) exit_group(ctx.editor);
        ctx.report(select(ctx.editor, {e.id}, click_mode()), "select");
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) ctx.window.focus_selection();
    }
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s #%d", type_label(e.type()), e.id);
    if (errors || warnings) {
        ImGui::SameLine();
        ImGui::TextColored(errors ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(1, 0.8f, 0.3f, 1), "!%d",
                           errors + warnings);
        if (ImGui::IsItemHovered()) {
            std::string tip;
            for (const auto& issue : ctx.editor.issues())
                if (issue.entity_id == e.id) tip += issue.message + "\n";
            ImGui::SetTooltip("%s", tip.c_str());
        }
    }
    ImGui::PopID();
}

void Outliner::group_context_menu(const PanelContext& ctx, const level::Group& group) {
    if (!ImGui::BeginPopupContextItem("group_menu")) return;
    const int id = group.id;
    if (ImGui::MenuItem("Select")) select_group(ctx.editor, ctx.log, id);
    if (ImGui::MenuItem("Enter group")) ctx.report(enter_group(ctx.editor, id), "enter group");
    if (ImGui::MenuItem("Rename...")) {
        rename_group_ = id;
        std::snprintf(rename_buffer_, sizeof rename_buffer_, "%s", group.name.c_str());
    }
    if (ImGui::MenuItem("Ungroup")) {
        select_group(ctx.editor, ctx.log, id);
        ungroup_selection(ctx.editor, ctx.log);
    }
    if (group.has_prefab) {
        ImGui::Separator();
        if (ImGui::MenuItem("Apply to prefab")) apply_to_prefab(ctx.editor, ctx.log, id);
        if (ImGui::MenuItem("Revert all overrides"))
            ctx.report(revert_prefab_overrides(ctx.editor, id), "revert");
        if (ImGui::MenuItem("Unlink from prefab")) ctx.report(unlink_prefab(ctx.editor, id), "unlink");
    }
    ImGui::EndPopup();
}

void Outliner::rename_group_popup(const PanelContext& ctx) {
    if (rename_group_ != 0 && !ImGui::IsPopupOpen("Rename group")) ImGui::OpenPopup("Rename group");
    if (!ImGui::BeginPopup("Rename group")) {
        rename_group_ = 0;
        return;
    }
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(200);
    if (ImGui::InputText("##group_name", rename_buffer_, sizeof rename_buffer_,
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
        ctx.report(rename_group(ctx.editor, rename_group_, rename_buffer_), "rename group");
        rename_group_ = 0;
        ImGui::CloseCurrentPopup();
    }
    ImGui::TextDisabled("Enter renames, Esc cancels");
    ImGui::EndPopup();
}

void Outliner::group_node(const PanelContext& ctx, const level::Group& group) {
    const level::EditorData& data = ctx.editor.level().editor;
    ImGui::PushID(-group.id); // entity rows push positive ids
    const std::vector<int>& members = group.entities;
    const bool selected = !members.empty() && std::all_of(members.begin(), members.end(), [&](int id) {
        return ctx.editor.doc().is_selected(id);
    });
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
    if (selected) flags |= ImGuiTreeNodeFlags_Selected;
    if (ctx.editor.open_group() != 0 && group_within(data, ctx.editor.open_group(), group.id))
        ImGui::SetNextItemOpen(true, ImGuiCond_Always); // the entered group and its parents stay open
    char label[200];
    const size_t count = group.entities.size() + group.groups.size();
    if (group.has_prefab)
        std::snprintf(label, sizeof label, "[P] %s  (%s, %zu)", group.name.c_str(),
                      group.prefab.prefab.c_str(), count);
    else
        std::snprintf(label, sizeof label, "[G] %s  (%zu)", group.name.c_str(), count);
    ImGui::PushStyleColor(ImGuiCol_Text, group.has_prefab ? kPrefabText : kGroupText);
    const bool open = ImGui::TreeNodeEx("group", flags, "%s", label);
    ImGui::PopStyleColor();
    ctx.spots.here("outliner.group:" + std::to_string(group.id));
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !ImGui::IsItemToggledOpen()) {
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            rename_group_ = group.id;
            std::snprintf(rename_buffer_, sizeof rename_buffer_, "%s", group.name.c_str());
        } else {
            select_group(ctx.editor, ctx.log, group.id, click_mode());
        }
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(group.has_prefab ? "Prefab instance of %s: click selects it, double-click renames, "
                                             "right-click for Apply / Revert / Unlink"
                                           : "Group%s: click selects it, double-click renames, right-click "
                                             "for Enter / Ungroup",
                          group.has_prefab ? group.prefab.prefab.c_str() : "");
    group_context_menu(ctx, group);
    if (open) {
        for (int child : group.groups)
            if (const level::Group* g = data.find_group(child)) group_node(ctx, *g);
        for (int id : group.entities) {
            const auto& entities = ctx.editor.level().entities;
            // Members are few; the level's entities are sorted by id, so a binary search finds each.
            auto it = std::lower_bound(entities.begin(), entities.end(), id,
                                       [](const level::Entity& e, int v) { return e.id < v; });
            if (it != entities.end() && it->id == id)
                entity_row(ctx, static_cast<int>(it - entities.begin()));
            else if (const level::Entity* e = ctx.editor.level().find(id))
                entity_row(ctx, static_cast<int>(e - entities.data()));
        }
        ImGui::TreePop();
    }
    ImGui::PopID();
}

void Outliner::tree(const PanelContext& ctx) {
    const Document& doc = ctx.editor.doc();
    const bool flat = type_filter_ >= 0 || search_[0] != '\0';
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(4, 2));
    player_start_row(ctx);
    if (!flat)
        for (int id : tree_.top_groups)
            if (const level::Group* g = doc.level.editor.find_group(id)) group_node(ctx, *g);
    const std::vector<int>& rows = flat ? tree_.filtered : tree_.loose;
    // Picked in the viewport: bring the primary selection's row into view (when it is in this list).
    int scroll_to = -1;
    if (!doc.selection.empty() && doc.selection.front() != scrolled_to_) {
        scrolled_to_ = doc.selection.front();
        for (size_t i = 0; i < rows.size(); ++i)
            if (doc.level.entities[static_cast<size_t>(rows[i])].id == scrolled_to_)
                scroll_to = static_cast<int>(i);
    }
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(rows.size()));
    if (scroll_to >= 0) clipper.ForceDisplayRangeByIndices(scroll_to, scroll_to + 1);
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            entity_row(ctx, rows[static_cast<size_t>(i)]);
            if (i == scroll_to) ImGui::SetScrollHereY(0.5f);
        }
    ImGui::PopStyleVar();
    rename_group_popup(ctx);
}

void Outliner::layers_tab(const PanelContext& ctx) {
    const auto& layers = ctx.editor.level().editor.layers;
    const int active = ctx.editor.level().editor.active_layer;
    if (ImGui::SmallButton("+ Layer")) {
        const std::string name = "Layer " + std::to_string(std::max<size_t>(1, layers.size()));
        if (auto added = layer_add(ctx.editor, name); !added)
            ctx.log.line("layer: " + added.error().str(), true);
    }
    ctx.spots.here("layers.add");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A new layer (the first one also makes the Default layer)");
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped(layers.empty() ? "No layers yet: every entity is in Default."
                                      : "o shows or hides a layer, L locks it, the dot is the active layer "
                                        "(new entities go there). Right-click a name: move the selection "
                                        "there, select its entities; double-click renames.");
    ImGui::PopStyleColor();
    if (layers.empty()) return;
    if (!ImGui::BeginTable("layers", 6, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) return;
    ImGui::TableSetupColumn("eye");
    ImGui::TableSetupColumn("lock");
    ImGui::TableSetupColumn("active");
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("count");
    ImGui::TableSetupColumn("delete");
    for (int i = 0; i < static_cast<int>(layers.size()); ++i) {
        const level::Layer& layer = layers[static_cast<size_t>(i)];
        const std::string spot = "layer" + std::to_string(i);
        ImGui::PushID(i);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, layer.visible ? ImVec4(0.8f, 0.85f, 0.95f, 1) : kDimText);
        if (ImGui::SmallButton(layer.visible ? "o" : "-"))
            ctx.report(layer_set_visible(ctx.editor, i, !layer.visible), "layer");
        ImGui::PopStyleColor();
        ctx.spots.here(spot + ".eye");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip(layer.visible ? "Shown: click to hide" : "Hidden");
        ImGui::TableNextColumn();
        ImGui::PushStyleColor(ImGuiCol_Text, layer.locked ? ImVec4(1.0f, 0.7f, 0.3f, 1) : kDimText);
        if (ImGui::SmallButton(layer.locked ? "L" : "."))
            ctx.report(layer_set_locked(ctx.editor, i, !layer.locked), "layer");
        ImGui::PopStyleColor();
        ctx.spots.here(spot + ".lock");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip(layer.locked ? "Locked: click to unlock" : "Lock");
        ImGui::TableNextColumn();
        if (ImGui::RadioButton("##active", active == i)) ctx.report(layer_set_active(ctx.editor, i), "layer");
        ctx.spots.here(spot + ".active");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The active layer: new entities go here");
        ImGui::TableNextColumn();
        if (rename_layer_ == i) {
            ImGui::SetNextItemWidth(-1);
            if (focus_rename_) ImGui::SetKeyboardFocusHere(), focus_rename_ = false;
            if (ImGui::InputText("##name", rename_buffer_, sizeof rename_buffer_,
                                 ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
                ctx.report(layer_rename(ctx.editor, i, rename_buffer_), "rename layer");
                rename_layer_ = -1;
            } else if (ImGui::IsItemDeactivated()) {
                rename_layer_ = -1;
            }
        } else {
            ImGui::Selectable(layer.name.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick);
            ctx.spots.here(spot + ".name");
            if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
                rename_layer_ = i, focus_rename_ = true;
                std::snprintf(rename_buffer_, sizeof rename_buffer_, "%s", layer.name.c_str());
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("Double-click to rename; right-click to move the selection here");
            if (ImGui::BeginPopupContextItem("layer_menu")) {
                if (ImGui::MenuItem("Move selection here", nullptr, false,
                                    !ctx.editor.doc().selection.empty()))
                    ctx.report(move_selection_to_layer(ctx.editor, i), "move to layer");
                ctx.spots.here("layer_menu.move");
                if (ImGui::MenuItem("Select all in layer")) {
                    const auto table = layer_table(ctx.editor.level().editor);
                    select_where(ctx.editor, [&](const level::Entity& e) {
                        auto it = table.find(e.id);
                        return (it == table.end() ? 0 : it->second) == i;
                    });
                }
                if (ImGui::MenuItem("Rename")) {
                    rename_layer_ = i, focus_rename_ = true;
                    std::snprintf(rename_buffer_, sizeof rename_buffer_, "%s", layer.name.c_str());
                }
                ImGui::EndPopup();
            }
        }
        ImGui::TableNextColumn();
        const int count = static_cast<size_t>(i) < tree_.layer_counts.size()
                              ? tree_.layer_counts[static_cast<size_t>(i)]
                              : 0;
        ImGui::TextDisabled("%d", count);
        ImGui::TableNextColumn();
        if (i > 0) {
            if (ImGui::SmallButton("x")) ctx.report(layer_remove(ctx.editor, i), "remove layer");
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove the layer: its entities go to Default");
        }
        ImGui::PopID();
    }
    ImGui::EndTable();
}

std::optional<LeftTab> parse_left_tab(std::string_view name) {
    if (name == "outliner") return LeftTab::Outliner;
    if (name == "layers") return LeftTab::Layers;
    if (name == "prefabs") return LeftTab::Prefabs;
    return std::nullopt;
}

const char* left_tab_name(LeftTab tab) {
    constexpr const char* kNames[] = {"outliner", "layers", "prefabs"};
    return kNames[static_cast<int>(tab)];
}

// The Outliner tab: type filter, search and the entity tree.
void Outliner::outliner_tab(const PanelContext& ctx) {
    ImGui::SetNextItemWidth(-1);
    const char* preview =
        type_filter_ < 0 ? "All types" : type_label(static_cast<level::EntityType>(type_filter_));
    if (ImGui::BeginCombo("##type", preview)) {
        if (ImGui::Selectable("All types", type_filter_ < 0)) type_filter_ = -1;
        for (auto t : level::all_types())
            if (ImGui::Selectable(type_label(t), type_filter_ == static_cast<int>(t)))
                type_filter_ = static_cast<int>(t);
        ImGui::EndCombo();
    }
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##search", "Search names...", search_, sizeof(search_));
    if (type_filter_ >= 0 && ImGui::Button("Select all of this type", ImVec2(-1, 0)))
        select_all_of_type(ctx.editor, static_cast<level::EntityType>(type_filter_));
    ImGui::BeginChild("entities", ImVec2(0, 0), false);
    tree(ctx);
    ImGui::EndChild();
}

// The player start's row at the top of the tree (viewport_lines.cpp draws its figure).
void Outliner::player_start_row(const PanelContext& ctx) {
    if (type_filter_ >= 0 || !mentions("player start", search_)) return;
    ImGui::PushStyleColor(ImGuiCol_Text, kOutlinerStartText);
    const bool clicked = ImGui::Selectable("     Player start", ctx.editor.doc().player_start_selected(),
                                           ImGuiSelectableFlags_AllowDoubleClick);
    ImGui::PopStyleColor();
    ctx.spots.here("outliner.player_start");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Where the player starts: click to select, then move and turn it");
    if (!clicked) return;
    ctx.report(select(ctx.editor, {kPlayerStartId}, click_mode()), "select");
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) ctx.window.focus_selection();
}

} // namespace ks::editor::ui
