#pragma once
// "Did you mean" help for names a designer typed: the known name closest by edit distance.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ks::jsonio {

// Levenshtein distance: insertions, deletions and substitutions of single bytes.
std::size_t edit_distance(std::string_view a, std::string_view b);
// The same, but any distance of `limit` or more comes back as `limit`: it stops as soon as the words' lengths
// or a whole row of the table say so, so a long unknown word against a list of names costs little.
std::size_t edit_distance_within(std::string_view a, std::string_view b, std::size_t limit);

// The candidate closest to `word`, or "" when none is close enough to be a plausible typo (more than a
// third of the word, and at least 3 edits, away).
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// "a, b, c": lists of valid names in messages.
std::string join(const std::vector<std::string>& words, std::string_view separator = ", ");

} // namespace ks::jsonio
