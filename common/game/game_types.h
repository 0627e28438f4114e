#pragma once
// The vocabulary the game shares with its drivers (keyboard, autoplay bot, replay file) and with the
// renderer: the per-step input, the per-step events and the tunable game settings. Plain data only.
#include "core/math.h"
#include "game/difficulty.h"
#include "level/entity_shapes.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace ks::game {

// One fixed step of input. The keyboard, the bot and a replay file all produce exactly this.
struct Input {
    float move_forward = 0.0f; // -1..1 (W/S)
    float move_right = 0.0f;   // -1..1 (D/A); the pair is normalised when longer than 1
    float look_yaw = 0.0f;     // radians to add to the view yaw this step (positive turns left)
    float look_pitch = 0.0f;   // radians to add to the view pitch (positive looks up)
    bool jump = false;
    bool fire = false;     // one shot this step (the runtime sets it on a click, not while held)
    bool interact = false; // E pressed this step
    bool pause = false;    // toggles pause (Esc); a paused game ignores everything else
    bool operator==(const Input&) const = default;
};

enum class Phase : std::uint8_t { Playing, Dead, Won };

enum class EventType : std::uint8_t {
    ShotFired, // player shot: position = rifle tip, end = where the ray stopped
    RobotShot, // robot shot (fired or dry): position = hand tip, end = where the ray stopped
    // A shot (the player's or a robot's) hit something: position = point, end = surface normal, entity =
    // what (-1: player or scenery), amount = damage to the player (> 0 only when it hit the player).
    Hit,
    RobotHurt,      // entity = robot, amount = damage
    RobotAlerted,   // entity = robot
    RobotDied,      // entity = robot, after its death clip; the robot is removed
    Explosion,      // position = centre, amount = blast radius (robot deaths: 0, visual only)
    PickupTaken,    // entity = pickup, amount = what was added
    DoorToggled,    // entity = door, amount = 1 opening / 0 closing
    LightToggled,   // entity = floor light, amount = 1 on / 0 off
    CaptionChanged, // the caption text or visibility changed
    PlayerDamaged,  // amount = damage before the shield; position = where it came from (the robot's hand
                    // tip, the blast centre), end = the player's eye then (both the eye: no source, a fall)
    PlayerDied,
    Won,
    Paused,    // amount = 1 paused / 0 resumed
    Footstep,  // the player's foot: position = feet, amount = 0 on a floor, 1 on stairs (a slope)
    Jump,      // the player left the ground
    Land,      // the player landed: amount = downward speed at touch-down
    DryFire,   // fire with an empty magazine: position = eye
    ShieldHit, // the shield absorbed damage: amount = absorbed (PlayerDamaged follows with the total)
    ClipCue,   // a robot's animation clip passed an event: entity = robot, cue = the event's sound (may be
               // empty), position = the robot's centre
    // Level logic (game/level_logic.h):
    Used,               // the player pressed E on it: entity = door, floor light or control panel
    LockedDoorUsed,     // E at a locked door (nothing opens): entity = door, position = the doorway
    ObjectiveCompleted, // cue = the objective's id, amount = its index in Game::logic().objectives()
    MessageShown,       // entity = message, cue = its text, amount = seconds on screen
    SoundPlayed,        // a play link: entity = sound emitter, position = its point, cue = its sound name,
                        // amount = its volume, end.x = its radius
    RobotSpawned,       // entity = the new robot, position = its feet, amount = the spawner's entity id
};

struct Event {
    EventType type = EventType::ShotFired;
    Vec3 position{0.0f};
    Vec3 end{0.0f};
    int entity = -1; // level entity id
    float amount = 0.0f;
    std::string_view cue; // ClipCue: the clip event's sound name (owned by the game's clip set)
};

// Gameplay numbers that are not per entity in the level file (reference values, seed-facts §5).
struct GameSettings {
    double step = 1.0 / 120.0;
    float player_speed = 15.0f;
    float jump_speed = 15.0f;
    float player_radius = level::kPlayerRadius; // capsule: radius 1, height 3, eye at feet + 3
    float player_height = level::kPlayerHeight;
    float eye_height = 3.0f;
    float max_health = 100.0f, start_health = 100.0f;
    float max_shield = 50.0f, start_shield = 0.0f;
    int max_ammo = 400, start_ammo = 150;
    float shot_range = 500.0f;
    float player_shot_damage = 20.0f; // damage a robot takes per player hit (5 hits kill a 100 hp robot)
    float interact_reach = 6.0f;      // floor lights and the panel: eye-to-surface distance for E
    float interact_view_cos = 0.34f;  // in view: within ~70° of the horizontal view direction
    float robot_radius = level::kRobotRadius; // robots: capsule of height 3
    float robot_height = level::kRobotHeight;
    float robot_same_level = 6.0f; // |Δy| below which a robot considers the player on its level
    float robot_shot_range = 100.0f;
    float robot_wander_speed = 2.4f;    // 0.3 · velocity 8 in the reference
    float robot_replan_interval = 0.5f; // seconds between path plans toward a goal that has not moved much
    float robot_search_radius = 6.0f;   // searching robots look around within this of the last known position
    float cylinder_fuse = 0.12f;        // seconds between a cylinder taking blast damage and exploding
    float knockback_decay = 4.0f;       // 1/s: how fast an explosion's push fades
    float fall_limit = -50.0f;          // a character below this y is dead (fell out of the level)
    float footstep_stride = 5.0f;       // ground distance between the player's footsteps (pace follows speed)
    float land_min_air_time = 0.2f;     // seconds off the ground before touching down counts as a landing
    float land_min_speed = 3.0f; // and the downward speed it must have (stairs and steps are not jumps)
    // The player's choice (game/difficulty.h): the robots' aim time, hit chance and damage per shot.
    Difficulty difficulty = Difficulty::Normal;
};

} // namespace ks::game
