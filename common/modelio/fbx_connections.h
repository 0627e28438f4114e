#pragma once
// An ASCII FBX file's object connections checked before assimp reads it: assimp 5.2.5's FBX converter
// follows "C:" links from child to parent by recursion, so a link cycle ("C: "OO",2,2", an object its own
// parent) recursed until the stack overflowed and took the editor down (a fuzz finding, docs/reliability.md).
// Binary FBX files are not read here (their connections need the binary node reader this project does not
// have yet).
#include "core/result.h"

#include <filesystem>
#include <string_view>

namespace ks::modelio {

// The text of an ASCII FBX file: refuses a cycle of object-to-object or object-to-property links, naming the
// file, the line of the link that closes it and the objects on it. A binary file ("Kaydara FBX Binary")
// passes unread.
Result<void> check_fbx_connections(std::string_view text, const std::filesystem::path& path);

} // namespace ks::modelio
