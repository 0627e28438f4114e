#pragma once
// A JSON file parsed once, with every check on the document itself done here for every file kind (levels,
// campaigns, clips, prefabs, options, saves, play-test reports): a byte-order mark (skipped), an empty
// file, binary bytes or broken UTF-8, nesting deeper than kMaxNestingDepth, a syntax error, a number that
// overflows a double, a key written twice in one object, a root that is not an object. Each problem is an
// error with its line:column and a fix; the typed reading of the fields is ObjectReader's job.
#include "jsonio/json_writer.h"
#include "jsonio/position_map.h"
#include "jsonio/problems.h"

#include <string>
#include <string_view>
#include <vector>

namespace ks::jsonio {

// No file of ours nests more than about ten levels; far deeper text is a generator gone wrong or an
// attack, refused before any reader walks it.
inline constexpr int kMaxNestingDepth = 64;

// How messages name a file kind: "expected the level as a JSON object"; `example` is the fix shown for an
// empty or binary file ("a level file starts with {\"format\": ...}").
struct DocumentKind {
    std::string what;
    std::string example;
};

class Document {
  public:
    // Never throws. The text may be anything: a problem leaves root() null or, for a duplicate key or an
    // overflowing number (read as null), is reported beside a usable root.
    static Document parse(std::string_view text, std::string file, const DocumentKind& kind);

    // The root object; nullptr when the text is not a readable JSON object.
    const Json* root() const { return readable_ ? &root_ : nullptr; }
    // The same, for a reader that upgrades an older document in place before reading it.
    Json* root() { return readable_ ? &root_ : nullptr; }
    const std::string& file() const { return file_; }
    const PositionMap& positions() const { return positions_; }
    // The document's own problems, all errors, in document order.
    const std::vector<Problem>& problems() const { return problems_; }
    bool has_problems() const { return !problems_.empty(); }
    // Passes the problems on, and marks the overflowing numbers' paths as reported so that readers skip them.
    void report_to(ProblemSink& sink) const;

  private:
    void add(TextPosition position, std::string path, std::string message, std::string hint);
    void parse_text(std::string_view text, const DocumentKind& kind);

    std::string file_;
    Json root_;
    bool readable_ = false;
    PositionMap positions_;
    std::vector<Problem> problems_;
    std::vector<std::string> overflowing_paths_;
};

} // namespace ks::jsonio
