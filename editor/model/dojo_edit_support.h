#pragma once
// Shared by the dojo's edit files (dojo_clips.cpp, dojo_blends.cpp, dojo_events.cpp, dojo_curves.cpp):
// finding a clip by index with a clear error, the clip list for hints, and refusing an edit that makes a
// clip invalid by asking anim::validate (one home for the file's limits).
#include "anim/clip.h"
#include "core/result.h"

#include <cstddef>
#include <string>

namespace ks::editor::dojo_support {

Result<anim::ClipDef*> clip_at(anim::AnimationFile& file, std::size_t clip);
Result<const anim::ClipDef*> clip_at(const anim::AnimationFile& file, std::size_t clip);
// "clips: idle, alert, ..." for hints.
std::string clip_list(const anim::AnimationFile& file);
// "0.25 s"
std::string seconds_text(double seconds);
// OK unless anim::validate reports an issue inside clips[clip] of `edited` that `before` (the file before
// the edit, same clip order) does not have; the error is the first such issue's message and hint (the caller
// then leaves its file as it was). Issues the clip already had do not block an unrelated edit.
Result<void> no_new_clip_issues(const anim::AnimationFile& before, const anim::AnimationFile& edited,
                                std::size_t clip);

} // namespace ks::editor::dojo_support
