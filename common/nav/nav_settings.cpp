#include "nav/nav_settings.h"

#include <cmath>
#include <string>

namespace ks::nav {
namespace {

bool positive_finite(float v) {
    return std::isfinite(v) && v > 0.0f;
}

Error settings_error(const std::string& what, const std::string& hint) {
    return Error("navigation settings: " + what, Location{}, hint);
}

} // namespace

NavSettings robot_nav_settings(float step_height, float max_slope_degrees) {
    NavSettings s;
    s.agent_radius = level::kRobotRadius;
    s.agent_height = level::kRobotHeight;
    s.agent_climb = step_height;
    s.agent_max_slope_degrees = max_slope_degrees;
    return s;
}

NavSettings player_nav_settings(float step_height, float max_slope_degrees) {
    NavSettings s = robot_nav_settings(step_height, max_slope_degrees);
    s.agent_radius = level::kPlayerRadius;
    s.agent_height = level::kPlayerHeight;
    return s;
}

std::optional<Error> check_settings(const NavSettings& s) {
    if (!positive_finite(s.agent_radius) || !positive_finite(s.agent_height))
        return settings_error("agent radius and height must be positive", "use nav::robot_nav_settings");
    if (!std::isfinite(s.agent_climb) || s.agent_climb < 0.0f)
        return settings_error("agent climb must be 0 or more", "pass the character's step height");
    if (!(s.agent_max_slope_degrees > 0.0f && s.agent_max_slope_degrees < 90.0f))
        return settings_error("agent max slope must be in (0, 90) degrees",
                              "pass the character's max_slope_degrees to nav::robot_nav_settings");
    if (!positive_finite(s.cell_size) || !positive_finite(s.cell_height))
        return settings_error("cell size and cell height must be positive", "the defaults are 0.2 and 0.05");
    const AgentCells cells = agent_cells(s);
    if (s.tile_size_cells < 2 * (cells.radius + 3) || s.tile_size_cells > 1024)
        return settings_error("tile size of " + std::to_string(s.tile_size_cells) +
                                  " cells is outside [2 * (agent radius in cells + 3), 1024]",
                              "the default is 64");
    if (cells.height > 255 || cells.climb > 255)
        return settings_error("cell height too small for the agent (over 255 cells tall)",
                              "raise cell_height");
    if (s.max_path_polygons < 16 || s.max_search_nodes < 64 || s.max_search_nodes > 65535)
        return settings_error("path and search limits too small or too large",
                              "max_path_polygons >= 16, max_search_nodes in [64, 65535]");
    if (!positive_finite(s.query_extents.x) || !positive_finite(s.query_extents.y) ||
        !positive_finite(s.query_extents.z))
        return settings_error("query extents must be positive", "the default is 2 x 2 x 2");
    return std::nullopt;
}

AgentCells agent_cells(const NavSettings& s) {
    // A tiny allowance keeps exact multiples (0.8 / 0.2) from rounding up a whole extra cell.
    constexpr float kSlack = 1e-4f;
    AgentCells c;
    c.radius = static_cast<int>(std::ceil(s.agent_radius / s.cell_size - kSlack));
    c.height = static_cast<int>(std::ceil(s.agent_height / s.cell_height - kSlack));
    c.climb = static_cast<int>(std::floor(s.agent_climb / s.cell_height + kSlack));
    return c;
}

} // namespace ks::nav
