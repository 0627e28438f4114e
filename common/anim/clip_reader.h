#pragma once
// Parsed JSON -> AnimationFile for clip_io: checks types and shapes (a wrong type, a missing key, an unknown
// key), records each problem as an Issue and keeps going, so one load reports everything.
#include "anim/clip_io.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace ks::anim {

// Fills `file` with whatever could be read; the problems found on the way, in document order.
std::vector<Issue> read_animation_json(const nlohmann::ordered_json& root, AnimationFile& file);

} // namespace ks::anim
