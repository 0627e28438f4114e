// Key bindings (runtime/model/key_bindings.h, key_names.h, controls_state.h's finish_rebind and
// keyboard_mouse_input.h, without a window): the defaults, names both ways, the options.json round trip, bad
// entries giving the defaults and a warning, conflicts, the swap on rebind, reset, and the game's Input read
// through a rebound key from synthetic key state.
#include "core/log.h"
#include "runtime/model/controls_state.h"
#include "runtime/model/key_bindings.h"
#include "runtime/model/keyboard_mouse_input.h"
#include "runtime/model/options.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::runtime;

namespace {
constexpr int kBindPress = InputState::kPress, kBindRelease = InputState::kRelease;

bool has(const std::vector<std::string>& problems, const std::string& part) {
    for (const auto& p : problems)
        if (p.find(part) != std::string::npos) return true;
    return false;
}
} // namespace

TEST_CASE("key bindings: the defaults are WASD/arrows, Space, either mouse button, E, P, M and clash-free") {
    const Bindings b;
    CHECK(b == Bindings::defaults());
    CHECK(keys_text(b, Action::Forward) == "W / Up");
    CHECK(keys_text(b, Action::Left) == "A / Left");
    CHECK(keys_text(b, Action::Jump) == "Space");
    CHECK(keys_text(b, Action::Fire) == "Mouse Left / Mouse Right");
    CHECK(keys_text(b, Action::Interact) == "E");
    CHECK(keys_text(b, Action::Pause) == "P");
    CHECK(keys_text(b, Action::Mute) == "M");
    for (bool clash : conflicts(b)) CHECK_FALSE(clash);
    // Esc is reserved: no action has it.
    for (const auto& slots : b.keys)
        for (int code : slots) CHECK(code != kKeyEscape);
}

TEST_CASE("key names: every named code reads back to itself, case-insensitively; unknown names are no key") {
    int named = 0;
    for (int code = 0; code <= kLastKeyCode; ++code) {
        const std::string name = key_name(code);
        if (name.empty()) continue;
        ++named;
        CHECK_MESSAGE(key_code(name) == code, name);
    }
    CHECK(named > 100); // letters, digits, F-keys, keypad, arrows, modifiers, punctuation
    for (int b = 0; b < kMouseButtons; ++b) CHECK(key_code(key_name(kMouseBase + b)) == kMouseBase + b);
    CHECK(key_name('W') == "W");
    CHECK(key_name(290) == "F1");
    CHECK(key_name(kMouseBase) == "Mouse Left");
    CHECK(key_code("space") == kKeySpace);
    CHECK(key_code("LEFT SHIFT") == 340);
    CHECK(key_code("w") == 'W');
    CHECK(key_code("") == kNoKey);
    CHECK(key_code("Hyper") == kNoKey);
    CHECK(key_code("F26") == kNoKey);
    CHECK(key_name(-5).empty());
    CHECK(key_name(5000).empty());
}

TEST_CASE("key bindings: saved in options.json by name and read back the same") {
    test::ScratchDir dir;
    const auto path = dir / "killswitch" / "options.json";
    Options o;
    REQUIRE(rebind(o.bindings, Action::Jump, 0, 'F').accepted);
    REQUIRE(rebind(o.bindings, Action::Fire, 1, 341).accepted); // Left Ctrl
    o.bindings[Action::Mute][1] = 290;                          // F1
    o.pad_look_sensitivity = 2.5f;
    o.pad_dead_zone = 0.25f;
    REQUIRE(save_options(path, o).ok());
    const std::string text = *files::read_text(path);
    CHECK(text.find("\"jump\": [\n      \"F\",\n      \"\"\n    ]") != std::string::npos);
    CHECK(text.find("\"Left Ctrl\"") != std::string::npos);
    CHECK(text.find("\"Mouse Left\"") != std::string::npos);
    log::Capture capture;
    CHECK(load_options(path) == o);
    CHECK(capture.text().empty());
}

TEST_CASE("key bindings: bad entries give that action's defaults and a warning naming the file and field") {
    std::vector<std::string> problems;
    const Options o = options_from_json(R"({"bindings": {
        "forward": ["Hyperspace", "Up"],
        "jump": ["Esc"],
        "fire": "Mouse Left",
        "interact": [7, "E"],
        "left": ["Q", "Left", "Z"],
        "teleport": ["T"],
        "back": ["X"],
        "mute": []
    }})",
                                        problems);
    CHECK(o.bindings[Action::Forward] == Bindings::defaults()[Action::Forward]);
    CHECK(o.bindings[Action::Jump] == Bindings::defaults()[Action::Jump]);
    CHECK(o.bindings[Action::Fire] == Bindings::defaults()[Action::Fire]);
    CHECK(o.bindings[Action::Interact] == Bindings::defaults()[Action::Interact]);
    CHECK(o.bindings[Action::Left] == Bindings::defaults()[Action::Left]);
    CHECK(o.bindings[Action::Mute] == Bindings::defaults()[Action::Mute]);
    CHECK(o.bindings[Action::Back] == std::array<int, kSlots>{'X', kNoKey}); // the good one is kept
    CHECK(has(problems, "bindings.forward: expected one or two key names"));
    CHECK(has(problems, "\"Hyperspace\""));
    CHECK(has(problems, "bindings.jump"));
    CHECK(has(problems, "bindings.fire"));
    CHECK(has(problems, "bindings.interact"));
    CHECK(has(problems, "bindings.left"));
    CHECK(has(problems, "bindings.mute"));
    CHECK(has(problems, "bindings.teleport: no such action"));
    CHECK_FALSE(has(problems, "bindings.back:"));

    problems.clear();
    const Options not_object = options_from_json(R"({"bindings": [1, 2]})", problems);
    CHECK(not_object.bindings == Bindings::defaults());
    CHECK(has(problems, "bindings: expected an object"));

    // Through load_options: one warning per problem, each naming the file.
    test::ScratchDir dir;
    const auto path = dir / "options.json";
    REQUIRE(files::write_atomic(path, R"({"bindings": {"jump": ["Nope"]}, "pad_dead_zone": NaN})").ok());
    log::Capture capture;
    const Options loaded = load_options(path);
    CHECK(loaded == Options{}); // NaN makes the file not JSON: every default
    CHECK(capture.text().find(path.string()) != std::string::npos);
    REQUIRE(files::write_atomic(path, R"({"bindings": {"jump": ["Nope"]}, "pad_dead_zone": 0.9,
                                          "pad_look_sensitivity": -1})")
                .ok());
    log::Capture capture2;
    const Options loaded2 = load_options(path);
    CHECK(loaded2 == Options{});
    CHECK(capture2.text().find("bindings.jump") != std::string::npos);
    CHECK(capture2.text().find("pad_dead_zone") != std::string::npos);
    CHECK(capture2.text().find("pad_look_sensitivity") != std::string::npos);
}

TEST_CASE("key bindings: a file that binds one key twice is read as written and the clash reported") {
    std::vector<std::string> problems;
    const Options o = options_from_json(R"({"bindings": {"jump": ["E"]}})", problems);
    CHECK(o.bindings[Action::Jump][0] == 'E');
    const auto clash = conflicts(o.bindings);
    CHECK(clash[static_cast<std::size_t>(Action::Jump)]);
    CHECK(clash[static_cast<std::size_t>(Action::Interact)]);
    CHECK_FALSE(clash[static_cast<std::size_t>(Action::Forward)]);
    CHECK(has(problems, "bindings.jump: shares a key"));
    CHECK(has(problems, "bindings.interact: shares a key"));
    // Both slots of one action holding the same key is a clash too.
    Bindings b;
    b[Action::Mute] = {'M', 'M'};
    CHECK(conflicts(b)[static_cast<std::size_t>(Action::Mute)]);
}

TEST_CASE("key bindings: rebinding a used key swaps it; Esc and nameless codes are refused; reset") {
    Bindings b;
    // Space onto Interact: Jump gets E (Interact's old key).
    RebindResult r = rebind(b, Action::Interact, 0, kKeySpace);
    CHECK(r.accepted);
    REQUIRE(r.swapped_with.has_value());
    CHECK(*r.swapped_with == Action::Jump);
    CHECK(b[Action::Interact][0] == kKeySpace);
    CHECK(b[Action::Jump][0] == 'E');
    CHECK(r.message.find("Space moved from Jump") != std::string::npos);
    for (bool clash : conflicts(b)) CHECK_FALSE(clash);
    // Into an empty slot: the other action's slot becomes empty.
    r = rebind(b, Action::Mute, 1, 'W');
    CHECK(r.accepted);
    CHECK(b[Action::Forward][0] == kNoKey);
    CHECK(b[Action::Mute] == std::array<int, kSlots>{'M', 'W'});
    // Within one action: the two slots swap.
    r = rebind(b, Action::Fire, 0, kMouseBase + 1);
    CHECK(b[Action::Fire] == std::array<int, kSlots>{kMouseBase + 1, kMouseBase + 0});
    CHECK_FALSE(r.swapped_with.has_value());
    // Refused: Esc, codes without a name, a slot that does not exist.
    const Bindings before = b;
    CHECK_FALSE(rebind(b, Action::Jump, 0, kKeyEscape).accepted);
    CHECK_FALSE(rebind(b, Action::Jump, 0, 9999).accepted);
    CHECK_FALSE(rebind(b, Action::Jump, 5, 'K').accepted);
    CHECK(b == before);
    // The Controls screen's path: Backspace clears the waiting slot, a key binds, Reset restores.
    Options o;
    ControlsState st;
    st.waiting_action = static_cast<int>(Action::Jump);
    st.waiting_slot = 1;
    CHECK_FALSE(finish_rebind(o, st, kNoKey)); // nothing pressed yet: still waiting
    CHECK(st.waiting());
    CHECK(finish_rebind(o, st, 'J'));
    CHECK_FALSE(st.waiting());
    CHECK(o.bindings[Action::Jump] == std::array<int, kSlots>{kKeySpace, 'J'});
    st.waiting_action = static_cast<int>(Action::Jump);
    st.waiting_slot = 1;
    CHECK(finish_rebind(o, st, 259)); // Backspace
    CHECK(o.bindings[Action::Jump][1] == kNoKey);
    st.waiting_action = static_cast<int>(Action::Fire);
    st.waiting_slot = 0;
    CHECK(finish_rebind(o, st, kMouseBase + 2));
    CHECK(st.hold_mouse); // the bound click must not reach the menu
    o.bindings = Bindings::defaults();
    CHECK(o.bindings == Bindings{});
}

TEST_CASE("key bindings: the game's Input follows a rebound key, and the old key no longer moves") {
    Options o;
    REQUIRE(rebind(o.bindings, Action::Forward, 0, 'I').accepted); // W leaves Forward (W had no other job)
    REQUIRE(rebind(o.bindings, Action::Fire, 0, 'F').accepted);
    o.bindings[Action::Fire][1] = kNoKey;
    InputState s;
    s.key('I', kBindPress);
    game::Input in = keyboard_mouse_input(s, o, true);
    CHECK(in.move_forward == 1.0f);
    s.key('I', kBindRelease);
    s.key('W', kBindPress);
    in = keyboard_mouse_input(s, o, true);
    CHECK(in.move_forward == 0.0f);
    s.key('W', kBindRelease);
    // A tap of the new fire key shoots once; the right mouse button, unbound now, does not.
    s.key('F', kBindPress);
    s.key('F', kBindRelease);
    s.button(1, kBindPress);
    s.button(1, kBindRelease);
    in = keyboard_mouse_input(s, o, true);
    CHECK(in.fire);
    CHECK_FALSE(keyboard_mouse_input(s, o, true).fire);
    // Not captured (a menu): no shot, but the latch is still spent.
    s.key('F', kBindPress);
    CHECK_FALSE(keyboard_mouse_input(s, o, false).fire);
    CHECK_FALSE(keyboard_mouse_input(s, o, true).fire);
    // Jump on a mouse button: held counts every step, like Space.
    REQUIRE(rebind(o.bindings, Action::Jump, 0, kMouseBase + 2).accepted);
    s.button(2, kBindPress);
    CHECK(keyboard_mouse_input(s, o, true).jump);
    CHECK(keyboard_mouse_input(s, o, true).jump);
    s.button(2, kBindRelease);
    CHECK_FALSE(keyboard_mouse_input(s, o, true).jump);
    // The arrows still move (the alternative slot), strafing included.
    s.key(kKeyLeft, kBindPress);
    CHECK(keyboard_mouse_input(s, o, true).move_right == -1.0f);
    // Pause and Mute by their keys.
    s.key('P', kBindPress);
    CHECK(action_pressed(s, o.bindings, Action::Pause));
    CHECK_FALSE(action_pressed(s, o.bindings, Action::Pause));
}
