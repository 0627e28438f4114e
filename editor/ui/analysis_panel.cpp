// The Play-test report panel (bottom strip) and Play > Analyze: the autoplay bot's runs of the level being
// edited (ui/analysis_view.h), and what the status file says of them.
#include "ui/analysis_view.h"
#include "ui/panel_style.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

void AnalysisView::window(const Editor& editor, UiSpots& spots, const Rect& rect) {
    const bool continuous = editor.history().in_transaction() || ImGui::IsAnyItemActive();
    update(editor.level(), editor.revision(), continuous, editor.file_path());
    place_panel(rect.x, rect.y, rect.w, rect.h);
    ImGui::Begin("Play-test report", nullptr, kPanelFlags);
    panel(editor.level(), editor.file_path(), spots);
    ImGui::End();
}

void AnalysisView::status(nlohmann::json& s) const {
    nlohmann::json a = {
        {"running", running()}, {"progress", progress()}, {"runs_done", runs_done()},      {"runs", runs},
        {"overlay", overlay},   {"stale", stale()},       {"file", report_file().string()}};
    if (const game::PlaytestReport* r = report())
        a["report"] = {{"completed", r->runs.size()},
                       {"requested", r->requested},
                       {"wins", r->wins},
                       {"deaths", r->deaths},
                       {"cancelled", r->cancelled},
                       {"damage_cells", r->damage_heat.cells.size()},
                       {"level_hash", r->level_hash}};
    s["analysis"] = a;
}

} // namespace ks::editor::ui
