#include "anim/dojo.h"

#include <cstdio>

namespace ks::anim {

std::vector<std::string> reference_dojo_clips() {
    return {"alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death"};
}

Result<DojoController> DojoController::create(const ClipSet& clips, const Rig& rig,
                                              const std::vector<std::string>& key_clips,
                                              const std::string& reset_clip) {
    if (key_clips.size() > 9) return Error("the Dojo has keys 1-9 only", {}, "bind at most 9 clips");
    DojoController dojo(clips, rig);
    std::vector<std::string> missing;
    auto bind = [&](char key, const std::string& name) {
        const int index = clips.find(name);
        if (index < 0) missing.push_back(name);
        dojo.keys_.push_back({key, name, index});
    };
    for (std::size_t i = 0; i < key_clips.size(); ++i) bind(static_cast<char>('1' + i), key_clips[i]);
    if (!reset_clip.empty()) bind('0', reset_clip);
    if (!missing.empty()) {
        std::string names, known;
        for (const std::string& m : missing) names += (names.empty() ? "'" : ", '") + m + "'";
        for (const Clip& c : clips.clips) known += (known.empty() ? "" : ", ") + c.name;
        return Error("Dojo keys name clips that do not exist: " + names, {}, "known clips: " + known);
    }
    return dojo;
}

bool DojoController::press(char key) {
    for (const DojoKey& k : keys_)
        if (k.key == key) {
            player_.play(k.index);
            return true;
        }
    return false;
}

std::vector<std::string> DojoController::legend() const {
    std::vector<std::string> lines;
    for (const DojoKey& k : keys_) lines.push_back(std::string(1, k.key) + "  " + k.clip);
    const int playing = player_.current_clip();
    char time[32];
    std::snprintf(time, sizeof time, "%.2f s", player_.clip_time());
    lines.push_back(playing < 0 ? std::string("playing: (rest pose)")
                                : "playing: " + clips_->clips[static_cast<std::size_t>(playing)].name + "  " +
                                      time + (player_.blending() ? "  (blending)" : ""));
    return lines;
}

} // namespace ks::anim
