// Robots made: the clips the AI plays (checked once per game), and a robot's record, body and animation
// player, for the level's robots and the spawners' alike.
#include "game/robot_system.h"

#include "core/log.h"
#include "core/paths.h"

#include <algorithm>

namespace ks::game {

RobotSystem::RobotSystem(GameCore& core, PlayerSystem& player, Explosives& explosives,
                         std::shared_ptr<const anim::AnimationLibrary> animations)
    : core_(core), player_(player), explosives_(explosives), animations_(std::move(animations)) {}

Result<void> RobotSystem::find_clips() {
    const anim::ClipSet& clips = animations_->clips;
    // Problems are the file's that was read (a --clips file, a designer's copy), not the shipped one's.
    const std::string source = animations_->source.empty() ? paths::asset("animations/robot.json").string()
                                                           : animations_->source.string();
    auto need = [&](const char* name, int& out) -> Result<void> {
        out = clips.find(name);
        if (out < 0)
            return Error(std::string("robot animations lack the clip \"") + name + "\"", Location(source),
                         "the game needs idle, alert, shoot_pose, shooting, shoot_pose_reverse and death");
        return ok();
    };
    for (auto [name, slot] : {std::pair{"idle", &clips_.idle},
                              {"alert", &clips_.alert},
                              {"shoot_pose", &clips_.shoot_pose},
                              {"shooting", &clips_.shooting},
                              {"shoot_pose_reverse", &clips_.shoot_pose_reverse},
                              {"death", &clips_.death}})
        if (auto r = need(name, *slot); !r) return r;
    const auto& shooting_events = clips.clips[static_cast<std::size_t>(clips_.shooting)].events;
    shot_on_event_ = std::any_of(shooting_events.begin(), shooting_events.end(),
                                 [](const anim::ClipEvent& e) { return e.name == kMuzzleFlashEvent; });
    if (!shot_on_event_) // the robots still shoot, but the animator should know why the timing is off
        log::warn(source,
                  ": the \"shooting\" clip has no \"muzzle_flash\" event, so robots fire as the clip starts; "
                  "add one where the shot should leave the hand, e.g. \"events\": [{\"time\": 0, \"name\": "
                  "\"muzzle_flash\", \"sound\": \"robot_shot\"}] (the editor's dojo panel adds events on its "
                  "timeline)");
    warn_missing_event_sounds(source);
    alert_length_ = static_cast<float>(clips.clips[clips_.alert].duration);
    aim_length_ = static_cast<float>(clips.clips[clips_.shoot_pose].duration);
    death_length_ = static_cast<float>(clips.clips[clips_.death].duration);
    hand_tip_node_ = animations_->rig.find("hand_r_tip");
    if (hand_tip_node_ < 0) {
        hand_tip_node_ = animations_->rig.find("hand_r");
        if (hand_tip_node_ >= 0)
            log::warn(source, ": the rig has no \"hand_r_tip\" node, so robot shots start at \"hand_r\" "
                              "(the wrist) instead of the hand's tip; add the node (a child of hand_r at the "
                              "fingertips) to the rig");
    }
    if (hand_tip_node_ < 0)
        return Error("the robot rig has no hand_r_tip node (nor hand_r)", Location(source),
                     "robot shots start at the right hand's tip: add hand_r and hand_r_tip to the rig");
    return ok();
}

// A clip event's sound that is not a file of assets/sounds plays nothing: said once, at load.
void RobotSystem::warn_missing_event_sounds(const std::string& source) const {
    const anim::ClipSet& clips = animations_->clips;
    for (const auto& clip : clips.clips)
        for (const anim::ClipEvent& e : clip.events) {
            if (e.sound.empty()) continue;
            std::error_code ec;
            if (std::filesystem::is_regular_file(paths::asset("sounds/" + e.sound + ".wav"), ec)) continue;
            log::warn(source, ": clip \"", clip.name, "\", event \"", e.name, "\" plays sound \"", e.sound,
                      "\", which is not in assets/sounds (no ", e.sound,
                      ".wav there); name a file of that folder without .wav, or leave \"sound\" out");
        }
}

void RobotSystem::prepare(std::size_t count, float gravity) {
    robots_.reserve(count);
    anims_.reserve(count);
    gravity_ = gravity;
}

Result<void> RobotSystem::add(const level::Entity& e) {
    using physics::Shape;
    const auto& rp = e.as<level::RobotProps>();
    if (rp.dummy) return ok(); // the dojo's animation dummy: no AI, not in physics
    const GameSettings& settings = core_.settings;
    const float yaw = radians(e.rotation.x);
    Robot r;
    r.entity_id = e.id;
    r.props = rp;
    r.feet = e.position;
    r.yaw = yaw;
    r.health = rp.health;
    r.wander_from = r.wander_to = yaw;
    r.wander_length = 0.0f; // first idle step draws a new wander
    r.dormant = rp.dormant;
    physics::BodyDesc d;
    d.shape = Shape::capsule(settings.robot_radius, settings.robot_height * 0.5f - settings.robot_radius);
    d.transform = {e.position + Vec3(0, settings.robot_height * 0.5f + d.character.skin, 0),
                   Quat(1, 0, 0, 0)};
    d.motion = physics::Motion::Character;
    d.layers = physics::layer::kSolid | physics::layer::kShootable | physics::layer::kCharacter;
    d.user_data = pack_user(BodyKind::Robot, static_cast<std::uint32_t>(robots_.size()));
    d.movement.gravity = gravity_;
    d.movement.max_speed = 200.0f;
    auto id = core_.world.add(d, entity_label(e));
    if (!id) return id.error();
    r.body = *id;
    if (navigation_) r.path.reserve(kMaxPathCorners); // the level's robots: when the mesh is built
    robots_.push_back(std::move(r));
    anims_.emplace_back(animations_->clips, animations_->rig);
    anims_.back().play(clips_.idle, 0.0f);
    return ok();
}

} // namespace ks::game
