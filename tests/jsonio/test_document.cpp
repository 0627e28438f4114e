// jsonio::Document: the checks on a JSON document that every file kind shares, done once.
#include "jsonio/bad_documents.h"
#include "jsonio/document.h"

#include <doctest/doctest.h>

using namespace ks::jsonio;

namespace {
const DocumentKind kKind{"thing", "a thing file is {\"name\": ...}"};

std::string all(const Document& doc) {
    std::string out;
    for (const Problem& p : doc.problems()) out += p.error.str() + "\n";
    return out;
}
} // namespace

TEST_CASE("every bad document gives one error with its line:column, its words and a fix") {
    for (const ks::test::BadDocument& bad : ks::test::bad_documents()) {
        CAPTURE(bad.name);
        const Document doc = Document::parse(bad.text, "t.json", kKind);
        const std::string text = all(doc);
        CAPTURE(text);
        REQUIRE(doc.problems().size() == 1);
        CHECK(text.find("t.json" + bad.place) != std::string::npos);
        CHECK(text.find(bad.message) != std::string::npos);
        CHECK_FALSE(doc.problems()[0].error.hint.empty());
        CHECK(doc.problems()[0].severity == Severity::Error);
    }
}

TEST_CASE("a byte-order mark before a good document is no problem") {
    const Document doc = Document::parse("\xEF\xBB\xBF{\"a\": 1}", "t.json", kKind);
    CHECK_FALSE(doc.has_problems());
    REQUIRE(doc.root());
    CHECK((*doc.root())["a"] == 1);
}

TEST_CASE("a duplicate key or an overflowing number still leaves the rest readable") {
    const Document dup = Document::parse("{\"a\": 1, \"a\": 2, \"b\": 3}", "t.json", kKind);
    REQUIRE(dup.root());
    CHECK(dup.problems().size() == 1);
    const Document big = Document::parse("{\"a\": 1e999, \"b\": -2e400, \"c\": 3}", "t.json", kKind);
    REQUIRE(big.root());
    CHECK((*big.root())["a"].is_null());
    CHECK((*big.root())["c"] == 3);
    CHECK(big.problems().size() == 2);
    // The overflowing paths are passed on as reported, so a reader says nothing more about them.
    Problems sink("t.json", &big.positions());
    big.report_to(sink);
    CHECK(sink.already_reported("a"));
    CHECK(sink.already_reported("b"));
    CHECK_FALSE(sink.already_reported("c"));
    CHECK(sink.errors().size() == 2);
}

TEST_CASE("a root that is not an object, broken UTF-8 and a truncated file") {
    const Document array = Document::parse("[1, 2]", "t.json", kKind);
    CHECK_FALSE(array.root());
    CHECK(all(array).find("t.json:1:1: expected the thing as a JSON object {...}, found an array") !=
          std::string::npos);
    const Document utf8 = Document::parse("{\"a\": \"\xff\"}", "t.json", kKind);
    CHECK(all(utf8).find("t.json:1:8: file is not a text file (byte 0xff at offset 7)") != std::string::npos);
    const Document cut = Document::parse("{\"a\": [1,", "t.json", kKind);
    CHECK(all(cut).find("file ends early (truncated?)") != std::string::npos);
}

TEST_CASE("nesting is counted outside strings only, up to the limit") {
    const std::string at_limit =
        "{\"a\": " + std::string(kMaxNestingDepth - 1, '[') + std::string(kMaxNestingDepth - 1, ']') + "}";
    CHECK_FALSE(Document::parse(at_limit, "t.json", kKind).has_problems());
    const std::string in_string = "{\"a\": \"" + std::string(200, '[') + "\"}";
    CHECK_FALSE(Document::parse(in_string, "t.json", kKind).has_problems());
}
