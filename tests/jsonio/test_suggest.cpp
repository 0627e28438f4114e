// Edit distance and the "did you mean" choice built on it.
#include "jsonio/suggest.h"

#include <doctest/doctest.h>

using namespace ks::jsonio;

TEST_CASE("edit_distance counts single-byte insertions, deletions and substitutions") {
    CHECK(edit_distance("", "") == 0);
    CHECK(edit_distance("abc", "") == 3);
    CHECK(edit_distance("", "abc") == 3);
    CHECK(edit_distance("kitten", "sitting") == 3);
    CHECK(edit_distance("health", "heatlh") == 2); // a swap is two edits
    CHECK(edit_distance("flaw", "lawn") == 2);
    CHECK(edit_distance("same", "same") == 0);
    CHECK(edit_distance("ab", "ba") == edit_distance("ba", "ab"));
}

TEST_CASE("closest_match suggests only plausible typos") {
    const std::vector<std::string> fields = {"position", "rotation", "health", "speed"};
    CHECK(closest_match("positon", fields) == "position");
    CHECK(closest_match("helth", fields) == "health");
    CHECK(closest_match("sped", fields) == "speed");
    CHECK(closest_match("colour", fields).empty());
    CHECK(closest_match("xyz", {}).empty());
    // Short words allow two edits; three is too many.
    CHECK(closest_match("ab", {"abcd"}) == "abcd");
    CHECK(closest_match("ab", {"abcde"}).empty());
    // Ties go to the first candidate, so the suggestion does not depend on hash order.
    CHECK(closest_match("cat", {"bat", "hat"}) == "bat");
}

TEST_CASE("join lists names with a separator") {
    CHECK(join({}) == "");
    CHECK(join({"a"}) == "a");
    CHECK(join({"a", "b", "c"}) == "a, b, c");
    CHECK(join({"a", "b"}, " | ") == "a | b");
}
