// An OBJ's material library walked statement by statement as assimp's ObjFileMtlImporter::load dispatches
// them (mtl_checks.h).
#include "modelio/mtl_checks.h"

#include "modelio/obj_text.h"

#include <array>
#include <cctype>
#include <string>

namespace ks::modelio {

namespace {

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) !=
            std::tolower(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

// The texture statements getTexture() writes into the current material (its "refl" writes nothing).
bool is_texture_statement(std::string_view s) {
    static constexpr std::array<std::string_view, 16> kTextures{
        "map_Kd", "map_Ka", "map_Ks", "map_d",  "map_emissive", "map_Ke", "map_bump", "bump",
        "map_Kn", "norm",   "disp",   "map_ns", "map_Pr",       "map_Pm", "map_Ps",   "map_disp"};
    for (std::string_view t : kTextures)
        if (starts_with_ignoring_case(s, t)) return true;
    return false;
}

// What load() does with a statement starting at `s`, as far as the current material goes.
enum class Statement { other, creates_material, needs_material };

Statement classify(std::string_view s) {
    if (s.empty()) return Statement::other;
    switch (s[0]) {
    case 'a':
        return Statement::needs_material; // anisotropy, written without a check
    case 'm':
    case 'b':
        return is_texture_statement(s) ? Statement::needs_material : Statement::other;
    case 'd':
        return s.size() >= 4 && s.substr(1, 3) == "isp" ? Statement::needs_material : Statement::other;
    case 'n':
    case 'N':
        if (s.size() >= 2 && s[1] == 'e') return Statement::creates_material;
        if (s.size() >= 2 && s[1] == 'o' && is_texture_statement(s)) return Statement::needs_material;
        return Statement::other;
    default:
        return Statement::other;
    }
}

std::string statement_word(std::string_view s) {
    std::size_t n = 0;
    while (n < s.size() && n < 24 && !is_obj_line_end(s[n]) && !is_obj_space(s[n])) ++n;
    std::string word(s.substr(0, n));
    for (char& c : word)
        if (static_cast<unsigned char>(c) < 0x20) c = '?';
    return word;
}

} // namespace

Result<bool> check_mtl_file(std::string_view file, const std::filesystem::path& path, bool material_current) {
    // BaseImporter::ConvertToUTF8, which the reader's text goes through: under 8 bytes it refuses the
    // file; a UTF-8 byte order mark is dropped; UTF-16 and UTF-32 ones are "converted" into a buffer it
    // then drops, so the reader parses the raw bytes (the big-endian UTF-32 swap writes past the buffer).
    if (file.size() < 8) return material_current;
    if (file.starts_with(std::string_view("\xFE\xFF", 2)) ||
        file.starts_with(std::string_view("\xFF\xFE", 2)) ||
        file.starts_with(std::string_view("\0\0\xFE\xFF", 4)))
        return Error("the material library is UTF-16 or UTF-32 text, which the OBJ reader cannot read (it "
                     "parses the bytes as they are, and writes past them for big-endian UTF-32)",
                     Location(path.string(), 1, 1), "save the .mtl file as UTF-8");
    const std::size_t text_start = file.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    int line = 1;
    std::size_t line_start = 0;
    for (std::size_t s = text_start; s < file.size();) {
        if (!material_current) {
            switch (classify(file.substr(s))) {
            case Statement::creates_material:
                material_current = true;
                break;
            case Statement::needs_material:
                return Error("\"" + statement_word(file.substr(s)) +
                                 "\" comes before the file's first newmtl, so it belongs to no material (the "
                                 "OBJ reader crashes on it)",
                             Location(path.string(), line, static_cast<int>(s - line_start) + 1),
                             "put \"newmtl <name>\" before each material's statements");
            case Statement::other:
                break;
            }
        }
        // The next statement: past this line's end, then spaces and tabs.
        while (s < file.size() && !is_obj_line_end(file[s])) ++s;
        if (s < file.size() && file[s] == '\n') {
            ++line;
            line_start = s + 1;
        }
        ++s;
        while (s < file.size() && is_obj_space(file[s])) ++s;
    }
    return material_current;
}

} // namespace ks::modelio
