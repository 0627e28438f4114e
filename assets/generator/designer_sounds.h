#pragma once
// Sounds a designer replaced by hand. A designer replaces a generated sound by dropping a WAV of the same
// name into assets/sounds/ and adding the name to assets/sounds/designer_sounds.txt (one per line, `#`
// comments): ks_assetgen then leaves that file alone, and the byte-for-byte test does not compare it.
#include "core/result.h"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace ks::assetgen {

inline constexpr const char* kDesignerSoundsFile = "designer_sounds.txt";

// Reads the list; a missing file is an empty list. A name that is not one of `known` is an error naming
// the file and line, with the closest known name.
Result<std::set<std::string>> load_designer_sounds(const std::filesystem::path& file,
                                                   const std::vector<std::string>& known);

} // namespace ks::assetgen
