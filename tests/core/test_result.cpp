#include "core/result.h"

#include <doctest/doctest.h>

using namespace ks;

namespace {
Result<int> parse_positive(int v) {
    if (v <= 0) return Error("must be positive", Location{"f.json", 3, 7, "entities[2].health"}, "use a value > 0");
    return v;
}
} // namespace

TEST_CASE("Result holds a value or an error with its location") {
    auto good = parse_positive(5);
    REQUIRE(good.ok());
    CHECK(*good == 5);

    auto bad = parse_positive(-1);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().str() == "f.json:3:7: entities[2].health: must be positive (use a value > 0)");
    CHECK(bad.value_or(42) == 42);
}

TEST_CASE("Location prints only the parts it has") {
    CHECK(Location{}.str().empty());
    CHECK(Location{"a.json"}.str() == "a.json");
    CHECK(Location{"a.json", 2}.str() == "a.json:2");
    CHECK(Location{"", 0, 0, "name"}.str() == "name");
}

TEST_CASE("Result<void> and combine_errors") {
    Result<void> fine = ok();
    CHECK(fine.ok());
    Result<void> broken = Error("nope");
    CHECK_FALSE(broken.ok());
    CHECK(broken.error().message == "nope");

    Error all = combine_errors({Error("one", Location{"x"}), Error("two", Location{"x"})});
    CHECK(all.message.find("2 problems") != std::string::npos);
    CHECK(all.message.find("x: one") != std::string::npos);
    CHECK(all.message.find("x: two") != std::string::npos);
}
