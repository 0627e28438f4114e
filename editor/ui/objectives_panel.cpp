// The inspector's Objectives tab: the level's objectives in HUD order (all complete: the level is won), each
// with its id, text, kill list (names with a remove button; add from a list of robots and spawners or by a
// pick in the viewport) and on_complete links (the link-list widget); add, remove, move up and down. Every
// change is one undo step; problems the level checks find are shown under what they are about.
#include "jsonio/json_path.h"
#include "model/edit_logic.h"
#include "ui/logic_panels.h"
#include "ui/problem_lines.h"
#include "view/link_options.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

namespace {
const ImVec4 kErrorText(1.0f, 0.4f, 0.35f, 1.0f);

std::string fresh_objective_id(const level::Level& level) {
    for (int n = static_cast<int>(level.objectives.size()) + 1;; ++n) {
        const std::string id = "objective_" + std::to_string(n);
        if (std::none_of(level.objectives.begin(), level.objectives.end(),
                         [&](const level::Objective& o) { return o.id == id; }))
            return id;
    }
}

// A one-line text field committed with Enter: the new text, or nothing.
std::optional<std::string> text_field(const char* label, const std::string& value) {
    char buffer[level::kMaxMessageLength + 1];
    std::snprintf(buffer, sizeof buffer, "%s", value.c_str());
    if (ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue))
        return std::string(buffer);
    return std::nullopt;
}
} // namespace

Result<void> LogicPanels::add_kill_name(int objective, int entity_id) {
    editor_.begin_transaction("Add to kill list"); // naming the robot and listing it: one step
    auto named = ensure_link_name(editor_, entity_id);
    const auto& objectives = editor_.level().objectives;
    if (!named || objective < 0 || objective >= static_cast<int>(objectives.size())) {
        editor_.cancel_transaction();
        return named ? Error("the objective being edited is gone") : named.error();
    }
    level::Objective edited = objectives[static_cast<size_t>(objective)];
    if (std::find(edited.kill.begin(), edited.kill.end(), *named) == edited.kill.end())
        edited.kill.push_back(*named);
    auto r = objective_set(editor_, objective, std::move(edited));
    if (!r) {
        editor_.cancel_transaction();
        return r;
    }
    editor_.commit_transaction();
    return ok();
}

bool LogicPanels::kill_list(int index, const level::Objective& objective, const std::string& path) {
    ImGui::TextDisabled("Kill:");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("All of these dead completes it (a spawner: all its robots)");
    for (int k = 0; k < static_cast<int>(objective.kill.size()); ++k) {
        ImGui::PushID(k);
        ImGui::SameLine();
        ImGui::TextUnformatted(objective.kill[static_cast<size_t>(k)].c_str());
        ImGui::SameLine(0.0f, 2.0f);
        const bool removed = ImGui::SmallButton("x");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove from the kill list");
        problem_lines(problems_at(logic_problems_, jsonio::element_path(jsonio::member_path(path, "kill"),
                                                                        static_cast<size_t>(k))));
        ImGui::PopID();
        if (removed) {
            level::Objective edited = objective;
            edited.kill.erase(edited.kill.begin() + k);
            report(objective_set(editor_, index, std::move(edited)), "kill list");
            return false;
        }
    }
    const std::string spot = "objective" + std::to_string(index);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Pick").x -
                            ImGui::GetStyle().FramePadding.x * 2.0f - ImGui::GetStyle().ItemSpacing.x);
    bool changed = false;
    if (ImGui::BeginCombo("##kill_add", "add a robot or spawner")) {
        for (const TargetOption& option : kill_options(editor_.level())) {
            if (ImGui::Selectable(option.label.c_str(), false) && !changed) {
                report(add_kill_name(index, option.entity_id), "kill list");
                changed = true;
            }
            spots_.here("combo:" + option.label);
        }
        ImGui::EndCombo();
    }
    spots_.here(spot + ".kill_add");
    ImGui::SameLine();
    const bool picking = pick_ && pick_->purpose == PickPurpose::KillName && pick_->index == index;
    if (picking) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
    if (ImGui::SmallButton("Pick##kill"))
        picking ? end_pick() : begin_pick({PickPurpose::KillName, LinkOwner::level(), index});
    if (picking) ImGui::PopStyleColor();
    spots_.here(spot + ".kill_pick");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Pick a robot or spawner in the viewport (Esc cancels)");
    return !changed;
}

bool LogicPanels::objective_item(int index) {
    const level::Objective objective = editor_.level().objectives[static_cast<size_t>(index)]; // a copy
    const std::string path = jsonio::element_path("objectives", static_cast<size_t>(index));
    const std::string spot = "objective" + std::to_string(index);
    std::vector<const LogicProblem*> own; // about the objective itself, its id or text (not kills or links)
    for (const LogicProblem* p : problems_at(logic_problems_, path)) {
        const std::string_view below = std::string_view(p->path).substr(path.size());
        if (!below.starts_with(".kill") && !below.starts_with(".links")) own.push_back(p);
    }
    const bool broken = std::any_of(own.begin(), own.end(), [](auto* p) { return p->error; });
    if (broken) ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    const bool open =
        ImGui::CollapsingHeader((std::to_string(index + 1) + ". " + objective.id + "###objective").c_str(),
                                ImGuiTreeNodeFlags_DefaultOpen);
    if (broken) ImGui::PopStyleColor();
    spots_.here(spot);
    if (!open) return true;
    const int count = static_cast<int>(editor_.level().objectives.size());
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttons_w =
        ImGui::CalcTextSize("UpDnx").x + style.FramePadding.x * 6.0f + style.ItemSpacing.x * 3.0f;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttons_w - ImGui::CalcTextSize("id").x -
                            style.ItemInnerSpacing.x);
    if (auto id = text_field("id", objective.id)) {
        level::Objective edited = objective;
        edited.id = *id;
        report(objective_set(editor_, index, std::move(edited)), "objective id");
        return false;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Links name it (Enter commits; links that named it follow)");
    ImGui::SameLine();
    if (ImGui::SmallButton("Up") && index > 0) {
        report(objective_move(editor_, index, index - 1), "move objective");
        return false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Earlier in the HUD's order");
    ImGui::SameLine();
    if (ImGui::SmallButton("Dn") && index + 1 < count) {
        report(objective_move(editor_, index, index + 1), "move objective");
        return false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Later in the HUD's order");
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) {
        report(objective_remove(editor_, index), "remove objective");
        return false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this objective");
    spots_.here(spot + ".remove");
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("text").x - style.ItemInnerSpacing.x);
    if (auto text = text_field("text", objective.text)) {
        level::Objective edited = objective;
        edited.text = *text;
        report(objective_set(editor_, index, std::move(edited)), "objective text");
        return false;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("What the HUD shows (Enter commits)");
    problem_lines(own);
    if (!kill_list(index, objective, path)) return false;
    ImGui::TextDisabled("On complete:");
    ImGui::Indent(8.0f);
    link_list(LinkOwner::objective(objective.id), spot + ".link");
    ImGui::Unindent(8.0f);
    return editor_.level().objectives.size() == static_cast<size_t>(count);
}

void LogicPanels::objectives_tab() {
    ImGui::TextDisabled("HUD order; all complete wins (?)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("An objective completes when a link does 'complete' to it, or when everything on\n"
                          "its kill list is dead (a spawner: all the robots it makes). Completing one sets\n"
                          "off its on_complete links; the HUD shows the first one not complete.");
    const int count = static_cast<int>(editor_.level().objectives.size());
    for (int i = 0; i < count; ++i) {
        ImGui::PushID(i);
        const bool same = objective_item(i);
        ImGui::PopID();
        if (!same) break; // the list changed under the loop: the rest is drawn next frame
    }
    if (count == 0) ImGui::TextDisabled("No objectives: the level is never won by them.");
    if (ImGui::Button("+ Add objective"))
        report(objective_add(editor_, {fresh_objective_id(editor_.level()), "New objective", {}, {}}),
               "add objective");
    spots_.here("objective_add");
}

} // namespace ks::editor::ui
