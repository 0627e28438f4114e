#pragma once
// An OBJ's material library (.mtl) checked before assimp reads it. Assimp 5.2.5's MTL reader writes a
// texture statement (`map_Kd`, `bump`, `disp`, `norm`, …) and an anisotropy (`a`) into the current
// material without checking that there is one: such a statement before the file's first `newmtl`, in a
// library the OBJ names before any `usemtl`, crashed the import (a null pointer written; found by reading
// the reader after a fuzz finding in the OBJ one, confirmed with assimp itself). Statements start where the
// reader starts them: at the file's first byte, and after every line end (\n, \r, \f, NUL) past spaces and
// tabs.
#include "core/result.h"

#include <filesystem>
#include <string_view>

namespace ks::modelio {

// A library in UTF-16 or UTF-32 (by its byte order mark) is refused: the reader parses its raw bytes.
// Whether a material is current after the library is read (it was before, or the file made one), or the
// first statement the reader would crash on, refused with the library's file, line and column.
Result<bool> check_mtl_file(std::string_view file, const std::filesystem::path& path, bool material_current);

} // namespace ks::modelio
