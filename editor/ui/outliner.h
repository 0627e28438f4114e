#pragma once
// The left column's Outliner and Layers tabs (outliner_tree.cpp): the player start's row, groups as a tree
// and the entities in no group (or, with a type filter or a search, a flat list of the matches), each row's
// eye, lock and issue badge; the layers' eye, lock, active radio, name, count and delete. The tree and the
// counts are rebuilt only when the level or its issues change.
#include "ui/panel_context.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ks::editor::ui {

// The left column's tabs (the window arranges them: panels.cpp).
enum class LeftTab { Outliner, Layers, Prefabs };
std::optional<LeftTab> parse_left_tab(std::string_view name); // "outliner", "layers", "prefabs"
const char* left_tab_name(LeftTab tab);

// The outliner's tree, rebuilt when the level changes: each group's members, the entities in no group,
// and each entity's issue counts.
struct OutlinerTree {
    std::uint64_t revision = ~0ull;
    size_t issue_count = ~size_t(0);
    std::vector<int> top_groups; // groups in no group
    std::vector<int> loose;      // indices into level.entities of the entities in no group
    std::vector<int> filtered;   // indices of the entities a type filter or search shows (flat list)
    int filter_type = -2;        // the type filter and search the flat list is for
    std::string filter_search;
    std::vector<std::pair<int, int>> issues; // per entity index: errors, warnings
    std::vector<int> layer_counts;           // entities per layer
};

class Outliner {
  public:
    void refresh(Editor& editor); // cheap unless the level or its issues changed
    void outliner_tab(const PanelContext& ctx);
    void layers_tab(const PanelContext& ctx);
    const std::vector<int>& layer_counts() const { return tree_.layer_counts; } // the status file

  private:
    void tree(const PanelContext& ctx);
    void player_start_row(const PanelContext& ctx);
    void group_node(const PanelContext& ctx, const level::Group& group);
    void entity_row(const PanelContext& ctx, int index);
    void group_context_menu(const PanelContext& ctx, const level::Group& group);
    void rename_group_popup(const PanelContext& ctx);

    int type_filter_ = -1; // -1: all
    int scrolled_to_ = 0;  // the primary selection the list last scrolled to
    char search_[64] = {};
    OutlinerTree tree_;
    int rename_group_ = 0;  // the group the rename popup is for
    int rename_layer_ = -1; // the layer whose name is being edited inline
    char rename_buffer_[128] = {};
    bool focus_rename_ = false;
};

} // namespace ks::editor::ui
