#pragma once
// An FBX file's object connections checked before assimp reads it: assimp 5.2.5's FBX converter follows
// "C" links from child to parent by recursion, so a link cycle (`C: "OO",2,2`, an object its own parent)
// recursed until the stack overflowed and took the editor down (a fuzz finding, docs/reliability.md). Both
// encodings are read: ASCII line by line, binary through its node records with every length checked against
// the file's end.
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace ks::modelio {

// One "C" record: an object (or a property, "OP") linked to its parent object. `place` is the line (ASCII)
// or the byte offset of the record (binary) that a message names.
struct FbxLink {
    std::int64_t child = 0, parent = 0;
    std::size_t place = 0;
};

struct FbxLinks {
    std::vector<FbxLink> links;
    bool binary = false;
};

// The links of an ASCII or binary FBX file. What cannot be read (a malformed line, a record whose lengths
// leave the file) is skipped or ends the reading: the file's structure is assimp's to judge, and it refuses
// what it cannot tokenise before it converts anything.
FbxLinks read_fbx_links(std::string_view file);

// Refuses a cycle of object-to-object or object-to-property links, naming the file, the line (ASCII) or
// byte (binary) of the link that closes it and the objects on it.
Result<void> check_fbx_connections(std::string_view file, const std::filesystem::path& path);

} // namespace ks::modelio
