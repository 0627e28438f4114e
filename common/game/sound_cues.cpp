#include "game/sound_cues.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ks::game {
namespace {

constexpr auto kEventSounds = std::to_array<std::string_view>({"rifle_shot",
                                                               "dry_fire",
                                                               "impact",
                                                               "robot_hit",
                                                               "robot_alert",
                                                               "robot_death",
                                                               "robot_explosion",
                                                               "cylinder_explosion",
                                                               "door_open",
                                                               "door_close",
                                                               "light_switch",
                                                               "pickup_health",
                                                               "pickup_ammo",
                                                               "pickup_shield",
                                                               "player_hurt",
                                                               "shield_hit",
                                                               "player_death",
                                                               "win_sting",
                                                               "jump",
                                                               "land",
                                                               "footstep_floor",
                                                               "footstep_stairs",
                                                               "door_locked",
                                                               "objective_complete",
                                                               "message_shown"});

SoundCue own(std::string_view sound, Vec3 at, float volume, SoundPriority priority) {
    SoundCue c;
    c.sound = sound;
    c.position = at;
    c.positional = false;
    c.volume = volume;
    c.priority = priority;
    return c;
}

SoundCue world(std::string_view sound, Vec3 at, int entity, SoundPriority priority, float reference = 8.0f) {
    SoundCue c;
    c.sound = sound;
    c.position = at;
    c.entity = entity;
    c.priority = priority;
    c.reference_distance = reference;
    return c;
}

std::string_view pickup_sound(const Game& game, int entity) {
    for (const Pickup& p : game.pickups())
        if (p.entity_id == entity)
            return p.kind == PickupKind::Health ? "pickup_health"
                   : p.kind == PickupKind::Ammo ? "pickup_ammo"
                                                : "pickup_shield";
    return "pickup_health";
}

// A small deterministic pitch spread so repeated footsteps do not sound mechanical.
float footstep_pitch(std::int64_t step) {
    const auto h = static_cast<std::uint32_t>(step) * 2654435761u;
    return 0.94f + 0.12f * static_cast<float>(h >> 24) / 255.0f;
}

} // namespace

std::span<const std::string_view> event_sound_names() {
    return kEventSounds;
}

void sound_cues(const Game& game, std::span<const Event> events, std::vector<SoundCue>& out) {
    out.clear();
    float shield_absorbed = 0.0f;
    for (const Event& e : events)
        if (e.type == EventType::ShieldHit) shield_absorbed += e.amount;
    for (const Event& e : events) {
        switch (e.type) {
        case EventType::ShotFired:
            out.push_back(own("rifle_shot", e.position, 0.75f, SoundPriority::Critical));
            break;
        case EventType::DryFire:
            out.push_back(own("dry_fire", e.position, 0.8f, SoundPriority::Combat));
            break;
        case EventType::Hit:
            // Scenery hit by the player's shot: a spark; robots sound through RobotHurt, the player (amount =
            // damage) through PlayerDamaged.
            if (e.entity < 0 && e.amount <= 0.0f)
                out.push_back(world("impact", e.position, -1, SoundPriority::Detail, 6.0f));
            break;
        case EventType::RobotHurt:
            out.push_back(world("robot_hit", e.position + Vec3(0, 1.5f, 0), e.entity, SoundPriority::Combat));
            break;
        case EventType::RobotAlerted:
            out.push_back(
                world("robot_alert", e.position + Vec3(0, 2.0f, 0), e.entity, SoundPriority::Combat, 12.0f));
            break;
        case EventType::RobotDied:
            out.push_back(
                world("robot_death", e.position + Vec3(0, 1.5f, 0), e.entity, SoundPriority::Combat));
            break;
        case EventType::Explosion:
            out.push_back(world(e.amount > 0.0f ? "cylinder_explosion" : "robot_explosion", e.position,
                                e.entity, SoundPriority::Critical, e.amount > 0.0f ? 24.0f : 14.0f));
            break;
        case EventType::PickupTaken:
            out.push_back(own(pickup_sound(game, e.entity), e.position, 0.9f, SoundPriority::Combat));
            break;
        case EventType::DoorToggled:
            out.push_back(world(e.amount > 0.5f ? "door_open" : "door_close", e.position, e.entity,
                                SoundPriority::Detail, 10.0f));
            break;
        case EventType::LightToggled:
            out.push_back(world("light_switch", e.position, e.entity, SoundPriority::Detail, 4.0f));
            break;
        case EventType::PlayerDamaged:
            if (e.amount > shield_absorbed + 1e-3f)
                out.push_back(own("player_hurt", e.position, 1.0f, SoundPriority::Critical));
            break;
        case EventType::ShieldHit:
            out.push_back(own("shield_hit", e.position, 0.9f, SoundPriority::Critical));
            break;
        case EventType::PlayerDied:
            out.push_back(own("player_death", e.position, 1.0f, SoundPriority::Critical));
            break;
        case EventType::Won:
            out.push_back(own("win_sting", e.position, 0.8f, SoundPriority::Critical));
            break;
        case EventType::Jump:
            out.push_back(own("jump", e.position, 0.6f, SoundPriority::Detail));
            break;
        case EventType::Land:
            // Louder the harder the landing: a hop is soft, a drop from a floor above is a thud.
            out.push_back(
                own("land", e.position, std::clamp(e.amount / 30.0f, 0.35f, 1.0f), SoundPriority::Detail));
            break;
        case EventType::Footstep: {
            SoundCue c = own(e.amount > 0.5f ? "footstep_stairs" : "footstep_floor", e.position, 0.45f,
                             SoundPriority::Footstep);
            c.pitch = footstep_pitch(game.steps());
            out.push_back(c);
            break;
        }
        case EventType::ClipCue:
            if (!e.cue.empty())
                out.push_back(world(e.cue, e.position, e.entity, SoundPriority::Combat, 12.0f));
            break;
        case EventType::SoundPlayed: // a level's emitter, played by a link: its radius sets how far it
                                     // carries
            if (!e.cue.empty()) {
                SoundCue c = world(e.cue, e.position, e.entity, SoundPriority::Detail,
                                   std::max(1.0f, e.end.x * 0.25f));
                c.volume = std::clamp(e.amount, 0.0f, 1.0f);
                out.push_back(c);
            }
            break;
        case EventType::LockedDoorUsed: // at the door, so the refusal comes from where the player pushed
            out.push_back(
                world("door_locked", e.position + Vec3(0, 2.0f, 0), e.entity, SoundPriority::Combat));
            break;
        case EventType::ObjectiveCompleted: // news for the player, not a sound in the world
            out.push_back(own("objective_complete", e.position, 0.8f, SoundPriority::Critical));
            break;
        case EventType::MessageShown:
            out.push_back(own("message_shown", e.position, 0.6f, SoundPriority::Combat));
            break;
        case EventType::RobotShot: // the shooting clip's muzzle_flash event carries the sound (ClipCue)
        case EventType::CaptionChanged:
        case EventType::Paused:
        case EventType::Used: // doors and lights make their own sounds; the panel's beeps are an emitter
        case EventType::RobotSpawned:
            break;
        }
    }
}

} // namespace ks::game
