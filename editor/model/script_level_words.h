#pragma once
// The word readers the level commands' parsers share (script_level_edits.cpp, script_level_settings.cpp,
// script_level_expect.cpp).
#include "model/script_command.h"

#include <vector>

namespace ks::editor::level_words {

template <class T>
Result<ScriptStep> level_step(T step) {
    return step_of<LevelStep>(std::move(step));
}

// Entity ids from word `first` on; with `player_start`, the word player_start stands for the player start
// (kPlayerStartId).
inline Result<void> ids_from(const script_tokens::LineWords& w, const char* usage, size_t first,
                             std::vector<int>& out, bool player_start = false) {
    if (w.size() <= first) return w.fail(first, "expected entity ids", usage);
    for (size_t i = first; i < w.size(); ++i) {
        if (player_start && w.text(i) == "player_start") {
            out.push_back(kPlayerStartId);
            continue;
        }
        int id = 0;
        if (!script_tokens::to_int(w.text(i), id) || id < 1)
            return w.fail(i, "expected an entity id (a positive whole number)", usage);
        out.push_back(id);
    }
    return ok();
}

// A two-word command ("select none", "expect valid") that takes nothing more.
template <class T>
Result<ScriptStep> nothing_after(const script_tokens::LineWords& w, size_t words, T step) {
    if (w.size() > words) return w.fail(words, "unexpected '" + w.word(words) + "'", "");
    return level_step(std::move(step));
}

// A one-word command ("new", "delete").
template <class T>
Result<ScriptStep> no_arguments(const script_tokens::LineWords& w) {
    if (w.size() > 1) return w.fail(1, "unexpected '" + w.word(1) + "'", w.word(0) + " takes no arguments");
    return level_step(T{});
}

} // namespace ks::editor::level_words
