#include "game/robot_rig.h"

#include "anim/gltf_rig.h"
#include "core/log.h"
#include "core/paths.h"

namespace ks::game {

Result<anim::Rig> rig_with_model_offsets(const anim::Rig& rig, const std::filesystem::path& gltf) {
    auto model = anim::load_gltf_rig(gltf);
    if (!model) return model.error();
    return rig.with_rest_from(*model);
}

Result<std::shared_ptr<const anim::AnimationLibrary>> load_robot_animations() {
    return load_robot_animations(paths::asset("animations/robot.json"));
}

Result<std::shared_ptr<const anim::AnimationLibrary>>
load_robot_animations(const std::filesystem::path& clips) {
    auto lib = anim::load_animation_library(clips);
    if (!lib) return lib.error();
    const auto model = paths::asset("models/robot.gltf");
    auto rig = rig_with_model_offsets(lib->rig, model);
    if (!rig) {
        log::warn("robot shots use the clip file's joint offsets: " + rig.error().str());
    } else if (auto clips = anim::compile(lib->file, *rig); !clips) {
        log::warn("robot clips do not fit the model's rig, using the clip file's: " + clips.error().str());
    } else {
        lib->rig = std::move(*rig);
        lib->clips = std::move(*clips);
    }
    return std::make_shared<const anim::AnimationLibrary>(std::move(*lib));
}

} // namespace ks::game
