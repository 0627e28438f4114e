// The dojo's blend table editor: the default blend time, and a from -> to grid of the blend time the game
// uses for every pair of clips (model: blend_grid), explicit pairs highlighted, wildcard ("*") pairs
// tinted, the rest at the default. A cell is dragged or typed (Ctrl+click or double-click) to set its pair,
// and cleared back from its menu or the Clear button; selecting a cell plays that transition in the
// transition tester. Each change is one undo step through model/dojo_clips.h.
#include "ui/dojo_blend_grid.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

namespace {
constexpr double kBlendMin = 0.0, kBlendMax = kMaxBlendSeconds;
const ImVec4 kExplicitFill(0.22f, 0.42f, 0.72f, 1.0f);
const ImVec4 kWildcardFill(0.36f, 0.27f, 0.52f, 1.0f);
const ImVec4 kDefaultFill(0.14f, 0.15f, 0.19f, 1.0f);

ImVec4 fill_of(BlendCell::Source source) {
    return source == BlendCell::Source::Explicit   ? kExplicitFill
           : source == BlendCell::Source::Wildcard ? kWildcardFill
                                                   : kDefaultFill;
}

ImVec4 lighter(ImVec4 c, float by) {
    return ImVec4(std::min(1.0f, c.x + by), std::min(1.0f, c.y + by), std::min(1.0f, c.z + by), c.w);
}

void legend_chip(const ImVec4& fill, const char* label) {
    const float h = ImGui::GetTextLineHeight();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + h, p.y + h - 2),
                                              ImGui::GetColorU32(fill), 2.0f);
    ImGui::Dummy(ImVec2(h + 2, h));
    ImGui::SameLine(0, 4);
    ImGui::TextDisabled("%s", label);
}
} // namespace

void DojoBlendGrid::select(const DojoContext& dojo, int from, int to) {
    from_ = from, to_ = to;
    dojo.playback.test_transition(from, to);
}

void DojoBlendGrid::draw(const DojoContext& dojo) {
    const BlendGrid grid = editor::blend_grid(dojo.edits.file());
    const std::size_t n = grid.clips.size();
    if (from_ >= static_cast<int>(n) || to_ >= static_cast<int>(n)) from_ = to_ = -1;
    double seconds = grid.default_seconds;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Default blend");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::DragScalar("##default", ImGuiDataType_Double, &seconds, 0.005f, &kBlendMin, &kBlendMax,
                          "%.2f s", ImGuiSliderFlags_AlwaysClamp)) {
        dojo.edits.begin_drag("default blend");
        if (auto r = set_default_blend(dojo.edits.file_in_place(), seconds); !r)
            dojo.edits.refuse(r.error());
        else
            dojo.edits.changed();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The blend time of every pair not set below");
    ImGui::SameLine(0, 18);
    legend_chip(kExplicitFill, "set for the pair");
    ImGui::SameLine(0, 12);
    legend_chip(kWildcardFill, "from a * pair");
    ImGui::SameLine(0, 12);
    legend_chip(kDefaultFill, "default");

    // Compact cells, so the robot's clips fit without scrolling; the column headers are the clips' names cut
    // to the cell (short_clip_labels: start.end, or the row's number where cuts would read the same), the
    // whole name in the tooltip.
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(2.0f, 1.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(3.0f, 1.0f));
    float name_width = ImGui::CalcTextSize("from \\ to").x;
    for (std::size_t i = 0; i < n; ++i)
        name_width =
            std::max(name_width, ImGui::CalcTextSize(grid.clips[i].c_str()).x + ImGui::CalcTextSize("00 ").x);
    name_width += 8.0f;
    const float avail = ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ScrollbarSize;
    const float cell_width = std::clamp((avail - name_width) / static_cast<float>(n) - 4.0f, 38.0f, 72.0f);
    const ImGuiTableFlags flags = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerH;
    const float rows_height = (ImGui::GetFrameHeight() + 2.0f) * static_cast<float>(n + 1) + 8.0f;
    const float height =
        std::min(rows_height, ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeightWithSpacing());
    centres_.assign(n * n, Vec2(0.0f));
    if (ImGui::BeginTable("blend grid", static_cast<int>(n) + 1, flags, ImVec2(0, std::max(80.0f, height)))) {
        ImGui::TableSetupScrollFreeze(1, 1);
        ImGui::TableSetupColumn("from \\ to", ImGuiTableColumnFlags_WidthFixed, name_width);
        const float char_width = std::max(1.0f, ImGui::CalcTextSize("m").x);
        const std::vector<std::string> headers =
            short_clip_labels(grid.clips, static_cast<std::size_t>(cell_width / char_width));
        for (std::size_t to = 0; to < n; ++to)
            ImGui::TableSetupColumn(headers[to].c_str(), ImGuiTableColumnFlags_WidthFixed, cell_width);
        ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
        for (int column = 0; column <= static_cast<int>(n); ++column) {
            ImGui::TableSetColumnIndex(column);
            ImGui::TableHeader(ImGui::TableGetColumnName(column));
            if (column > 0 && ImGui::IsItemHovered())
                ImGui::SetTooltip("to %s", grid.clips[static_cast<size_t>(column - 1)].c_str());
        }
        for (std::size_t from = 0; from < n; ++from) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::AlignTextToFramePadding();
            ImGui::TextDisabled("%zu", from + 1);
            ImGui::SameLine();
            ImGui::TextUnformatted(grid.clips[from].c_str());
            for (std::size_t to = 0; to < n; ++to) {
                ImGui::TableNextColumn();
                cell(dojo, from, to, grid.at(from, to), cell_width);
            }
        }
        ImGui::EndTable();
    }
    ImGui::PopStyleVar(2);
    details(dojo, grid);
}

void DojoBlendGrid::cell(const DojoContext& dojo, std::size_t from, std::size_t to, const BlendCell& cell,
                         float width) {
    const anim::AnimationFile& file = dojo.edits.file();
    const std::string from_name = file.clips[from].name, to_name = file.clips[to].name;
    const bool selected = from_ == static_cast<int>(from) && to_ == static_cast<int>(to);
    const ImVec4 fill = fill_of(cell.source);
    ImGui::PushID(static_cast<int>(from * 1000 + to));
    ImGui::PushStyleColor(ImGuiCol_FrameBg, fill);
    ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, lighter(fill, 0.08f));
    ImGui::PushStyleColor(ImGuiCol_FrameBgActive, lighter(fill, 0.14f));
    if (cell.source == BlendCell::Source::Default)
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, selected ? 2.0f : 0.0f);
    ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1.0f, 0.82f, 0.3f, 1.0f));
    double seconds = cell.seconds;
    ImGui::SetNextItemWidth(width);
    const bool changed = ImGui::DragScalar("##cell", ImGuiDataType_Double, &seconds, 0.005f, &kBlendMin,
                                           &kBlendMax, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    ImGui::PopStyleColor(cell.source == BlendCell::Source::Default ? 5 : 4);
    ImGui::PopStyleVar();
    // Reported only when its centre is inside the grid's visible part (a row half under the table's edge
    // would take a click meant for it on what is drawn there).
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    const ImVec2 centre((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f);
    const ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 clip_lo = draw->GetClipRectMin(), clip_hi = draw->GetClipRectMax();
    if (const std::size_t n = file.clips.size(); centres_.size() == n * n && ImGui::IsItemVisible() &&
                                                 centre.y > clip_lo.y && centre.y < clip_hi.y &&
                                                 centre.x > clip_lo.x && centre.x < clip_hi.x)
        centres_[from * n + to] = Vec2(centre.x, centre.y);
    if (ImGui::IsItemActivated() && !selected) select(dojo, static_cast<int>(from), static_cast<int>(to));
    if (changed) {
        dojo.edits.begin_drag("blend " + from_name + " -> " + to_name);
        if (auto r = set_blend(dojo.edits.file_in_place(), from_name, to_name, seconds); !r)
            dojo.edits.refuse(r.error());
        else
            dojo.edits.changed(), dojo.playback.test_transition(static_cast<int>(from), static_cast<int>(to));
    }
    if (ImGui::IsItemHovered() && !ImGui::IsItemActive())
        ImGui::SetTooltip("%s -> %s: %.3f s (%s)\ndrag, or Ctrl+click to type; right-click to clear",
                          from_name.c_str(), to_name.c_str(), cell.seconds,
                          cell.source == BlendCell::Source::Explicit   ? "set for this pair"
                          : cell.source == BlendCell::Source::Wildcard ? "from a * pair"
                                                                       : "the default");
    if (ImGui::BeginPopupContextItem("cell menu")) {
        ImGui::TextDisabled("%s -> %s", from_name.c_str(), to_name.c_str());
        if (ImGui::MenuItem("Clear (back to the * pairs or the default)", nullptr, false,
                            cell.source == BlendCell::Source::Explicit))
            dojo.edits.apply("clear blend " + from_name + " -> " + to_name,
                             [&](anim::AnimationFile& f) { return clear_blend(f, from_name, to_name); });
        if (ImGui::MenuItem("Preview in the transition tester"))
            select(dojo, static_cast<int>(from), static_cast<int>(to));
        ImGui::EndPopup();
    }
    ImGui::PopID();
}

// The selected cell, where its time comes from, and Clear.
void DojoBlendGrid::details(const DojoContext& dojo, const BlendGrid& grid) {
    if (from_ < 0 || to_ < 0) {
        ImGui::TextDisabled("Select a cell to play that transition in the tester under the preview.");
        return;
    }
    const auto from = static_cast<size_t>(from_), to = static_cast<size_t>(to_);
    if (from >= grid.clips.size() || to >= grid.clips.size()) return;
    const BlendCell& cell = grid.at(from, to);
    ImGui::AlignTextToFramePadding();
    ImGui::Text("%s -> %s: %.2f s, %s", grid.clips[from].c_str(), grid.clips[to].c_str(), cell.seconds,
                cell.source == BlendCell::Source::Explicit   ? "set for this pair"
                : cell.source == BlendCell::Source::Wildcard ? "from a * pair"
                                                             : "the default");
    ImGui::SameLine();
    ImGui::BeginDisabled(cell.source != BlendCell::Source::Explicit);
    if (ImGui::SmallButton("Clear"))
        dojo.edits.apply(
            "clear blend " + grid.clips[from] + " -> " + grid.clips[to],
            [&](anim::AnimationFile& f) { return clear_blend(f, grid.clips[from], grid.clips[to]); });
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Remove this pair: the cell falls back to the * pairs or the default");
    ImGui::SameLine();
    if (dojo.playback.transition()) ImGui::TextDisabled("(in the tester)");
}

} // namespace ks::editor::ui
