// The deterministic document writer and the value descriptions used in messages.
#include "jsonio/describe.h"
#include "jsonio/json_writer.h"

#include <doctest/doctest.h>

#include <limits>

using namespace ks::jsonio;

TEST_CASE("write_document keeps key order, puts scalar arrays on one line and numbers in shortest form") {
    Json doc = Json::object();
    doc["zeta"] = 100.0;
    doc["alpha"] = Json::array({0.1, 1, true, nullptr, "s"});
    doc["nested"] = Json::array({Json::object({{"k", -0.0}}), Json::array()});
    doc["empty"] = Json::object();
    CHECK(write_document(doc) == "{\n"
                                 "  \"zeta\": 100,\n"
                                 "  \"alpha\": [0.1, 1, true, null, \"s\"],\n"
                                 "  \"nested\": [\n"
                                 "    {\n"
                                 "      \"k\": 0\n"
                                 "    },\n"
                                 "    []\n"
                                 "  ],\n"
                                 "  \"empty\": {}\n"
                                 "}\n");
}

TEST_CASE("written numbers read back to the same values") {
    Json doc = Json::array({0.1, 1e-7, 1.0 / 3.0, 4.9406564584124654e-324, -1.7976931348623157e308});
    const Json back = Json::parse(write_document(doc));
    for (std::size_t i = 0; i < doc.size(); ++i) CHECK(back[i].get<double>() == doc[i].get<double>());
}

TEST_CASE("non-finite numbers are written as null, invalid UTF-8 is replaced, not thrown over") {
    const Json doc = Json::array({std::numeric_limits<double>::infinity(), "bad \xff byte"});
    const std::string text = write_document(doc);
    CHECK(text.rfind("[null, \"bad ", 0) == 0);
    CHECK(Json::parse(text)[1].get<std::string>() == "bad \xef\xbf\xbd byte");
    CHECK(json_string("a\"b") == "\"a\\\"b\"");
}

TEST_CASE("json_string quotes exactly as the serializer does, with or without its plain-text shortcut") {
    // Every byte alone and between letters, and a few mixed strings: the same text as nlohmann's dump.
    std::vector<std::string> samples{"",     "Wall 3", "back\\slash", "tab\there",
                                     "Café", "数字",   "\x7f",        "a\"b"};
    for (int c = 1; c < 256; ++c) {
        samples.push_back(std::string(1, static_cast<char>(c)));
        samples.push_back("x" + std::string(1, static_cast<char>(c)) + "y");
    }
    for (const std::string& text : samples) {
        CAPTURE(text);
        CHECK(json_string(text) == Json(text).dump(-1, ' ', false, Json::error_handler_t::replace));
    }
}

TEST_CASE("values are described the way messages need them") {
    CHECK(std::string(type_name(Json(1.5))) == "a number");
    CHECK(std::string(type_name(Json(3))) == "a number");
    CHECK(std::string(type_name(Json("x"))) == "a string");
    CHECK(std::string(type_name(Json::array())) == "an array");
    CHECK(std::string(type_name(Json::object())) == "an object");
    CHECK(std::string(type_name(Json(nullptr))) == "null");
    CHECK(std::string(type_name(Json(false))) == "a boolean");
    CHECK(describe_value(Json("12")) == "the string \"12\"");
    CHECK(describe_value(Json(12)) == "the number 12");
    CHECK(describe_value(Json(true)) == "the boolean true");
    CHECK(describe_value(Json(nullptr)) == "null");
    CHECK(describe_value(Json::array({1})) == "an array");
    const std::string long_text(200, 'x');
    CHECK(quote(Json(long_text)).size() == 80);
    CHECK(quote(Json(long_text)).substr(77) == "...");
}
