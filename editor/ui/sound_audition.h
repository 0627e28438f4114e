#pragma once
// The editor's ears: the Audition buttons' player (sound_widgets.h). It opens the sound card on the first
// audition (never at start-up: a designer who never listens never waits for the device) and falls back to
// silence with one notice line where there is none. A sound added to assets/sounds/ while the editor runs
// is picked up: an unknown name reloads the folder once before giving up.
#include "sound_widgets.h"

namespace ks::editor::ui {

SoundAudition make_sound_audition();

} // namespace ks::editor::ui
