#include "model/sound_validation.h"

#include "jsonio/suggest.h"
#include "level/sound_name.h"
#include "model/sound_names.h"

#include <algorithm>

namespace ks::editor {
namespace {

// "which is not in assets/sounds; did you mean "x"?" or the list of the names there, and the fix to offer.
struct Verdict {
    std::string text;
    std::string suggestion; // "" when no name is close
};

Verdict judge(const std::string& name, const std::vector<std::string>& known) {
    Verdict v;
    v.suggestion = jsonio::closest_match(name, known);
    v.text = "\"" + name + "\", which is not a file in assets/sounds";
    if (!v.suggestion.empty())
        v.text += "; did you mean \"" + v.suggestion + "\"?";
    else
        v.text += " (known sounds: " + jsonio::join(known) + ")";
    return v;
}

bool spelled_right(const std::string& name) {
    return level::is_valid_sound_name(name, 1, level::kMaxSoundNameLength);
}

} // namespace

void check_sound_names(const level::Level& level, const ValidationOptions& options, std::vector<Issue>& out) {
    const std::vector<std::string> known = options.sound_names ? *options.sound_names : shipped_sound_names();
    if (known.empty()) return;
    auto is_known = [&](const std::string& name) {
        return std::find(known.begin(), known.end(), name) != known.end();
    };

    const std::string& ambient = level.settings.ambient_sound.value;
    if (spelled_right(ambient) && !is_known(ambient)) {
        const Verdict v = judge(ambient, known);
        QuickFix fix;
        if (!v.suggestion.empty())
            fix = {"Use " + v.suggestion, fixes::SetSetting{"ambient_sound", FieldValue(v.suggestion)}};
        out.push_back(
            {Rule::Sound, IssueSeverity::Error, 0, "the level's ambient_sound is " + v.text, std::move(fix)});
    }
    for (const level::Entity& e : level.entities) {
        const auto* sound = e.try_as<level::SoundProps>();
        if (!sound || !spelled_right(sound->sound.value) || is_known(sound->sound.value)) continue;
        const Verdict v = judge(sound->sound.value, known);
        QuickFix fix;
        if (!v.suggestion.empty())
            fix = {"Use " + v.suggestion, fixes::SetField{"sound", FieldValue(v.suggestion)}};
        std::string who = "sound " + std::to_string(e.id);
        if (!e.name.empty()) who += " '" + e.name + "'";
        out.push_back({Rule::Sound, IssueSeverity::Error, e.id, who + " plays " + v.text, std::move(fix)});
    }
}

} // namespace ks::editor
