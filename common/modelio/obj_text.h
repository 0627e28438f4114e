#pragma once
// The character classes of assimp's OBJ and MTL readers (its ParsingUtils.h), shared by the checks that
// walk a file as those readers do (obj_checks.h, mtl_checks.h).

namespace ks::modelio {

// A line ends at \n, \r, \f or NUL.
inline bool is_obj_line_end(char c) {
    return c == '\n' || c == '\r' || c == '\f' || c == '\0';
}

// Spaces between words: a space or a tab only (a vertical tab is not one).
inline bool is_obj_space(char c) {
    return c == ' ' || c == '\t';
}

} // namespace ks::modelio
