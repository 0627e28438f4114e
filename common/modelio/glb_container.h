#pragma once
// The binary glTF container checked before assimp reads it: the 12-byte header (magic "glTF", version 2,
// the total length) and each chunk's length against the bytes the file really has. assimp 5.2.5 allocates and
// clears a chunk by its declared length before comparing it with the file, so one flipped bit in a 900-byte
// file cost 2 GB and seconds (a fuzz finding, docs/reliability.md); refused here in microseconds instead.
#include "core/result.h"

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace ks::modelio {

// Reads only the headers (12 bytes and 8 per chunk). Refusals name the file and what is wrong ("the GLB
// header says 1076 bytes, the file has 895").
Result<void> check_glb_container(const std::filesystem::path& path);

} // namespace ks::modelio
