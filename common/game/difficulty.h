#pragma once
// The difficulty a player chooses (Options, `--difficulty`): what the robots do differently, in the ways a
// player notices and expects: how long a robot aims before its first shot, how often its shots hit, and how
// much a hit hurts. Robots' health, numbers and speeds never change (no hidden health sponges). Normal is
// the reference game's balance: every scale is exactly 1 (or 0), so a Normal game is the game as it was.
// docs/game.md, "Difficulty", gives the numbers and why.
#include "core/result.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace ks::game {

enum class Difficulty : std::uint8_t { Easy, Normal, Hard };

inline constexpr std::array<Difficulty, 3> kDifficulties{Difficulty::Easy, Difficulty::Normal,
                                                         Difficulty::Hard};

struct DifficultyScale {
    // Seconds added to a robot's aim (its shoot pose) before it may fire, every time it takes aim; negative
    // shortens it (never below nothing).
    float reaction_delay = 0.0f;
    float accuracy = 1.0f; // multiplies a robot's hit_probability (capped at 1)
    float damage = 1.0f;   // multiplies the damage of a robot's shot
};

DifficultyScale difficulty_scale(Difficulty difficulty);
// "easy", "normal", "hard": the words of the options file and the command line.
const char* difficulty_name(Difficulty difficulty);
// "Easy", "Normal", "Hard": the menus and the summary.
const char* difficulty_title(Difficulty difficulty);
// One of difficulty_name's words; anything else is an error at `where` naming the three.
Result<Difficulty> parse_difficulty(std::string_view text, const Location& where);

} // namespace ks::game
