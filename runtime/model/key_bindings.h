#pragma once
// Which keys do what: every player action has two slots (primary, alternative), each a key or a mouse
// button (key_names.h), saved in options.json as readable names under "bindings". Rebinding a key already
// used elsewhere swaps the two (the other action gets this slot's old key), as most shooters do, so no
// key ever does two things and no action is left without a key by accident. A hand-edited file can still
// bind one key twice: conflicts() finds that, the Controls screen shows it in red. Esc is reserved (pause,
// back, cancel a rebind) and never bound. The reader, bindings_from_json, stays inline beside options.h's:
// both are the options file's reading.
#include "key_names.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ks::runtime {

enum class Action : std::uint8_t { Forward, Back, Left, Right, Jump, Fire, Interact, Pause, Mute, Count };
inline constexpr std::size_t kActionCount = static_cast<std::size_t>(Action::Count);
inline constexpr std::size_t kSlots = 2;

struct ActionInfo {
    const char* id;    // the key in options.json
    const char* label; // what the Controls screen and How to Play show
};
inline constexpr std::array<ActionInfo, kActionCount> kActionInfo{{
    {"forward", "Move forward"},
    {"back", "Move back"},
    {"left", "Strafe left"},
    {"right", "Strafe right"},
    {"jump", "Jump"},
    {"fire", "Shoot"},
    {"interact", "Interact (doors, lights, computer)"},
    {"pause", "Pause (Esc always pauses)"},
    {"mute", "Mute / unmute"},
}};
const ActionInfo& action_info(Action a);

// The defaults, in Action order: WASD and the arrows, Space, either mouse button, E, P, M.
inline constexpr std::array<std::array<int, kSlots>, kActionCount> kDefaultKeys{{
    {'W', kKeyUp},
    {'S', kKeyDown},
    {'A', kKeyLeft},
    {'D', kKeyRight},
    {kKeySpace, kNoKey},
    {kMouseBase + 0, kMouseBase + 1},
    {'E', kNoKey},
    {'P', kNoKey},
    {'M', kNoKey},
}};

struct Bindings {
    std::array<std::array<int, kSlots>, kActionCount> keys = kDefaultKeys;
    bool operator==(const Bindings&) const = default;

    std::array<int, kSlots>& operator[](Action a) { return keys[static_cast<std::size_t>(a)]; }
    const std::array<int, kSlots>& operator[](Action a) const { return keys[static_cast<std::size_t>(a)]; }
    static Bindings defaults() { return Bindings{}; }
};

// "W / Up", "Space", "-" when unbound: an action's keys for How to Play.
std::string keys_text(const Bindings& b, Action a);

// For each action: does one of its keys also belong to another action (or to both of its own slots)?
std::array<bool, kActionCount> conflicts(const Bindings& b);

// What a rebind did, for the message under the table.
struct RebindResult {
    bool accepted = false;
    std::optional<Action> swapped_with; // the action that had the key and now has this slot's old key
    std::string message;
};

// Puts `code` in `action`'s `slot`. A key another slot holds moves here and that slot gets this slot's old
// key (a swap); Esc and unknown codes are refused.
RebindResult rebind(Bindings& b, Action action, std::size_t slot, int code);

// An object of action id → [name, name] ("" for an empty slot), as options.json keeps them.
nlohmann::json bindings_to_json(const Bindings& b);

// Reads "bindings" (an object of action → [name, name]); an action missing keeps its defaults, a bad one
// (unknown name, Esc, wrong shape) gets its defaults and a problem line naming the field.
inline Bindings bindings_from_json(const nlohmann::json& j, std::vector<std::string>& problems) {
    Bindings b = Bindings::defaults();
    if (!j.is_object()) {
        problems.push_back("bindings: expected an object of action: [key, key], got " + j.dump() +
                           "; using the default keys");
        return b;
    }
    for (const auto& [id, value] : j.items()) {
        std::size_t a = 0;
        while (a < kActionCount && id != kActionInfo[a].id) ++a;
        if (a == kActionCount) {
            problems.push_back("bindings." + id +
                               ": no such action (known: forward, back, left, right, jump, "
                               "fire, interact, pause, mute); ignored");
            continue;
        }
        const auto defaults = Bindings::defaults().keys[a];
        std::array<int, kSlots> slots{kNoKey, kNoKey};
        bool good = value.is_array() && value.size() >= 1 && value.size() <= kSlots;
        for (std::size_t s = 0; good && s < value.size(); ++s) {
            if (!value[s].is_string()) {
                good = false;
                break;
            }
            const std::string name = value[s].get<std::string>();
            slots[s] = key_code(name);
            if ((!name.empty() && slots[s] == kNoKey) || slots[s] == kKeyEscape) good = false;
        }
        if (good) {
            b.keys[a] = slots;
        } else {
            problems.push_back("bindings." + id +
                               ": expected one or two key names like [\"W\", \"Up\"] (Esc "
                               "is reserved), got " +
                               value.dump() + "; using the default " +
                               nlohmann::json(bindings_to_json(Bindings::defaults())[id]).dump());
            b.keys[a] = defaults;
        }
    }
    const auto clash = conflicts(b);
    for (std::size_t a = 0; a < kActionCount; ++a)
        if (clash[a])
            problems.push_back(std::string("bindings.") + kActionInfo[a].id +
                               ": shares a key with another action (shown in red in Options > Controls)");
    return b;
}

} // namespace ks::runtime
