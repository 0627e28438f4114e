#pragma once
// The level `ks_bench render --models N` draws: an open floor with N model entities on a grid ahead of the
// player start (the camera path's 40 units down -z run through it), most of them a dense generated statue
// written as an OBJ into a scratch models folder, every fifth the shipped gas cylinder read as a model file.
// It also prints what the statue's levels of detail cost to build and how far each strays
// (docs/performance.md).
#include "level/level.h"

#include <filesystem>

namespace ks::bench {

// Points XDG_DATA_HOME at `scratch` (the statue is a designer's model in its models folder) and builds the
// level.
level::Level model_field_level(int count, const std::filesystem::path& scratch);

} // namespace ks::bench
