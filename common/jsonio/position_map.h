#pragma once
// Where each value of a JSON text sits (line:column), keyed by its path ("entities[3].props.size"), so that
// problems found after parsing -- a range error, an unknown field -- can still point at the exact spot.
// nlohmann's parser keeps no positions, so this is a second, small scan of text it has already accepted.
// Only the duplicate keys and overflowing numbers are found up front; the map of every value's position is
// built by the first lookup, since only a file with a problem ever needs one (it used to cost more than
// nlohmann's whole parse on every load).
#include "jsonio/json_path.h"
#include "jsonio/text_position.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ks::jsonio {

struct DuplicateKey {
    std::string path; // path of the repeated member
    TextPosition first, second;
};

// A number token too large for a double (1e999): nlohmann refuses the whole document over it, so the scan
// finds these first and a loader can report each one with its place, then blank it out and parse the rest.
struct OverflowingNumber {
    std::string path;
    TextPosition position;
    std::size_t offset = 0, length = 0;
    std::string token;
};

class PositionMap {
  public:
    // Scans JSON text (tolerant of errors: it never loops or reads out of bounds); the root is "". Keeps a
    // copy of the text for the lookups.
    static PositionMap scan(std::string_view text);

    // Where a problem with `path` is shown: an object member at its key, an array element at its value. A
    // missing path gives its nearest known ancestor (a missing field points at its object); a duplicated
    // key its first occurrence. The first lookup scans the text again, recording every value, and sorts an
    // index (only files with problems ever need one); not thread-safe.
    TextPosition find(const std::string& path) const;
    // Where the value at `path` starts, as the parser reads the document: for a duplicated key the last
    // occurrence (the one nlohmann keeps); {0, 0} if the path is not in that document.
    TextPosition find_value(const std::string& path) const;

    const std::vector<DuplicateKey>& duplicate_keys() const { return duplicates_; }
    const std::vector<OverflowingNumber>& overflowing_numbers() const { return overflows_; }

  private:
    struct Entry {
        std::uint32_t offset, length; // the path, inside arena_
        TextPosition key;             // the member's key; the value itself for elements and the root
        TextPosition value;
    };
    std::string_view path_of(const Entry& e) const {
        return std::string_view(arena_).substr(e.offset, e.length);
    }
    // Indices into sorted_ of the entries whose path is exactly `path`, in document order.
    std::pair<std::size_t, std::size_t> occurrences(std::string_view path) const;
    void index() const;
    std::string text_;
    // Built by the first lookup: every path back to back, one entry per value in document order (no
    // allocation per value), and the entry indices sorted by path.
    mutable bool indexed_ = false;
    mutable std::string arena_;
    mutable std::vector<Entry> entries_;
    mutable std::vector<std::uint32_t> sorted_;
    std::vector<DuplicateKey> duplicates_;
    std::vector<OverflowingNumber> overflows_;
    friend class PositionScanner;
};

// Where the value at `path` starts in valid JSON `text` (one scan; use a PositionMap for many lookups).
TextPosition locate(std::string_view text, const JsonPath& path);

} // namespace ks::jsonio
