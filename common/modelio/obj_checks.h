#pragma once
// An OBJ file's face statements checked before assimp reads it. Assimp 5.2.5's OBJ reader walks a face
// (`f`, `l` or `p`) line with a cursor that it moves by the digits of the index `atoi` returned, and
// `while (cursor != end)`, so three inputs move it past the line and it reads on through the heap (a fuzz
// finding, docs/reliability.md):
//  - a corner with more than three parts (`1/2/3/4`): the reader reports the token, skips to the line's
//    end, then still adds the token's length;
//  - an index outside a 32-bit int (`2147483648` becomes -2147483648, eleven characters' worth);
//  - a vertical tab (0x0b), which the reader takes for part of an index but `atoi` skips as white space,
//    past the line's end when nothing follows.
// Lines are split as the reader splits them: at \n, \r, \f and NUL, a backslash before one of them joining
// the next line; statements inside a `cstype` … `end` section are not faces. Each `mtllib` library the
// reader would open (the name beside the OBJ, else the OBJ's own name with .mtl) is checked too
// (mtl_checks.h), knowing whether a `usemtl` came before it.
#include "core/result.h"

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace ks::modelio {

// The first face statement the reader would read past, or library statement it would crash on, refused
// with the file (the OBJ or the library), the line and the column (1-based, counted in \n lines) and how to
// write it; any other text passes (assimp refuses or reads it).
Result<void> check_obj_file(std::string_view file, const std::filesystem::path& path);

} // namespace ks::modelio
