#pragma once
// The dojo's clip management: the clip list (name, length, loop mode, events, a lock on the clips the game
// needs), New (empty, or from the pose shown), Duplicate, Rename, Delete and the loop mode of the shown
// clip. Each is one undo step through model/dojo_clips.h; a refusal (a required clip, a taken name) shows
// the model's message under the list.
#include "ui/dojo_context.h"

#include <optional>

namespace ks::editor::ui {

class DojoClipList {
  public:
    void toolbar(const DojoContext& dojo); // the file's name, New / Duplicate / Rename / Delete
    void list(const DojoContext& dojo);
    void loop_row(const DojoContext& dojo); // once / loop / ping-pong / next for the shown clip
    void dialog(const DojoContext& dojo);   // the New / Rename popup, drawn at the window's level

  private:
    enum Dialog : int { kNoDialog, kNewEmpty, kNewFromPose, kRename };
    void open_dialog(const DojoContext& dojo, Dialog kind);
    void create_clip(const DojoContext& dojo, const std::string& name);

    // The list folded to one combo row (room for the pages): the animator's choice, else folded while the
    // column is under 18 lines high (960x540 and smaller); the toolbar decides for the frame.
    std::optional<bool> folded_;
    bool folded_now_ = false;
    bool folded() const;
    float rows_ = 0; // rows the splitter under the list gives it; 0: three tenths of the column
    Dialog dialog_ = kNoDialog;
    bool open_dialog_ = false;
    char name_[64] = {};
};

} // namespace ks::editor::ui
