#include "anim/dojo.h"

#include <algorithm>
#include <cstdio>

namespace ks::anim {

std::vector<std::string> reference_dojo_clips() {
    return {"alert", "shoot_pose", "shooting", "shoot_pose_reverse", "death"};
}

std::vector<std::string> dojo_key_clips(const ClipSet& clips, const std::string& reset_clip) {
    std::vector<std::string> keys = reference_dojo_clips();
    const std::size_t reference = keys.size();
    for (const Clip& clip : clips.clips) {
        if (keys.size() >= 9) break;
        if (clip.name == reset_clip) continue;
        if (std::find(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(reference), clip.name) !=
            keys.begin() + static_cast<std::ptrdiff_t>(reference))
            continue;
        keys.push_back(clip.name);
    }
    return keys;
}

ClipSet anchor_root_to_rest(const ClipSet& clips, const Rig& rig) {
    ClipSet anchored = clips;
    for (Clip& clip : anchored.clips)
        for (int node = 0; node < rig.size(); ++node) {
            if (rig.node(node).parent >= 0) continue;
            for (const bool position : {false, true}) {
                const Vec3 rest = position ? rig.node(node).rest_position : rig.node(node).rest_euler;
                const auto channel =
                    std::find_if(clip.channels.begin(), clip.channels.end(), [&](const Channel& c) {
                        return c.node == node && c.is_position == position;
                    });
                if (channel == clip.channels.end()) { // the clip leaves the root alone: hold it at rest
                    Channel hold;
                    hold.node = node;
                    hold.is_position = position;
                    hold.first_key = static_cast<std::uint32_t>(clip.keys.size());
                    hold.key_count = 1;
                    clip.keys.push_back(Key{0.0, rest, KeyMode::Absolute, Ease::linear()});
                    clip.channels.push_back(hold);
                    continue;
                }
                // Relative keys (the implicit start key, add_rot, add_pos) count from the rest, not from
                // wherever the root was when the clip started.
                for (std::uint32_t k = 0; k < channel->key_count; ++k) {
                    Key& key = clip.keys[channel->first_key + k];
                    if (key.mode != KeyMode::FromStart) continue;
                    key.value = rest + key.value;
                    key.mode = KeyMode::Absolute;
                }
            }
        }
    return anchored;
}

Result<DojoController> DojoController::create(const ClipSet& clips, const Rig& rig,
                                              const std::vector<std::string>& key_clips,
                                              const std::string& reset_clip) {
    if (key_clips.size() > 9) return Error("the Dojo has keys 1-9 only", {}, "bind at most 9 clips");
    DojoController dojo;
    std::vector<std::string> missing;
    auto bind = [&](char key, const std::string& name) {
        const int index = clips.find(name);
        if (index < 0) missing.push_back(name);
        dojo.entries_.push_back({key, name, index});
    };
    for (std::size_t i = 0; i < key_clips.size(); ++i) bind(static_cast<char>('1' + i), key_clips[i]);
    for (std::size_t i = 0; i < clips.clips.size(); ++i) {
        const std::string& name = clips.clips[i].name;
        const bool keyed = std::find(key_clips.begin(), key_clips.end(), name) != key_clips.end();
        if (!keyed && name != reset_clip) dojo.entries_.push_back({0, name, static_cast<int>(i)});
    }
    if (!reset_clip.empty()) bind('0', reset_clip);
    if (!missing.empty()) {
        std::string names, known;
        for (const std::string& m : missing) names += (names.empty() ? "'" : ", '") + m + "'";
        for (const Clip& c : clips.clips) known += (known.empty() ? "" : ", ") + c.name;
        return Error("Dojo keys name clips that do not exist: " + names, {}, "known clips: " + known);
    }
    dojo.anchored_ = std::make_unique<const ClipSet>(anchor_root_to_rest(clips, rig));
    dojo.player_ = std::make_unique<Player>(*dojo.anchored_, rig);
    return dojo;
}

bool DojoController::press(char key) {
    if (key == 0) return false; // the entries without a key
    for (std::size_t i = 0; i < entries_.size(); ++i)
        if (entries_[i].key == key) return play_entry(i);
    return false;
}

bool DojoController::play_entry(std::size_t entry) {
    if (entry >= entries_.size()) return false;
    player_->play(entries_[entry].index);
    return true;
}

int DojoController::playing_entry() const {
    const int playing = player_->current_clip();
    for (std::size_t i = 0; i < entries_.size(); ++i)
        if (playing >= 0 && entries_[i].index == playing) return static_cast<int>(i);
    return -1;
}

std::string DojoController::entry_line(const DojoKey& entry) {
    return std::string(1, entry.key == 0 ? ' ' : entry.key) + "  " + entry.clip;
}

std::vector<std::string> DojoController::legend() const {
    std::vector<std::string> lines;
    for (const DojoKey& k : entries_) lines.push_back(entry_line(k));
    const int playing = player_->current_clip();
    char time[32];
    std::snprintf(time, sizeof time, "%.2f s", player_->clip_time());
    lines.push_back(playing < 0 ? std::string("playing: (rest pose)")
                                : "playing: " + anchored_->clips[static_cast<std::size_t>(playing)].name +
                                      "  " + time + (player_->blending() ? "  (blending)" : ""));
    return lines;
}

} // namespace ks::anim
