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

// The links of an ASCII or binary FBX file. A malformed line is skipped; in a binary file, the links before
// the first damaged record (check_fbx_file refuses the file).
FbxLinks read_fbx_links(std::string_view file);

// What assimp's FBX reader would crash on, refused with the file and the line (ASCII) or byte (binary): a
// binary file's damaged records (fbx_records.h), scopes nested more than kMaxFbxNesting deep, and a cycle of
// object-to-object or object-to-property links (naming the link that closes it and its objects).
Result<void> check_fbx_file(std::string_view file, const std::filesystem::path& path);

} // namespace ks::modelio
