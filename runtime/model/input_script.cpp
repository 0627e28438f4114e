#include "runtime/model/input_script.h"

#include <cmath>
#include <cstdlib>
#include <iterator>
#include <sstream>

namespace ks::runtime {

int script_key_code(const std::string& name) {
    if (name.size() == 1 && name[0] >= 'a' && name[0] <= 'z') return 'A' + (name[0] - 'a');
    if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return name[0];
    if (name == "space") return 32;
    if (name == "escape" || name == "esc") return 256;
    if (name == "enter") return 257;
    if (name == "tab") return 258;
    if (name == "backspace") return 259;
    if (name == "right") return 262;
    if (name == "left") return 263;
    if (name == "down") return 264;
    if (name == "up") return 265;
    return -1;
}

int script_pad_button(const std::string& name) {
    static const char* const names[] = {"a",      "b",    "x",      "y",     "lb",
                                        "rb",     "back", "start",  "guide", "lthumb",
                                        "rthumb", "dup",  "dright", "ddown", "dleft"};
    for (int i = 0; i < static_cast<int>(std::size(names)); ++i)
        if (name == names[i]) return i;
    return -1;
}

int script_pad_axis(const std::string& name) {
    static const char* const names[] = {"lx", "ly", "rx", "ry", "lt", "rt"};
    for (int i = 0; i < static_cast<int>(std::size(names)); ++i)
        if (name == names[i]) return i;
    return -1;
}

Result<std::vector<ScriptEvent>> parse_input_script(const std::string& text, const std::string& file) {
    std::vector<ScriptEvent> events;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    long long last_frame = 0;
    auto fail = [&](const std::string& what, const std::string& hint) -> Error {
        return Error("input script: " + what, Location(file, number, 1), hint);
    };
    const std::string usage = "lines are '<frame> key <name> down|up|tap', '<frame> mouse left|right "
                              "down|up|click', '<frame> move X Y', '<frame> look DX DY', '<frame> click "
                              "<label>' or '<frame> quit'";
    while (std::getline(lines, line)) {
        ++number;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream in(line);
        std::string frame_text;
        if (!(in >> frame_text)) continue; // blank or comment
        ScriptEvent e;
        e.line = number;
        char* end = nullptr;
        e.frame = std::strtoll(frame_text.c_str(), &end, 10);
        if (end == frame_text.c_str() || *end != '\0' || e.frame < 0 || e.frame > 100000000)
            return fail("'" + frame_text + "' is not a frame number", usage);
        if (e.frame < last_frame)
            return fail("frame " + frame_text + " comes after frame " + std::to_string(last_frame),
                        "keep the events in frame order");
        last_frame = e.frame;
        std::string verb;
        in >> verb;
        auto action_of = [&](const std::string& word, const char* tap_word) {
            if (word == "down") return 1;
            if (word == "up") return 0;
            if (word == tap_word) return 2;
            return -1;
        };
        if (verb == "key") {
            std::string name, act;
            in >> name >> act;
            e.kind = ScriptEvent::Kind::Key;
            e.code = script_key_code(name);
            e.action = action_of(act, "tap");
            if (e.code < 0)
                return fail("unknown key '" + name + "'",
                            "keys: a-z, 0-9, space, escape, enter, tab, up, down, left, right");
            if (e.action < 0) return fail("key action '" + act + "'", "use down, up or tap");
        } else if (verb == "mouse") {
            std::string button, act;
            in >> button >> act;
            e.kind = ScriptEvent::Kind::Mouse;
            e.code = button == "left" ? 0 : button == "right" ? 1 : -1;
            e.action = action_of(act, "click");
            if (e.code < 0) return fail("unknown mouse button '" + button + "'", "use left or right");
            if (e.action < 0) return fail("mouse action '" + act + "'", "use down, up or click");
        } else if (verb == "move" || verb == "look") {
            e.kind = verb == "move" ? ScriptEvent::Kind::Move : ScriptEvent::Kind::Look;
            if (!(in >> e.x >> e.y) || !std::isfinite(e.x) || !std::isfinite(e.y) || std::abs(e.x) > 1e6 ||
                std::abs(e.y) > 1e6)
                return fail(verb + " needs two finite numbers (pixels)", usage);
        } else if (verb == "click") {
            e.kind = ScriptEvent::Kind::ClickButton;
            std::getline(in, e.label);
            const auto first = e.label.find_first_not_of(" \t");
            const auto last = e.label.find_last_not_of(" \t\r");
            e.label = first == std::string::npos ? "" : e.label.substr(first, last - first + 1);
            if (e.label.empty()) return fail("click needs a button label", "e.g. '10 click Play'");
        } else if (verb == "pad") {
            std::string name, act;
            in >> name >> act;
            if (script_pad_axis(name) >= 0) {
                e.kind = ScriptEvent::Kind::PadAxis;
                e.code = script_pad_axis(name);
                char* end = nullptr;
                e.x = std::strtod(act.c_str(), &end);
                if (act.empty() || *end != '\0' || !std::isfinite(e.x) || std::abs(e.x) > 1.0)
                    return fail("pad axis " + name + " needs a value in -1..1", "e.g. '10 pad ly -1'");
            } else {
                e.kind = ScriptEvent::Kind::PadButton;
                e.code = script_pad_button(name);
                e.action = action_of(act, "tap");
                if (e.code < 0)
                    return fail(
                        "unknown pad button or axis '" + name + "'",
                        "buttons: a b x y lb rb back start dup ddown dleft dright; axes: lx ly rx ry lt rt");
                if (e.action < 0) return fail("pad action '" + act + "'", "use down, up or tap");
            }
        } else if (verb == "quit") {
            e.kind = ScriptEvent::Kind::Quit;
        } else {
            return fail("unknown command '" + verb + "'", usage);
        }
        std::string extra;
        if (e.kind != ScriptEvent::Kind::ClickButton && (in >> extra))
            return fail("unexpected '" + extra + "' at the end of the line", usage);
        events.push_back(std::move(e));
    }
    return events;
}

} // namespace ks::runtime
