// Edit distance and the "did you mean" choice built on it.
#include "jsonio/suggest.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

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

TEST_CASE("edit_distance_within: the exact distance below its limit, the limit at or above it") {
    CHECK(edit_distance_within("kitten", "sitting", 4) == 3);
    CHECK(edit_distance_within("kitten", "sitting", 3) == 3);
    CHECK(edit_distance_within("kitten", "sitting", 2) == 2);
    CHECK(edit_distance_within("abc", "abc", 1) == 0);
    CHECK(edit_distance_within("abc", "xyz", 0) == 0);
    CHECK(edit_distance_within("", "abcdef", 3) == 3);
    CHECK(edit_distance_within(std::string(5000, 'q'), "position", 4) == 4); // by the lengths, at once
    // Against the full table on every pair of short words over a small alphabet (ties, swaps, prefixes).
    std::vector<std::string> words;
    for (int n = 0; n <= 4; ++n)
        for (int code = 0; code < (1 << (2 * n)); ++code) {
            std::string w;
            for (int k = 0; k < n; ++k) w += static_cast<char>('a' + ((code >> (2 * k)) & 3));
            words.push_back(w);
        }
    int mismatches = 0;
    for (std::size_t i = 0; i < words.size(); i += 3)
        for (std::size_t j = 0; j < words.size(); j += 5) {
            const std::size_t full = edit_distance(words[i], words[j]);
            for (std::size_t limit = 0; limit <= 5; ++limit)
                mismatches += edit_distance_within(words[i], words[j], limit) != std::min(full, limit);
        }
    CHECK(mismatches == 0);
}

TEST_CASE("closest_match: long unknown words give no suggestion, and the same one as the full table would") {
    const std::vector<std::string> fields = {"position", "rotation", "health", "speed"};
    CHECK(closest_match(std::string(100000, 'x'), fields).empty());
    CHECK(closest_match("rotatoin", fields) == "rotation");
}

TEST_CASE("join lists names with a separator") {
    CHECK(join({}) == "");
    CHECK(join({"a"}) == "a");
    CHECK(join({"a", "b", "c"}) == "a, b, c");
    CHECK(join({"a", "b"}, " | ") == "a | b");
}
