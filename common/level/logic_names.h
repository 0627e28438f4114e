#pragma once
// The level logic's vocabulary, in one table: which events each kind of source emits, which actions each
// kind of target takes, and which events an action sets off in the same step (what a zero-delay loop is made
// of). The level checks, the game's link table and the editor's inspector all read it.
#include "level/level.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::level {

enum class LinkEvent : std::uint8_t {
    OnEnter,    // trigger: someone it notices entered while it was empty
    OnExit,     // trigger: the last one left
    OnAlert,    // robot: noticed the player (or a sound)
    OnDeath,    // robot: took its last hit
    OnOpen,     // door: starts opening (the player's E or a link)
    OnClose,    // door: starts closing
    OnUse,      // floor light, control panel: the player pressed E on it
    OnPickup,   // pickup: the player took it
    OnStart,    // the level (its own links): the first step
    OnComplete, // objective (its own links): completed
    Count
};

enum class LinkAction : std::uint8_t {
    Open,
    Close,
    Toggle,
    Lock,
    Unlock, // doors (toggle: lights too)
    On,
    Off, // lights
    Enable,
    Disable, // triggers
    Activate,
    Alert,
    Kill,     // robots
    Spawn,    // spawners
    Show,     // messages
    Play,     // sounds
    Complete, // objectives
    Win,
    Lose, // the level
    Count
};

// What a link's target names: an entity (by its name), an objective (by its id) or the level ("level").
enum class TargetKind : std::uint8_t { Entity, Objective, Level };

std::string_view event_name(LinkEvent event);
std::optional<LinkEvent> event_from_name(std::string_view name);
std::string_view action_name(LinkAction action);
std::optional<LinkAction> action_from_name(std::string_view name);
std::vector<std::string> event_names(std::span<const LinkEvent> events);
std::vector<std::string> action_names(std::span<const LinkAction> actions);
std::span<const LinkEvent> all_events();
std::span<const LinkAction> all_actions();

// Events an entity of `type` emits; empty for walls, floors and the other passive types.
std::span<const LinkEvent> entity_events(EntityType type);
inline constexpr LinkEvent kLevelEvent = LinkEvent::OnStart;        // the only event of the level's links
inline constexpr LinkEvent kObjectiveEvent = LinkEvent::OnComplete; // the only event of an objective's

TargetKind target_kind(LinkAction action);
// Actions an entity of `type` takes; empty for the types no link can act on.
std::span<const LinkAction> entity_actions(EntityType type);
bool entity_takes(EntityType type, LinkAction action);

// The events `action` makes its target emit within the same step: a door's open its on_open, close its
// on_close, toggle either; a robot's kill its on_death; an objective's complete its on_complete.
std::span<const LinkEvent> events_caused(LinkAction action);

} // namespace ks::level
