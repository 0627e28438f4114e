// An OBJ file's face statements that assimp 5.2.5's reader would read past refused before it reads them
// (modelio/obj_checks.h): a fuzz finding (`l… ///63 2//6`, a corner with a fourth part, read past a
// 28-byte line buffer under ASan). A model of the reader's walk, written here from its source, checks that
// every line it would leave is refused.
#include "modelio/model_import.h"
#include "modelio/obj_checks.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cctype>
#include <climits>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace ks;

namespace {

const std::filesystem::path kFile = "props/crate.obj";

const std::string kCube = "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                          "f 1/1/1 2/2/1 3/3/1\nf 1//1 3//1 4//1\nf -4/-3 -3/-2 -2/-1\nf 1 2 3\n";

// ObjFileParser::getFace's cursor over "f …" with the line's '\n' at index line.size() and the buffer
// ending there (a one-line file): true when it, or atoi, would read past that '\n'.
bool reader_leaves_line(const std::string& line) {
    const std::string buffer = line + '\n' + std::string(32, '7') + '\0'; // what lies past: digits
    const std::size_t terminator = line.size();
    std::size_t p = 0;
    auto line_end = [&](std::size_t i) {
        return buffer[i] == '\n' || buffer[i] == '\r' || buffer[i] == '\0';
    };
    auto space = [&](std::size_t i) { return buffer[i] == ' ' || buffer[i] == '\t'; };
    while (p <= terminator && !(space(p) || line_end(p))) ++p;
    while (p <= terminator && space(p) && !line_end(p)) ++p;
    int part = 0;
    while (p != terminator + 1) {
        if (p > terminator) return true;
        if (line_end(p)) return false;
        if (buffer[p] == '/') {
            ++part;
        } else if (space(p)) {
            part = 0;
        } else {
            std::size_t read = p; // the last character strtol looks at
            while (std::isspace(static_cast<unsigned char>(buffer[read]))) ++read;
            if (buffer[read] == '+' || buffer[read] == '-') ++read;
            while (std::isdigit(static_cast<unsigned char>(buffer[read]))) ++read;
            if (read > terminator) return true;
            const int value = static_cast<int>(std::strtol(buffer.c_str() + p, nullptr, 10)); // atoi
            if (value == 0) return false; // "OBJ: Invalid face index": the import stops
            if (part >= 3) return true;   // reportErrorTokenInFace skips the line, then steps on
            int step = value < 0 ? 2 : 1;
            for (int rest = value / 10; rest != 0; rest /= 10) ++step;
            p += static_cast<std::size_t>(step) - 1;
        }
        ++p;
    }
    return true;
}

bool has_ten_digits(const std::string& line) {
    int run = 0;
    for (char c : line) {
        run = std::isdigit(static_cast<unsigned char>(c)) ? run + 1 : 0;
        if (run >= 10) return true;
    }
    return false;
}

std::string obj_refusal(const std::string& text) {
    const auto r = modelio::check_obj_file(text, kFile);
    return r.ok() ? std::string() : r.error().str();
}

} // namespace

TEST_CASE("obj checks: faces the reader reads past are refused with the line and column") {
    CHECK(modelio::check_obj_file(kCube, kFile).ok());
    // The fuzz finding: a line statement ('l' starts the keyword) whose first corner has a fourth part.
    const std::string found = obj_refusal("lliobCnnections: ///63 2//6\n");
    CHECK(found.find("crate.obj:1:21") != std::string::npos);
    CHECK(found.find("\"///63\" has more than three parts") != std::string::npos);
    CHECK(found.find("v/vt/vn") != std::string::npos);
    CHECK(obj_refusal(kCube + "f 1/1/1/1 2/2/1 3/3/1\n").find("crate.obj:13:9:") != std::string::npos);
    CHECK(obj_refusal(kCube + "p 1 2/2/2/2\n").find(":13:11:") != std::string::npos);
    // 2147483648 is -2147483648 to atoi, eleven characters' worth of step: past the line's end.
    CHECK(obj_refusal(kCube + "f 1 2 2147483648\n").find(":13:7: the face index in \"2147483648\" is outside") !=
          std::string::npos);
    CHECK_FALSE(obj_refusal(kCube + "f 1 2 -2147483649\n").empty());
    CHECK_FALSE(obj_refusal(kCube + "f 1 2 99999999999999999999999\n").empty());
    CHECK(
        modelio::check_obj_file(kCube + "f 1 2 -2147483648\n", kFile).ok()); // an int: the reader's to refuse
    CHECK(obj_refusal(kCube + "f 1 2 \v\n").find(":13:7: a vertical tab") != std::string::npos);
    // A backslash joins the next line: the place named is the byte's own line and column.
    CHECK(obj_refusal(kCube + "f 1 2 \\\n 3/1/1/1\n").find(":14:8:") != std::string::npos);
    CHECK(obj_refusal(kCube + "f 1 2 3\r\nf 1/2/3/4\r\n").find(":14:9:") != std::string::npos);
}

TEST_CASE("obj checks: what the reader does not walk as a face passes") {
    // Comments, statements not at a line's start, and a free-form section's lines are not faces.
    CHECK(modelio::check_obj_file(kCube + "# f 1/2/3/4\n  f 1/2/3/4\n\tl 2147483648\n", kFile).ok());
    CHECK(modelio::check_obj_file(kCube + "cstype bspline\ndeg 3\nparm 1/1/1/1\nend\n", kFile).ok());
    CHECK_FALSE(modelio::check_obj_file(kCube + "cstype bspline\nend\nparm 1/1/1/1\n", kFile).ok());
    CHECK_FALSE(modelio::check_obj_file(kCube + "curv 0 1 1 2\nparm 1/1/1/1\n", kFile).ok());
    // Faces the reader itself refuses ("Invalid face index") or reads within the line.
    CHECK(modelio::check_obj_file(kCube + "f a b c\nf 0 1 2\nf +1 +2 +3\nf 007 08 9\n", kFile).ok());
    CHECK(modelio::check_obj_file("", kFile).ok());
    CHECK(modelio::check_obj_file("\\", kFile).ok());
    CHECK(modelio::check_obj_file("f 1 2 3\\", kFile).ok());
    // A backslash before \r skips to the next \n (here the reader's filler past the file): the rest is
    // unread.
    CHECK(modelio::check_obj_file("f 1 2 3\\\r1/1/1/1", kFile).ok());
}

TEST_CASE("obj checks: every random face line the reader would read past is refused") {
    const std::vector<std::string> pieces{
        "1",  "2",  "9",  "0",  "-",          "+",          "/",           "//",         " ",
        "\t", "\v", "12", "-3", "2147483647", "2147483648", "-2147483648", "4294967295", "99999999999"};
    std::mt19937 random(20261202);
    int leaving = 0, refused = 0;
    for (int n = 0; n < 40000; ++n) {
        std::string line = "f ";
        const int count = 1 + static_cast<int>(random() % 9);
        for (int i = 0; i < count; ++i) line += pieces[random() % pieces.size()];
        const bool leaves = reader_leaves_line(line);
        const bool checked = modelio::check_obj_file(line + "\n", kFile).ok();
        if (leaves) {
            ++leaving;
            CAPTURE(line);
            CHECK_FALSE(checked);
        }
        if (!checked) ++refused;
        if (!checked && !leaves) { // stricter than the reader's walk only for a vertical tab or a huge number
            CAPTURE(line);
            CHECK((line.find('\v') != std::string::npos || has_ten_digits(line)));
        }
    }
    MESSAGE(leaving, " of 40000 random lines leave the line; ", refused, " refused");
    CHECK(leaving > 2000);
    CHECK(reader_leaves_line("f ///63 2//6"));
    CHECK(reader_leaves_line("f 1 2 2147483648"));
    CHECK(reader_leaves_line("f 1 \v"));
    CHECK_FALSE(reader_leaves_line("f 1/2/3 -1//2 +3"));
}

TEST_CASE("obj checks: the import refuses such a file before assimp reads it, naming it") {
    test::ScratchDir dir;
    const auto file = test::write_file(dir / "found.obj", "lliobCnnections: ///63 2//6\n");
    const auto model = modelio::import_model(file, modelio::ImportLimits{});
    REQUIRE_FALSE(model.ok());
    CHECK(model.error().where.file == file.string());
    CHECK(model.error().where.line == 1);
    CHECK(model.error().where.column == 21);
    CHECK(model.error().message.find("more than three parts") != std::string::npos);
    const auto good = test::write_file(dir / "good.obj", kCube);
    CHECK(modelio::import_model(good, modelio::ImportLimits{}).ok());
}
