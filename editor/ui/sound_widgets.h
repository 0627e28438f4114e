#pragma once
// The inspector's sound widgets: a sound name typed freely or picked from the files in assets/sounds, and
// the Audition button that lets the designer hear it.
#include <functional>
#include <string>
#include <vector>

namespace ks::editor::ui {

class UiSpots;

// Plays `sound` (a name in assets/sounds) once for the designer: not looped, not positional, at `volume`
// (0..1). The program that opens the editor window provides it (AppOptions::audition) and wires it to the
// audio engine; left unset, the inspector shows no Audition button.
using SoundAudition = std::function<void(const std::string& sound, float volume)>;

// A text field for the name with a drop-down of the sounds beside it; true when the name changed (Enter in
// the text field, or a pick from the list). `known` caches the names offered: the files in assets/sounds,
// read again each time the list opens, so a file dropped into the folder is offered at once.
// With `spots`, the list's button is "sound_list" and, while it is open, each entry "combo:NAME".
bool sound_name_widget(const char* id, std::string& name, std::vector<std::string>& known,
                       UiSpots* spots = nullptr);

// "Audition" (nothing when `audition` is unset or `sound` empty); plays it when clicked.
void audition_button(const SoundAudition& audition, const std::string& sound, float volume);

} // namespace ks::editor::ui
