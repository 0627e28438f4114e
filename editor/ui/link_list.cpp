// The link-list widget (an entity's links in the inspector, an objective's on_complete links, the level's
// on_start links): per link, the event (only those its owner emits), the target (objectives, the level and
// every entity that takes an action; an unnamed one is named when chosen), the action (those the target
// takes), the delay, "once", a pick button (the target by a click in the viewport: link_pick.cpp) and a
// remove button; "+ Add link" below. Every change is one undo step (a dragged delay too); a link the level
// checks find wrong is framed red with their message under it.
#include "jsonio/json_path.h"
#include "model/edit_logic.h"
#include "model/edit_selection.h"
#include "ui/logic_panels.h"
#include "ui/panel_style.h"
#include "ui/problem_lines.h"
#include "view/link_options.h"

#include <imgui.h>

#include <algorithm>

namespace ks::editor::ui {

namespace {

// A combo over `items`: the chosen one, or empty. While open, each entry's centre is a spot "combo:ITEM".
std::string choice_combo(const char* id, const std::string& current, const std::vector<std::string>& items,
                         UiSpots& spots) {
    std::string chosen;
    if (ImGui::BeginCombo(id, current.empty() ? "(none)" : current.c_str())) {
        for (const auto& item : items) {
            if (ImGui::Selectable(item.c_str(), item == current)) chosen = item;
            spots.here("combo:" + item);
        }
        ImGui::EndCombo();
    }
    return chosen;
}

std::string owner_key(const LinkOwner& owner) {
    switch (owner.kind) {
    case LinkOwner::Kind::Entity:
        return "entity " + std::to_string(owner.entity_id);
    case LinkOwner::Kind::Objective:
        return "objective " + owner.objective_id;
    case LinkOwner::Kind::Level:
        break;
    }
    return "level";
}

} // namespace

void LogicPanels::refresh_problems() {
    if (problems_revision_ == editor_.revision()) return;
    logic_problems_ = logic_problems(editor_.level());
    problems_revision_ = editor_.revision();
}

Result<void> LogicPanels::apply_link_target(const LinkOwner& owner, int index, const TargetOption& option) {
    editor_.begin_transaction("Set link target"); // naming the entity and the link's target: one step
    std::string target = option.target;
    if (option.kind == level::TargetKind::Entity) {
        auto named = ensure_link_name(editor_, option.entity_id);
        if (!named) {
            editor_.cancel_transaction();
            return named.error();
        }
        target = *named;
    }
    const std::vector<level::Link>* links = links_of(editor_, owner);
    if (!links || index < 0 || index >= static_cast<int>(links->size())) {
        editor_.cancel_transaction();
        return Error("the link being edited is gone");
    }
    level::Link link = (*links)[static_cast<size_t>(index)];
    link.target = target;
    const std::string action =
        action_for_target(target_actions(editor_.level(), option.kind, target), link.action);
    if (!action.empty()) link.action = action;
    auto r = link_set(editor_, owner, index, link);
    if (!r) {
        editor_.cancel_transaction();
        return r;
    }
    editor_.commit_transaction();
    return ok();
}

// The target combo and its Pick button; true when the target changed (the list changed under the caller).
bool LogicPanels::target_widgets(const LinkOwner& owner, int index, const level::Link& link, float width,
                                 const std::string& spot) {
    const level::Level& level = editor_.level();
    const level::TargetKind kind = link_target_kind(level, link);
    const bool picking =
        pick_ && pick_->purpose == PickPurpose::LinkTarget && pick_->owner == owner && pick_->index == index;
    bool changed = false;
    ImGui::SetNextItemWidth(std::max(40.0f, width));
    // The name alone (narrow inspector); the entries and the tooltip say what it is.
    if (ImGui::BeginCombo("##target", link.target.empty() ? "(no target)" : link.target.c_str())) {
        for (const TargetOption& option : target_options(level)) {
            const bool current =
                option.kind == kind && !option.target.empty() && option.target == link.target;
            if (ImGui::Selectable(option.label.c_str(), current) && !changed) {
                report(apply_link_target(owner, index, option), "link target");
                changed = true;
            }
            spots_.here("combo:" + option.label);
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", target_label(level, kind, link.target).c_str());
    spots_.here(spot + ".target");
    ImGui::SameLine();
    if (picking) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
    if (ImGui::SmallButton("Pick"))
        picking ? end_pick() : begin_pick({PickPurpose::LinkTarget, owner, index});
    if (picking) ImGui::PopStyleColor();
    spots_.here(spot + ".pick");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Pick the target by clicking it in the viewport (Esc cancels)");
    return changed;
}

bool LogicPanels::link_row(const LinkOwner& owner, int index, const std::vector<std::string>& events,
                           const std::string& spot) {
    const level::Level& level = editor_.level();
    level::Link link =
        (*links_of(editor_, owner))[static_cast<size_t>(index)]; // a copy: edits change the list
    const std::string path = jsonio::element_path(links_path(level, owner), static_cast<size_t>(index));
    const auto problems = problems_at(logic_problems_, path);
    const bool broken = std::any_of(problems.begin(), problems.end(), [](auto* p) { return p->error; });
    if (broken) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.5f, 0.12f, 0.1f, 1.0f));
    const float width = ImGui::GetContentRegionAvail().x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float pick_w = ImGui::CalcTextSize("Pick").x + ImGui::GetStyle().FramePadding.x * 2.0f;
    const float arrow_w = ImGui::CalcTextSize("->").x;
    bool changed = false;

    // Line 1: event -> target [Pick]. An objective's and the level's links have one event each, which the
    // list's heading names: their rows leave the event out and give the target the room.
    const bool one_event =
        owner.kind != LinkOwner::Kind::Entity && events.size() == 1 && link.event == events[0];
    float target_w = width - arrow_w - pick_w - spacing * 2.0f;
    if (!one_event) {
        ImGui::SetNextItemWidth(width * 0.36f);
        if (auto event = choice_combo("##event", link.event, events, spots_); !event.empty()) {
            link.event = event;
            report(link_set(editor_, owner, index, link), "link event");
            changed = true;
        }
        spots_.here(spot + ".event");
        ImGui::SameLine();
        target_w -= width * 0.36f + spacing;
    }
    ImGui::TextUnformatted("->");
    ImGui::SameLine();
    const level::TargetKind kind = link_target_kind(level, link);
    const bool picking =
        pick_ && pick_->purpose == PickPurpose::LinkTarget && pick_->owner == owner && pick_->index == index;
    if (target_widgets(owner, index, link, target_w, spot) && !changed) changed = true;

    // Line 2: action, delay, once, remove
    ImGui::SetNextItemWidth(width * 0.36f);
    const auto actions = target_actions(level, kind, link.target);
    if (auto action = choice_combo("##action", link.action, actions, spots_); !action.empty() && !changed) {
        link.action = action;
        report(link_set(editor_, owner, index, link), "link action");
        changed = true;
    }
    spots_.here(spot + ".action");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(50.0f, width * 0.25f));
    float delay = link.delay;
    if (ImGui::DragFloat("##delay", &delay, 0.05f, 0.0f, static_cast<float>(level::kMaxLinkDelay), "%.2f s",
                         ImGuiSliderFlags_AlwaysClamp) &&
        !changed) {
        link.delay = delay;
        report(link_set(editor_, owner, index, link,
                        "link delay " + owner_key(owner) + " " + std::to_string(index)),
               "link delay");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging(); // one drag = one step
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Seconds between the event and the action");
    spots_.here(spot + ".delay");
    ImGui::SameLine();
    bool once = link.once;
    if (ImGui::Checkbox("once", &once) && !changed) {
        link.once = once;
        report(link_set(editor_, owner, index, link), "link once");
        changed = true;
    }
    spots_.here(spot + ".once");
    ImGui::SameLine();
    if (ImGui::SmallButton("x") && !changed) {
        if (picking) end_pick();
        report(link_remove(editor_, owner, index), "remove link");
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this link");
    spots_.here(spot + ".remove");
    if (broken) ImGui::PopStyleColor();
    problem_lines(problems);
    return !changed;
}

void LogicPanels::link_list(const LinkOwner& owner, const std::string& spot) {
    const std::vector<level::Link>* links = links_of(editor_, owner);
    if (!links) return;
    const level::Level& level = editor_.level();
    const std::vector<std::string> events = level::event_names(owner_events(level, owner));
    const std::string path = links_path(level, owner);
    std::vector<const LogicProblem*> whole_list;
    for (const LogicProblem* p : problems_at(logic_problems_, path))
        if (p->path == path) whole_list.push_back(p);
    problem_lines(whole_list);
    ImGui::PushID(spot.c_str());
    for (int i = 0; i < static_cast<int>(links->size()); ++i) {
        ImGui::PushID(i);
        const bool same_list = link_row(owner, i, events, spot + std::to_string(i));
        ImGui::PopID();
        if (!same_list) break; // the list changed under the loop: the rest is drawn next frame
        ImGui::Separator();
    }
    ImGui::PopID();
    if (events.empty()) {
        ImGui::TextDisabled("Sets nothing off (links start at triggers, robots, doors, lights, panels, "
                            "pickups, objectives and the level)");
        return;
    }
    if (ImGui::SmallButton(("+ Add link##" + spot).c_str())) {
        // The first event it emits; the action is set again when the target is chosen.
        auto added = link_add(editor_, owner, {events.front(), "", "open"});
        if (!added) log_line("add link: " + added.error().str(), true);
    }
    spots_.here(spot + "_add");
}

// The Links tab: the selected entity's links (what its events set off) and the links that act on it; with
// nothing selected, the level's own (on_start).
void LogicPanels::links_tab() {
    const auto selected = selected_entities(editor_);
    if (selected.size() > 1) {
        ImGui::TextWrapped("%zu selected: select one entity to wire its links.", selected.size());
        return;
    }
    if (selected.empty()) {
        ImGui::TextWrapped("Nothing selected: the level's own links, set off when it starts (on_start). "
                           "Select an entity to wire its events.");
        ImGui::PushID("level_links");
        link_list(LinkOwner::level(), "level_link");
        ImGui::PopID();
        return;
    }
    const level::Entity& entity = *selected.front();
    ImGui::TextColored(type_colour(entity.type()), "%s", entity_title(entity).c_str());
    if (!level::entity_events(entity.type()).empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
        ImGui::TextWrapped("Each link: on the event, do the action to the target (after the delay; once: "
                           "the first time only).");
        ImGui::PopStyleColor();
    }
    ImGui::PushID("links");
    link_list(LinkOwner::entity(entity.id), "link");
    ImGui::PopID();
    const auto incoming = incoming_links(editor_.level(), entity.id);
    ImGui::Spacing();
    if (incoming.empty()) {
        ImGui::TextDisabled(entity.name.empty() ? "No links act on it (it has no name to be targeted by)"
                                                : "No links act on it");
        return;
    }
    ImGui::TextDisabled("Acted on by:");
    for (size_t i = 0; i < incoming.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string row = incoming[i].source + ": " + incoming[i].label;
        if (ImGui::Selectable(row.c_str(), false) && incoming[i].source_entity != 0)
            report(select(editor_, {incoming[i].source_entity}), "select");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(incoming[i].source_entity != 0 ? "Click to select the source"
                                                             : "In the Objectives tab or the level settings");
        ImGui::PopID();
    }
}

} // namespace ks::editor::ui
