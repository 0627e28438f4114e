#include "runtime/model/key_bindings.h"

namespace ks::runtime {

const ActionInfo& action_info(Action a) {
    return kActionInfo[static_cast<std::size_t>(a)];
}

std::string keys_text(const Bindings& b, Action a) {
    std::string text;
    for (int code : b[a]) {
        if (code == kNoKey) continue;
        if (!text.empty()) text += " / ";
        text += key_name(code);
    }
    return text.empty() ? "-" : text;
}

std::array<bool, kActionCount> conflicts(const Bindings& b) {
    std::array<bool, kActionCount> out{};
    for (std::size_t a = 0; a < kActionCount; ++a)
        for (std::size_t s = 0; s < kSlots; ++s) {
            const int code = b.keys[a][s];
            if (code == kNoKey) continue;
            for (std::size_t a2 = 0; a2 < kActionCount; ++a2)
                for (std::size_t s2 = 0; s2 < kSlots; ++s2)
                    if ((a2 != a || s2 != s) && b.keys[a2][s2] == code) out[a] = true;
        }
    return out;
}

RebindResult rebind(Bindings& b, Action action, std::size_t slot, int code) {
    RebindResult r;
    if (slot >= kSlots) return r;
    if (code == kKeyEscape) {
        r.message = "Esc is reserved for pause and back.";
        return r;
    }
    if (key_name(code).empty()) {
        r.message = "That key cannot be bound.";
        return r;
    }
    int& target = b[action][slot];
    const int old = target;
    r.accepted = true;
    for (std::size_t a = 0; a < kActionCount; ++a)
        for (std::size_t s = 0; s < kSlots; ++s) {
            int& other = b.keys[a][s];
            if (&other == &target || other != code) continue;
            other = old;
            const auto other_action = static_cast<Action>(a);
            if (other_action != action) {
                r.swapped_with = other_action;
                r.message = key_name(code) + " moved from " + action_info(other_action).label +
                            ", which now has " +
                            (old == kNoKey ? std::string("no key there") : key_name(old)) + ".";
            }
        }
    target = code;
    if (r.message.empty()) r.message = action_info(action).label + std::string(": ") + key_name(code) + ".";
    return r;
}

nlohmann::json bindings_to_json(const Bindings& b) {
    nlohmann::json j = nlohmann::json::object();
    for (std::size_t a = 0; a < kActionCount; ++a) {
        nlohmann::json slots = nlohmann::json::array();
        for (int code : b.keys[a]) slots.push_back(code == kNoKey ? "" : key_name(code));
        j[kActionInfo[a].id] = slots;
    }
    return j;
}

} // namespace ks::runtime
