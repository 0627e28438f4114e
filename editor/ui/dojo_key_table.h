#pragma once
// The selected key's (phase's) editor: the key list, Duplicate / Remove / Earlier / Later, its duration and
// easing (with the easing's curve), one row per keyed node (rotation, position offset, mode, remove) and
// Add key. Every change is one step of the dojo's history (a dragged field is one step).
#include "ui/dojo_context.h"

namespace ks::editor::ui {

class DojoKeyTable {
  public:
    void draw(const DojoContext& dojo);

  private:
    bool phase_buttons(const DojoContext& dojo); // true when the phases changed
    bool phase_timing(const DojoContext& dojo, anim::PhaseDef& phase);
    bool target_rows(const DojoContext& dojo, anim::PhaseDef& phase, std::string& remove_node);
    bool add_key_row(const DojoContext& dojo);

    int add_node_ = 0; // the "Add key" combo's choice among the unkeyed nodes
};

} // namespace ks::editor::ui
