#pragma once
// The dojo's way to and from Blender: "Export clip to glTF..." (the shown clip, or every clip) and "Import
// clips from glTF..." beside Save, each asking for a file path in a small modal. The work is window-free
// (model/dojo_gltf.h); an import is one undo step, and a refused file changes nothing and says why.
#include "ui/dojo_context.h"

#include <string>

namespace ks::editor::ui {

class DojoGltfPrompt {
  public:
    void buttons(const DojoContext& dojo); // on the file row
    void prompt(const DojoContext& dojo);  // the modal, inside the dojo window

  private:
    enum class Ask : std::uint8_t { None, Export, Import };
    void open(Ask ask);
    void run(const DojoContext& dojo);

    Ask ask_ = Ask::None;
    bool open_ = false;
    bool all_clips_ = false;
    std::string path_;
    std::string error_; // the last refusal, shown in the modal
};

} // namespace ks::editor::ui
