#pragma once
// The sound rule: every sound emitter's `sound` and the level's `ambient_sound` must name a file in
// assets/sounds (ValidationOptions::sound_names), with a did-you-mean and a quick fix for a near miss.
// Names the format already refuses (empty, bad characters) are left to the format rule.
#include "model/validation.h"

namespace ks::editor {

void check_sound_names(const level::Level& level, const ValidationOptions& options, std::vector<Issue>& out);

} // namespace ks::editor
