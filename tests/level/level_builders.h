#pragma once
// Levels for tests: one with every type and non-default values, and seeded random valid levels.
#include "core/random.h"
#include "level/level.h"

namespace ks::test {

// Every entity type once, every field off its default (colours on the file's 8-bit grid).
level::Level level_with_every_type();

// A valid level with `entity_count` entities whose fields are random within their ranges, with floats of
// every length (0.8, 12.345678, 3e-5, ...), names with quotes, escapes and non-ASCII, shuffled ids.
level::Level random_level(Rng& rng, int entity_count);

} // namespace ks::test
