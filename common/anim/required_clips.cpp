#include "anim/required_clips.h"

namespace ks::anim {
namespace {

constexpr RequiredClip kRequired[] = {
    {"idle", "the game plays 'idle' while a robot wanders or patrols"},
    {"alert", "the game plays 'alert' when a robot sees the player"},
    {"shoot_pose", "the game plays 'shoot_pose' when a robot takes aim"},
    {"shooting", "the game plays 'shooting' at each robot shot"},
    {"shoot_pose_reverse", "the game plays 'shoot_pose_reverse' when a robot lowers its arms"},
    {"death", "the game plays 'death' when a robot dies"},
    {"reset", "the Dojo's key 0 plays 'reset' to put the robot back in its rest pose"},
};

} // namespace

std::span<const RequiredClip> required_robot_clips() {
    return kRequired;
}

const RequiredClip* find_required_clip(std::string_view name) {
    for (const RequiredClip& r : kRequired)
        if (name == r.name) return &r;
    return nullptr;
}

std::vector<Issue> check_required_clips(const AnimationFile& file) {
    std::string missing;
    int count = 0;
    for (const RequiredClip& r : kRequired)
        if (!file.find_clip(r.name)) {
            missing += (missing.empty() ? "'" : ", '") + std::string(r.name) + "'";
            ++count;
        }
    if (count == 0) return {};
    std::string every;
    for (const RequiredClip& r : kRequired) every += (every.empty() ? "" : ", ") + std::string(r.name);
    return {Issue{JsonPath() / "clips",
                  std::string(count == 1 ? "the robot's required clip " : "the robot's required clips ") +
                      missing + (count == 1 ? " is" : " are") + " missing",
                  "the game and the Dojo play " + every + ": add the missing ones (a new clip, or Reload)"}};
}

} // namespace ks::anim
