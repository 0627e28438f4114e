// The Play-test report panel (bottom strip) and Play > Analyze: the autoplay bot's runs of the level being
// edited (ui/analysis_view.h), and what the status file says of them.
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

void EditorApp::start_analysis() {
    analysis_.start(editor_.level(), editor_.file_path());
}

void EditorApp::analysis_panel(float x, float y, float w, float h) {
    const bool continuous = editor_.history().in_transaction() || ImGui::IsAnyItemActive();
    analysis_.update(editor_.level(), editor_.revision(), continuous, editor_.file_path());
    place_panel(x, y, w, h);
    ImGui::Begin("Play-test report", nullptr, kPanelFlags);
    analysis_.panel(editor_.level(), editor_.file_path(), spots_);
    ImGui::End();
}

void EditorApp::analysis_status(nlohmann::json& s) const {
    nlohmann::json a = {{"running", analysis_.running()},
                        {"progress", analysis_.progress()},
                        {"runs_done", analysis_.runs_done()},
                        {"runs", analysis_.runs},
                        {"overlay", analysis_.overlay},
                        {"stale", analysis_.stale()},
                        {"file", analysis_.report_file().string()}};
    if (const game::PlaytestReport* r = analysis_.report())
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
