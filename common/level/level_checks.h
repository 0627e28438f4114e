#pragma once
// Semantic checks shared by the loader and validate(): ranges from each field's FieldInfo, NaN/inf in
// memory, unknown choices, duplicate ids, next_id, and the few rules that tie fields together.
#include "level/diagnostics.h"
#include "level/level.h"

#include <vector>

namespace ks::level {

// Positions farther than this from the origin are mistakes (a typo'd exponent), not level design.
inline constexpr double kPositionLimit = 1e5;
// A placed model (file size times scale) larger or smaller than these is a warning at props.scale.
inline constexpr float kMaxPlacedModelSize = 2000.0f;
inline constexpr float kMinPlacedModelSize = 0.01f;
// Angles are degrees; anything beyond ten turns is a unit mistake (radians * 1000?) rather than intent.
inline constexpr double kAngleLimit = 3600;

// `source_index[i]` is entity i's index in the file's "entities" array, for paths in messages; empty means
// the identity (an in-memory level).
void check_level(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index = {});
void check_entity(const Entity& entity, const std::string& path, DiagnosticSink& sink);

} // namespace ks::level
