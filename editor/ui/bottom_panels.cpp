// The history, log and validation panels (bottom_panels.h).
#include "ui/bottom_panels.h"
#include "model/edit_selection.h"
#include "model/quick_fix.h"

#include "ui/dojo_panel.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <cstdio>

namespace ks::editor::ui {

namespace {
// The steps, the done ones bright; returns the number of steps to have done after a click, -1 for none.
int history_list(const std::vector<std::string>& names, int done, const char* first) {
    int target = -1;
    if (ImGui::Selectable(first, done == 0)) target = 0;
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
        ImGui::PushID(i);
        ImGui::PushStyleColor(ImGuiCol_Text,
                              i < done ? ImVec4(0.9f, 0.92f, 1, 1) : ImVec4(0.5f, 0.5f, 0.55f, 1));
        char label[160];
        std::snprintf(label, sizeof(label), "%3d  %s", i + 1, names[static_cast<size_t>(i)].c_str());
        if (ImGui::Selectable(label, i + 1 == done)) target = i + 1;
        ImGui::PopStyleColor();
        ImGui::PopID();
    }
    return target;
}
} // namespace

void HistoryPanel::draw(Editor& editor, const Rect& rect) {
    place_panel(rect.x, rect.y, rect.w, rect.h);
    ImGui::Begin("History", nullptr, kPanelFlags);
    const auto& history = editor.history();
    const int target = history_list(history.step_names(), static_cast<int>(history.undo_count()), "(opened)");
    if (target >= 0) { // jump: undo or redo until `target` steps are done
        while (static_cast<int>(editor.history().undo_count()) > target && editor.undo()) {
        }
        while (static_cast<int>(editor.history().undo_count()) < target && editor.redo()) {
        }
    }
    ImGui::End();
}

void HistoryPanel::draw(DojoPanel& dojo, const Rect& rect) {
    place_panel(rect.x, rect.y, rect.w, rect.h);
    ImGui::Begin("History", nullptr, kPanelFlags);
    ImGui::TextDisabled("Dojo steps");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The clip file's undo steps; the level's show in the Level tab");
    const DojoHistory& history = dojo.history();
    const int target = history_list(history.step_names(), static_cast<int>(history.undo_count()), "(loaded)");
    if (target >= 0) {
        while (static_cast<int>(dojo.history().undo_count()) > target && dojo.undo()) {
        }
        while (static_cast<int>(dojo.history().undo_count()) < target && dojo.redo()) {
        }
    }
    ImGui::End();
}

void LogPanel::draw(EditorLog& log, const Rect& rect) {
    place_panel(rect.x, rect.y, rect.w, rect.h);
    ImGui::Begin("Log", nullptr, kPanelFlags);
    if (ImGui::SmallButton("Clear")) log.clear();
    ImGui::SameLine();
    ImGui::TextDisabled("editor messages, and the play-test's output");
    ImGui::BeginChild("lines");
    for (const auto& [line, error] : log.lines()) {
        if (error)
            ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", line.c_str());
        else
            ImGui::TextUnformatted(line.c_str());
    }
    if (shown_revision_ != log.revision()) ImGui::SetScrollHereY(1.0f), shown_revision_ = log.revision();
    ImGui::EndChild();
    ImGui::End();
}

void ValidationPanel::draw(const PanelContext& ctx, const Rect& rect) {
    place_panel(rect.x, rect.y, rect.w, rect.h);
    Editor& editor = ctx.editor;
    const auto& issues = editor.issues();
    const int errors = count_errors(issues);
    char title[96];
    std::snprintf(title, sizeof(title), "Validation: %d errors, %d warnings###Validation", errors,
                  static_cast<int>(issues.size()) - errors);
    ImGui::Begin(title, nullptr, kPanelFlags);
    if (issues.empty())
        ImGui::TextColored(ImVec4(0.4f, 1.0f, 0.5f, 1), "No problems: the level is ready to play.");
    for (size_t i = 0; i < issues.size(); ++i) {
        const Issue issue = issues[i]; // a copy: a fix changes the list
        ImGui::PushID(static_cast<int>(i));
        const bool error = issue.severity == IssueSeverity::Error;
        ImGui::TextColored(error ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(1, 0.8f, 0.3f, 1), "%s",
                           error ? "ERR " : "WARN");
        ImGui::SameLine();
        // The message wraps in the narrow column (a logic finding names entity, link and target); the quick
        // fix goes under it, where its label has the width it needs.
        ImGui::TextWrapped("[%s] %s", rule_name(issue.rule), issue.message.c_str());
        if (ImGui::IsItemHovered()) {
            ImGui::GetWindowDrawList()->AddRectFilled(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                                      IM_COL32(90, 120, 180, 50));
            ImGui::SetTooltip("Click to select what this is about");
        }
        if (ImGui::IsItemClicked()) ctx.report(select_issue(editor, issue), "select");
        if (issue.fix.available()) {
            ImGui::Indent(40.0f);
            const bool fix = ImGui::SmallButton(issue.fix.label.c_str());
            ctx.spots.here("fix:" + issue.fix.label);
            ImGui::Unindent(40.0f);
            if (fix) {
                ctx.report(apply_quick_fix(editor, issue), "quick fix");
                ImGui::PopID();
                break;
            }
        }
        ImGui::PopID();
    }
    ImGui::End();
}

} // namespace ks::editor::ui
