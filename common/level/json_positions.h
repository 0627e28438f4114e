#pragma once
// Where each value of a JSON text sits (line:column), keyed by its path ("entities[3].props.size"), so that
// problems found after parsing -- a range error, an unknown field -- can still point at the exact spot.
// nlohmann's parser keeps no positions, so this is a second, small scan of text it has already accepted.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ks::level {

struct TextPosition {
    int line = 0;   // 1-based; 0 = unknown
    int column = 0; // 1-based, in characters (UTF-8 code points)
};

// Line and column of a byte offset (clamped to the text).
TextPosition position_of_offset(std::string_view text, size_t offset);

struct DuplicateKey {
    std::string path; // path of the repeated member
    TextPosition first, second;
};

// A number token too large for a double (1e999): nlohmann refuses the whole document over it, so the scan
// finds these first and the loader reports each one with its place, then blanks it out and parses the rest.
struct OverflowingNumber {
    std::string path;
    TextPosition position;
    size_t offset = 0, length = 0;
    std::string token;
};

class PositionMap {
  public:
    // Scans JSON text (tolerant of errors: it never loops or reads out of bounds). Object members map to the
    // position of their key, array elements to the start of the value; the root is "".
    static PositionMap scan(std::string_view text);

    // The position of `path`, or of its nearest ancestor that is known (a missing field points at its
    // object). The first call sorts an index (only files with problems ever need one); not thread-safe.
    TextPosition find(const std::string& path) const;
    const std::vector<DuplicateKey>& duplicate_keys() const { return duplicates_; }
    const std::vector<OverflowingNumber>& overflowing_numbers() const { return overflows_; }
    bool empty() const { return entries_.empty(); }

  private:
    struct Entry {
        std::uint32_t offset, length; // the path, inside arena_
        TextPosition position;
    };
    std::string_view path_of(const Entry& e) const {
        return std::string_view(arena_).substr(e.offset, e.length);
    }
    // Every path back to back, and one entry per value in document order: no allocation per value, so a
    // 4 MB level scans in about the time nlohmann takes to parse it.
    std::string arena_;
    std::vector<Entry> entries_;
    mutable std::vector<std::uint32_t> sorted_; // entry indices sorted by path, built by the first find()
    std::vector<DuplicateKey> duplicates_;
    std::vector<OverflowingNumber> overflows_;
    friend class PositionScanner;
};

// Paths as designers read them: "entities[3].props.size[0]".
std::string member_path(const std::string& parent, std::string_view key);
std::string element_path(const std::string& parent, size_t index);

} // namespace ks::level
