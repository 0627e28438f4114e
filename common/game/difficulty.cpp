#include "game/difficulty.h"

namespace ks::game {

DifficultyScale difficulty_scale(Difficulty difficulty) {
    switch (difficulty) {
    case Difficulty::Easy:
        return {0.5f, 0.6f, 0.6f};
    case Difficulty::Hard:
        return {-0.15f, 1.3f, 1.35f};
    case Difficulty::Normal:
        break;
    }
    return {};
}

const char* difficulty_name(Difficulty difficulty) {
    return difficulty == Difficulty::Easy ? "easy" : difficulty == Difficulty::Hard ? "hard" : "normal";
}

const char* difficulty_title(Difficulty difficulty) {
    return difficulty == Difficulty::Easy ? "Easy" : difficulty == Difficulty::Hard ? "Hard" : "Normal";
}

Result<Difficulty> parse_difficulty(std::string_view text, const Location& where) {
    for (Difficulty d : kDifficulties)
        if (text == difficulty_name(d)) return d;
    return Error("unknown difficulty '" + std::string(text) + "'", where, "use easy, normal or hard");
}

} // namespace ks::game
