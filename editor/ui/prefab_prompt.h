#pragma once
// Edit > Save selection as prefab...: the name (the file's stem, checked by the model as it is typed) and
// the title; a name in use offers Replace. Its own state; works through the document, the log and the
// status file's spots (PanelContext).
#include "model/editor.h"
#include "ui/panel_context.h"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace ks::editor::ui {

class PrefabPrompt {
  public:
    void open(const Editor& editor); // nothing happens without a selection
    void draw(const PanelContext& ctx);
    void status(const Editor& editor, nlohmann::json& status) const; // "prefab_prompt"

  private:
    bool ask_ = false;
    bool open_ = false; // drawn this frame (status file)
    char name_[80] = {};
    char title_[128] = {};
    std::string error_;
};

} // namespace ks::editor::ui
