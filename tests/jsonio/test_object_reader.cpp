// jsonio::ObjectReader and the single-value reads: types, ranges, required fields, unknown fields with a
// did-you-mean, every problem at its line:column; text quoted with control characters escaped, lengths in
// characters.
#include "jsonio/document.h"
#include "jsonio/object_reader.h"
#include "jsonio/text.h"

#include <doctest/doctest.h>

using namespace ks::jsonio;

namespace {
const DocumentKind kThingKind{"thing", "a thing file is {\"name\": ...}"};

std::string joined(const std::vector<ks::Error>& errors) {
    std::string out;
    for (const ks::Error& e : errors) out += e.str() + "\n";
    return out;
}
} // namespace

TEST_CASE("typed members: good values are read, bad ones reported at their place and left alone") {
    const std::string text = "{\n"
                             "  \"name\": 7,\n"
                             "  \"speed\": 12,\n"
                             "  \"count\": 2.5,\n"
                             "  \"on\": \"yes\",\n"
                             "  \"mode\": \"lop\",\n"
                             "  \"size\": \"NaN\",\n"
                             "  \"weight\": \"3\",\n"
                             "  \"nmae\": 1\n"
                             "}";
    const Document doc = Document::parse(text, "t.json", kThingKind);
    REQUIRE(doc.root());
    Problems sink("t.json", &doc.positions());
    ObjectReader reader(*doc.root(), "", sink, "thing");
    std::string name = "keep", mode = "once";
    float speed = 1.0f, size = 1.0f, weight = 1.0f;
    int count = 4;
    bool on = false;
    CHECK_FALSE(reader.text("name", name, Need::Required));
    CHECK_FALSE(reader.number("speed", speed, {0, 10, "m/s"}));
    CHECK_FALSE(reader.whole("count", count, {0, 100}));
    CHECK_FALSE(reader.flag("on", on));
    CHECK_FALSE(reader.choice("mode", mode, {"once", "loop"}));
    CHECK_FALSE(reader.number("size", size, {}));
    CHECK_FALSE(reader.number("weight", weight, {}));
    std::string title;
    CHECK_FALSE(reader.text("title", title, Need::Required));
    reader.finish();
    CHECK(name == "keep");
    CHECK(speed == 1.0f);
    CHECK(count == 4);
    CHECK(mode == "once");
    const std::string errors = joined(sink.errors());
    CAPTURE(errors);
    CHECK(sink.errors().size() == 8);
    CHECK(errors.find("t.json:2:3: name: expected a string, found the number 7") != std::string::npos);
    CHECK(errors.find("t.json:3:3: speed: 12 is out of range (valid: 0 .. 10 m/s)") != std::string::npos);
    CHECK(errors.find("t.json:4:3: count: 2.5 is not a whole number") != std::string::npos);
    CHECK(errors.find("t.json:5:3: on: expected true or false, found the string \"yes\"") !=
          std::string::npos);
    CHECK(errors.find("t.json:6:3: mode: unknown value \"lop\" (did you mean \"loop\"?") !=
          std::string::npos);
    CHECK(errors.find("t.json:7:3: size: \"NaN\" is not a finite number") != std::string::npos);
    CHECK(errors.find("t.json:8:3: weight: number written as a string \"3\"") != std::string::npos);
    // A missing member points at its object.
    CHECK(errors.find("t.json:1:1: title: missing required field \"title\"") != std::string::npos);
    const std::string warnings = joined(sink.warnings());
    CHECK(sink.warnings().size() == 1);
    CHECK(warnings.find("t.json:9:3: nmae: unknown field \"nmae\" is ignored (did you mean \"name\"?") !=
          std::string::npos);
    CHECK(sink.has_errors());
    CHECK(sink.combined().str().find("8 problems:") != std::string::npos);
}

TEST_CASE("good members are read, and a claimed member is not unknown") {
    const Document doc = Document::parse("{\"name\": \"x\", \"speed\": 2, \"at\": [1, 2, 3], \"other\": {}}",
                                         "t.json", kThingKind);
    Problems sink("t.json", &doc.positions());
    ObjectReader reader(*doc.root(), "", sink, "thing");
    std::string name;
    double speed = 0;
    double at[3] = {};
    CHECK(reader.text("name", name, Need::Required, 8));
    CHECK(reader.number("speed", speed, {0, 10}));
    CHECK(reader.numbers("at", at, 3, {-5, 5}));
    reader.claim("other");
    reader.finish();
    CHECK(name == "x");
    CHECK(speed == 2);
    CHECK(at[2] == 3);
    CHECK_FALSE(sink.has_errors());
    CHECK(sink.warnings().empty());
}

TEST_CASE("an object that is not one is reported once; its reads find nothing") {
    const Document doc = Document::parse("{\"inner\": [1]}", "t.json", kThingKind);
    Problems sink("t.json", &doc.positions());
    ObjectReader reader((*doc.root())["inner"], "inner", sink, "the inner part");
    std::string name;
    CHECK_FALSE(reader.is_object());
    CHECK_FALSE(reader.text("name", name, Need::Required));
    reader.finish();
    REQUIRE(sink.errors().size() == 1);
    CHECK(sink.errors()[0].str().find(
              "t.json:1:2: inner: expected the inner part as an object {...}, found an array") !=
          std::string::npos);
}

TEST_CASE("text limits count characters, not bytes") {
    const std::string e_acute = "\xc3\xa9";
    std::string three_hundred;
    for (int i = 0; i < 300; ++i) three_hundred += e_acute;
    CHECK(character_count(three_hundred) == 300);
    const Document doc = Document::parse("{\"text\": \"" + three_hundred + "\"}", "t.json", kThingKind);
    Problems sink("t.json", &doc.positions());
    ObjectReader reader(*doc.root(), "", sink, "thing");
    std::string out;
    CHECK(reader.text("text", out, Need::Required, 300));
    CHECK_FALSE(sink.has_errors());
    ObjectReader short_reader(*doc.root(), "", sink, "thing");
    CHECK_FALSE(short_reader.text("text", out, Need::Required, 299));
    CHECK(joined(sink.errors()).find("text of 300 characters is too long") != std::string::npos);
}

TEST_CASE("quoted escapes control characters, so a NUL or a newline cannot cut a message short") {
    CHECK(quote_text(std::string("a\0b", 3)) == "\"a\\u0000b\"");
    CHECK(quote_text("line\nnext") == "\"line\\nnext\"");
    CHECK(quote_text("plain") == "\"plain\"");
    // Long text is cut at a character boundary.
    std::string long_text;
    for (int i = 0; i < 100; ++i) long_text += "\xc3\xa9";
    const std::string cut = quote_text(long_text, 10);
    CHECK(character_count(cut) == 12); // two quotes, 7 characters, "..."
    CHECK(cut.substr(cut.size() - 4) == "...\"");
    // An unknown key holding a NUL is named whole, escaped.
    const Document doc = Document::parse("{\"a\\u0000b\": 1}", "t.json", kThingKind);
    Problems sink("t.json", &doc.positions());
    ObjectReader reader(*doc.root(), "", sink, "thing");
    reader.finish();
    REQUIRE(sink.warnings().size() == 1);
    CHECK(sink.warnings()[0].message == "unknown field \"a\\u0000b\" is ignored");
}

TEST_CASE("ranges read as designers write them") {
    CHECK(Range{0, 10, "s"}.text() == "0 .. 10 s");
    CHECK(Range{1}.text() == "at least 1");
    CHECK(Range{}.text() == "any finite number");
    ks::Error many = combined_error(std::vector<ks::Error>(60, ks::Error("x", ks::Location("f", 1, 1))), "f");
    CHECK(many.message.find("... and 10 more errors") != std::string::npos);
}
