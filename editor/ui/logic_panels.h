#pragma once
// The level logic's widgets: the inspector's Links and Objectives tabs, the link-list widget they and the
// level's section share (link_list.cpp, objectives_panel.cpp), and pick mode (link_pick.cpp: a link's target
// or a name to kill by a click in the viewport). It works through the document, the log, the status file's
// spots and the window's cursor; the viewport hands it the entity a pick click hit and draws its hint.
#include "model/editor.h"
#include "ui/editor_log.h"
#include "ui/ui_spots.h"
#include "view/link_options.h"
#include "view/link_problems.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

struct ImDrawList;
struct GLFWcursor;
struct GLFWwindow;

namespace ks::editor::ui {

// Pick mode (link_pick.cpp): what the next click on an entity in the viewport is for.
enum class PickPurpose { LinkTarget, KillName };
struct PickRequest {
    PickPurpose purpose = PickPurpose::LinkTarget;
    LinkOwner owner; // LinkTarget: whose link
    int index = 0;   // LinkTarget: the link; KillName: the objective
};

class LogicPanels {
  public:
    LogicPanels(Editor& editor, EditorLog& log, UiSpots& spots, GLFWwindow* window)
        : editor_(editor), log_(log), spots_(spots), window_(window) {}
    ~LogicPanels();
    LogicPanels(const LogicPanels&) = delete;
    LogicPanels& operator=(const LogicPanels&) = delete;

    // The level checks' findings, redone at the start of a frame after a change: the pointers the widgets
    // take into logic_problems_ stay valid for the whole frame.
    void refresh_problems();

    void links_tab(); // the inspector's Links tab: the selected entity's links and those acting on it
    void objectives_tab();
    // The link-list widget; `spot` names its widgets in the status file ("link0.event").
    void link_list(const LinkOwner& owner, const std::string& spot);

    bool picking() const { return pick_.has_value(); }
    void end_pick();
    void pick_click(int entity_id);                // the viewport's left click while picking (0: nothing)
    void pick_hint(ImDrawList* draw, Vec2 origin); // the hint over the viewport and the crosshair
    void pick_status(nlohmann::json& status) const;

  private:
    void begin_pick(PickRequest request);
    bool link_row(const LinkOwner& owner, int index, const std::vector<std::string>& events,
                  const std::string& spot); // false: the list changed
    // The link's target (an entity is named first if it needs a name) and an action it takes: one step.
    Result<void> apply_link_target(const LinkOwner& owner, int index, const TargetOption& option);
    bool target_widgets(const LinkOwner& owner, int index, const level::Link& link, float width,
                        const std::string& spot); // true: the target changed
    bool objective_item(int index);               // false: the list changed
    bool kill_list(int index, const level::Objective& objective, const std::string& path);
    Result<void> add_kill_name(int objective, int entity_id); // naming the entity if needed: one step
    void log_line(std::string line, bool error = false) { log_.line(std::move(line), error); }
    void report(const Result<void>& result, const char* what) { log_.report(result, what); }

    Editor& editor_;
    EditorLog& log_;
    UiSpots& spots_;
    GLFWwindow* window_;
    std::optional<PickRequest> pick_;
    std::string pick_message_; // the hint over the viewport while picking
    GLFWcursor* crosshair_ = nullptr;
    std::vector<LogicProblem> logic_problems_;
    std::uint64_t problems_revision_ = ~0ull;
};

} // namespace ks::editor::ui
