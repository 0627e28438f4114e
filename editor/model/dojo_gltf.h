#pragma once
// The robot's clips to and from glTF 2.0 (Blender's exchange format), window-free. Export samples each clip
// as it plays from the rest pose (eases and all) at a frame rate into linear keys: every node the clip moves
// gets a rotation track (quaternions) and, when the clip moves it, a translation track; the rig's nodes are
// the file's node hierarchy with their rest transforms. Import maps a glTF's node animations onto the rig by
// node name and turns each into a clip of absolute, linear keys (Euler XYZ chosen continuous from key to
// key), reporting what did not map. The file I/O is modelio's (gltf_animation.h, through assimp); this file
// joins it to anim's clips, which only the editor sees together (docs/animation.md, "Clips to and from
// Blender").
#include "anim/clip.h"
#include "anim/rig.h"
#include "core/result.h"
#include "modelio/gltf_animation.h"

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace ks::editor {

inline constexpr double kGltfExportFps = 60.0;

// Clips `clips` of `file` (all of them when empty) as glTF animations on `rig`, sampled at `fps`: a key at
// every frame and one at the clip's end.
Result<modelio::AnimatedScene> clips_to_gltf_scene(const anim::AnimationFile& file, const anim::Rig& rig,
                                                   std::span<const std::size_t> clips,
                                                   double fps = kGltfExportFps);
Result<void> export_clips_gltf(const anim::AnimationFile& file, const anim::Rig& rig,
                               std::span<const std::size_t> clips, const std::filesystem::path& path,
                               double fps = kGltfExportFps);

struct GltfImportReport {
    std::vector<std::string> added, replaced; // clip names
    std::vector<std::string> unmapped;        // a line per animated node the rig has not, per ignored channel
    std::string summary() const;              // one line for the panel and the script's log
};

// Reads `path` and puts one clip per animation into `file`: a clip of the same name has its keys replaced
// (its loop mode, next, events and blends stay), any other is added (loop "once"). Names are made clip names
// (other characters become '_'). Step keys become a hold and a 0 s key; cubic-spline tangents are dropped
// (reported). Refused, with `file` unchanged: a file modelio refuses, an animation none of whose nodes is in
// the rig, no animation matching the rig at all (the error lists both node lists), a result anim::validate
// refuses. One undo step when wrapped in apply_dojo_edit.
Result<GltfImportReport> import_clips_gltf(anim::AnimationFile& file, const anim::Rig& rig,
                                           const std::filesystem::path& path);
// The same from a scene already read (`source` names it in errors).
Result<GltfImportReport> import_clips_gltf(anim::AnimationFile& file, const anim::Rig& rig,
                                           const modelio::AnimatedScene& scene, const std::string& source);

} // namespace ks::editor
