// An OBJ file's face statements checked for what assimp's reader would read past (obj_checks.h). The walk
// below follows ObjFileParser::getFace of assimp 5.2.5 step for step; where that cursor would leave the
// line, the file is refused instead.
#include "modelio/obj_checks.h"

#include "core/files.h"
#include "modelio/mtl_checks.h"
#include "modelio/obj_text.h"

#include <climits>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ks::modelio {

namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

// The lines as the reader's IOStreamBuffer::getNextDataLine builds them, each character with its offset in
// the file. Past the file's end the reader's cache holds '\n' (it is filled with them), so a backslash on
// the last line joins it to that filler, not to bytes past the file.
class ReaderLines {
  public:
    explicit ReaderLines(std::string_view file) : file_(file) {}

    bool next() {
        if (pos_ >= file_.size()) return false;
        text_.clear();
        offsets_.clear();
        for (;;) {
            if (at(pos_) == '\\' && is_obj_line_end(at(pos_ + 1))) {
                ++pos_;
                while (at(pos_) != '\n') ++pos_;
                ++pos_;
            } else if (is_obj_line_end(at(pos_))) {
                break;
            }
            text_.push_back(at(pos_));
            offsets_.push_back(std::min(pos_, file_.size()));
            ++pos_;
            if (pos_ >= file_.size()) break;
        }
        ++pos_;
        return true;
    }

    std::string_view text() const { return {text_.data(), text_.size()}; }
    std::size_t offset(std::size_t i) const { return offsets_[i]; }

  private:
    char at(std::size_t k) const { return k < file_.size() ? file_[k] : '\n'; }

    std::string_view file_;
    std::size_t pos_ = 0;
    std::string text_;
    std::vector<std::size_t> offsets_;
};

struct FaceFinding {
    std::size_t at = 0; // index in the line
    std::string what, fix;
};

// The corner (space-separated word) around index `at`, for the message.
std::string corner_at(std::string_view line, std::size_t at) {
    std::size_t begin = at, end = at;
    while (begin > 0 && !is_obj_space(line[begin - 1]) && !is_obj_line_end(line[begin - 1])) --begin;
    while (end < line.size() && !is_obj_space(line[end]) && !is_obj_line_end(line[end])) ++end;
    std::string corner(line.substr(begin, end - begin));
    if (corner.size() > 40) corner = corner.substr(0, 40) + "…";
    for (char& c : corner)
        if (static_cast<unsigned char>(c) < 0x20) c = '?';
    return corner;
}

// getFace's walk over one `f`, `l` or `p` line: the keyword, then corners whose parts ('/'-separated) are
// read by atoi and stepped over by the digits of the value read.
std::optional<FaceFinding> check_face(std::string_view line) {
    std::size_t end = 0;
    while (end < line.size() && !is_obj_line_end(line[end])) ++end;
    std::size_t p = 0;
    while (p < end && !is_obj_space(line[p])) ++p;
    while (p < end && is_obj_space(line[p])) ++p;
    int parts = 0;
    while (p < end) {
        const char c = line[p];
        if (c == '/') {
            ++parts;
            ++p;
            continue;
        }
        if (is_obj_space(c)) {
            parts = 0;
            ++p;
            continue;
        }
        if (c == '\v')
            return FaceFinding{
                p, "a vertical tab (byte 0x0b) in a face, which the OBJ reader reads past the line on",
                "separate a face's corners with spaces"};
        std::size_t q = p;
        const bool negative = line[q] == '-';
        if (line[q] == '-' || line[q] == '+') ++q;
        std::uint64_t magnitude = 0;
        const std::size_t first_digit = q;
        for (; q < end && is_digit(line[q]); ++q)
            magnitude = std::min<std::uint64_t>(magnitude * 10 + static_cast<unsigned>(line[q] - '0'),
                                                std::uint64_t{1} << 40);
        if (q == first_digit || magnitude == 0)
            return std::nullopt; // atoi gives 0: the reader refuses the file
        if (magnitude > (negative ? std::uint64_t{INT_MAX} + 1 : std::uint64_t{INT_MAX}))
            return FaceFinding{p,
                               "the face index in \"" + corner_at(line, p) +
                                   "\" is outside a 32-bit integer, which the OBJ reader misreads and reads "
                                   "past the line on",
                               "indices count the file's vertices from 1 (or back from -1)"};
        if (parts >= 3)
            return FaceFinding{
                p,
                "the face corner \"" + corner_at(line, p) +
                    "\" has more than three parts, which the OBJ reader reads past the line on",
                "write each corner as v, v/vt, v//vn or v/vt/vn"};
        // atoi's value stepped over by its digits: within the characters it read, as it fits in an int.
        std::size_t step = negative ? 2 : 1;
        for (std::uint64_t rest = magnitude / 10; rest != 0; rest /= 10) ++step;
        p += step;
    }
    return std::nullopt;
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && is_obj_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_obj_space(s.back())) s.remove_suffix(1);
    return s;
}

std::string_view first_word(std::string_view line) {
    std::size_t n = 0;
    while (n < line.size() && !is_obj_space(line[n]) && !is_obj_line_end(line[n])) ++n;
    return line.substr(0, n);
}

// What follows a statement's keyword and its spaces, to the line's end (the reader's getNextToken, then
// the line's rest: a `usemtl` or `mtllib` name, spaces inside and after it kept).
std::string_view statement_rest(std::string_view line) {
    std::size_t p = first_word(line).size();
    while (p < line.size() && is_obj_space(line[p])) ++p;
    std::size_t end = p;
    while (end < line.size() && !is_obj_line_end(line[end])) ++end;
    return line.substr(p, end - p);
}

// The library file the reader opens for `mtllib name`: the name after the OBJ's folder, or, when that is
// not there, the OBJ's own name with "mtl" for its extension's last three letters.
std::optional<std::filesystem::path> material_library(const std::filesystem::path& obj,
                                                      std::string_view name) {
    const std::string obj_name = obj.string();
    const std::size_t slash = obj_name.find_last_of("\\/");
    std::string named(name);
    if (slash != std::string::npos && slash > 0) named = obj_name.substr(0, slash) + "/" + named;
    std::error_code ec;
    if (std::filesystem::is_regular_file(named, ec)) return std::filesystem::path(named);
    if (obj_name.size() < 3) return std::nullopt;
    const std::string fallback = obj_name.substr(0, obj_name.size() - 3) + "mtl";
    if (std::filesystem::is_regular_file(fallback, ec)) return std::filesystem::path(fallback);
    return std::nullopt;
}

// A material library the OBJ names, read and checked (mtl_checks.h); whether a material is current after it.
Result<bool> check_material_library(const std::filesystem::path& obj, std::string_view name,
                                    bool material_current) {
    if (name.empty()) return material_current;
    const std::optional<std::filesystem::path> library = material_library(obj, name);
    if (!library) return material_current; // the reader reads no library
    const Result<std::string> text = files::read_text(*library);
    if (!text) return material_current; // unreadable: the reader cannot read it either
    Result<bool> checked = check_mtl_file(*text, *library, material_current);
    if (checked) return checked;
    Error error = checked.error(); // placed in the library; the message names the model it serves
    error.message = "in " + obj.filename().string() + "'s material library: " + error.message;
    return error;
}

} // namespace

Result<void> check_obj_file(std::string_view file, const std::filesystem::path& path) {
    ReaderLines lines(file);
    bool inside_curve_section = false; // `cstype` … `end`: free-form geometry, whose lines the reader skips
    bool material_current = false;     // set by `usemtl` or a library's `newmtl`, never unset
    while (lines.next()) {
        const std::string_view line = lines.text();
        if (line.empty()) continue;
        if (inside_curve_section) {
            if (line[0] == 'e') inside_curve_section = first_word(line) != "end";
            continue;
        }
        if (line[0] == 'c') {
            inside_curve_section = first_word(line) == "cstype";
            continue;
        }
        if (line[0] == 'u' && first_word(line) == "usemtl" && !trimmed(statement_rest(line)).empty()) {
            material_current = true;
            continue;
        }
        if (line[0] == 'm' && first_word(line) == "mtllib") {
            Result<bool> library = check_material_library(path, statement_rest(line), material_current);
            if (!library) return library.error();
            material_current = *library;
            continue;
        }
        if (line[0] != 'f' && line[0] != 'l' && line[0] != 'p') continue;
        const std::optional<FaceFinding> finding = check_face(line);
        if (!finding) continue;
        const std::size_t offset = lines.offset(finding->at);
        int line_number = 1;
        std::size_t line_start = 0;
        for (std::size_t i = 0; i < offset && i < file.size(); ++i)
            if (file[i] == '\n') {
                ++line_number;
                line_start = i + 1;
            }
        return Error(finding->what,
                     Location(path.string(), line_number, static_cast<int>(offset - line_start) + 1),
                     finding->fix);
    }
    return ok();
}

} // namespace ks::modelio
