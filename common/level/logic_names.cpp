#include "level/logic_names.h"

#include <array>

namespace ks::level {
namespace {

using E = LinkEvent;
using A = LinkAction;

constexpr std::array<std::string_view, static_cast<size_t>(E::Count)> kEventNames = {
    "on_enter", "on_exit", "on_alert",  "on_death", "on_open",
    "on_close", "on_use",  "on_pickup", "on_start", "on_complete",
};

constexpr std::array<std::string_view, static_cast<size_t>(A::Count)> kActionNames = {
    "open",     "close", "toggle", "lock",  "unlock", "on",   "off",      "enable", "disable",
    "activate", "alert", "kill",   "spawn", "show",   "play", "complete", "win",    "lose",
};

constexpr std::array kAllEvents = {E::OnEnter, E::OnExit, E::OnAlert,  E::OnDeath, E::OnOpen,
                                   E::OnClose, E::OnUse,  E::OnPickup, E::OnStart, E::OnComplete};
constexpr std::array kAllActions = {A::Open,  A::Close,  A::Toggle,  A::Lock,     A::Unlock, A::On,
                                    A::Off,   A::Enable, A::Disable, A::Activate, A::Alert,  A::Kill,
                                    A::Spawn, A::Show,   A::Play,    A::Complete, A::Win,    A::Lose};
static_assert(kAllEvents.size() == static_cast<size_t>(E::Count));
static_assert(kAllActions.size() == static_cast<size_t>(A::Count));

constexpr std::array kTriggerEvents = {E::OnEnter, E::OnExit};
constexpr std::array kRobotEvents = {E::OnAlert, E::OnDeath};
constexpr std::array kDoorEvents = {E::OnOpen, E::OnClose};
constexpr std::array kUseEvents = {E::OnUse};
constexpr std::array kPickupEvents = {E::OnPickup};

constexpr std::array kDoorActions = {A::Open, A::Close, A::Toggle, A::Lock, A::Unlock};
constexpr std::array kLightActions = {A::On, A::Off, A::Toggle};
constexpr std::array kTriggerActions = {A::Enable, A::Disable};
constexpr std::array kRobotActions = {A::Activate, A::Alert, A::Kill};
constexpr std::array kSpawnerActions = {A::Spawn};
constexpr std::array kMessageActions = {A::Show};
constexpr std::array kSoundActions = {A::Play};

constexpr std::array kOpenCauses = {E::OnOpen};
constexpr std::array kCloseCauses = {E::OnClose};
constexpr std::array kToggleCauses = {E::OnOpen, E::OnClose};
constexpr std::array kKillCauses = {E::OnDeath};
constexpr std::array kCompleteCauses = {E::OnComplete};

} // namespace

std::string_view event_name(LinkEvent event) {
    const auto index = static_cast<size_t>(event);
    return index < kEventNames.size() ? kEventNames[index] : std::string_view("unknown");
}

std::optional<LinkEvent> event_from_name(std::string_view name) {
    for (size_t i = 0; i < kEventNames.size(); ++i)
        if (kEventNames[i] == name) return static_cast<LinkEvent>(i);
    return std::nullopt;
}

std::string_view action_name(LinkAction action) {
    const auto index = static_cast<size_t>(action);
    return index < kActionNames.size() ? kActionNames[index] : std::string_view("unknown");
}

std::optional<LinkAction> action_from_name(std::string_view name) {
    for (size_t i = 0; i < kActionNames.size(); ++i)
        if (kActionNames[i] == name) return static_cast<LinkAction>(i);
    return std::nullopt;
}

std::vector<std::string> event_names(std::span<const LinkEvent> events) {
    std::vector<std::string> names;
    for (LinkEvent e : events) names.emplace_back(event_name(e));
    return names;
}

std::vector<std::string> action_names(std::span<const LinkAction> actions) {
    std::vector<std::string> names;
    for (LinkAction a : actions) names.emplace_back(action_name(a));
    return names;
}

std::span<const LinkEvent> all_events() {
    return kAllEvents;
}

std::span<const LinkAction> all_actions() {
    return kAllActions;
}

std::span<const LinkEvent> entity_events(EntityType type) {
    switch (type) {
    case EntityType::Trigger:
        return kTriggerEvents;
    case EntityType::Robot:
        return kRobotEvents;
    case EntityType::Door:
        return kDoorEvents;
    case EntityType::FloorLight:
    case EntityType::ControlPanel:
        return kUseEvents;
    case EntityType::Pickup:
        return kPickupEvents;
    default:
        return {};
    }
}

TargetKind target_kind(LinkAction action) {
    switch (action) {
    case LinkAction::Complete:
        return TargetKind::Objective;
    case LinkAction::Win:
    case LinkAction::Lose:
        return TargetKind::Level;
    default:
        return TargetKind::Entity;
    }
}

std::span<const LinkAction> entity_actions(EntityType type) {
    switch (type) {
    case EntityType::Door:
        return kDoorActions;
    case EntityType::FloorLight:
    case EntityType::TopLight:
        return kLightActions;
    case EntityType::Trigger:
        return kTriggerActions;
    case EntityType::Robot:
        return kRobotActions;
    case EntityType::Spawner:
        return kSpawnerActions;
    case EntityType::Message:
        return kMessageActions;
    case EntityType::Sound:
        return kSoundActions;
    default:
        return {};
    }
}

bool entity_takes(EntityType type, LinkAction action) {
    for (LinkAction a : entity_actions(type))
        if (a == action) return true;
    return false;
}

std::span<const LinkEvent> events_caused(LinkAction action) {
    switch (action) {
    case LinkAction::Open:
        return kOpenCauses;
    case LinkAction::Close:
        return kCloseCauses;
    case LinkAction::Toggle:
        return kToggleCauses;
    case LinkAction::Kill:
        return kKillCauses;
    case LinkAction::Complete:
        return kCompleteCauses;
    default:
        return {};
    }
}

} // namespace ks::level
