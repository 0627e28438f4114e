#pragma once
// A binary FBX file's node records walked the way assimp 5.2.5's tokenizer reads them, with every length
// checked without overflow, before assimp sees the file. Its tokenizer adds lengths to pointers: a property
// length near 2^64 wrapped the pointer below the cursor and an assertion aborted the process (a fuzz finding,
// docs/reliability.md); its reader recurses once per nested record; and an array whose element count times
// its element size passes 2^32 wraps to a small buffer that the parser then reads `count` elements from. Each
// is refused here with the byte it happens at. Internal to modelio.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace ks::modelio {

// assimp reads a file as binary FBX when it starts with these 18 bytes.
bool is_binary_fbx(std::string_view file);

// Records nested deeper than this are refused (real files nest a handful deep; assimp recurses per level).
inline constexpr std::size_t kMaxFbxNesting = 64;

struct FbxRecord {
    std::string_view name;
    std::string_view parent;     // the enclosing record's name; "" at the top level
    std::size_t at = 0;          // the record's byte offset in the file
    std::size_t depth = 0;       // 0 at the top level
    std::string_view properties; // the property bytes: type code, value, type code, value, ...
};

struct FbxDamage {
    std::size_t at = 0; // byte offset
    std::string what;
};

// Calls `visit` for each record in file order (a record before its children) until the end or the first
// damage, which it returns: what assimp's tokenizer would refuse, abort on or overflow with.
std::optional<FbxDamage> walk_binary_fbx(std::string_view file,
                                         const std::function<void(const FbxRecord&)>& visit);

} // namespace ks::modelio
