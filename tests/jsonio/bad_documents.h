#pragma once
// The bad documents every file kind's reader must refuse the same way, each with the place and the words
// its error names. Each reader's tests run this table through its own loader (levels, campaigns, clips,
// prefabs, options, saves, play-test reports), so the document checks cannot drift apart again.
#include <string>
#include <vector>

namespace ks::test {

struct BadDocument {
    const char* name;
    std::string text;
    std::string place;   // ":line:column: " as the message shows it
    std::string message; // words the message holds
};

inline const std::vector<BadDocument>& bad_documents() {
    static const std::vector<BadDocument> table = {
        // The byte-order mark is skipped, so the syntax error after it is still at 2:8.
        {"byte-order mark", "\xEF\xBB\xBF{\n  \"a\": }", ":2:8: ", "JSON syntax error"},
        {"empty", " \n\t", ":1:1: ", "file is empty"},
        {"NUL byte", std::string("{\"name\": \"a\0b\"}", 15),
         ":1:12: ", "file is not a text file (byte 0x00"},
        {"syntax error", "{\n  \"name\": \"x\",,\n}", ":2:15: ", "JSON syntax error"},
        {"duplicate key", "{\"name\": \"a\",\n \"name\": \"b\"}",
         ":2:2: ", "name: duplicate key (also at line 1:2)"},
        {"overflowing number", "{\"name\": 1e999}", ":1:10: ", "name: number 1e999 overflows"},
        {"too deep", "{\"a\": " + std::string(70, '[') + std::string(70, ']') + "}",
         ":1:70: ", "nested deeper than 64 levels"},
    };
    return table;
}

} // namespace ks::test
