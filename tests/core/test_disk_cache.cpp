#include "core/disk_cache.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;

TEST_CASE("disk_cache Writer/Reader round-trip values and vectors, empty ones included") {
    disk_cache::Writer w;
    w.value(std::uint32_t{7});
    w.values(std::vector<float>{});          // an empty vector (its data() is null): a count of zero
    w.values(std::vector<float>{1.5f, -2.0f});
    w.values(std::vector<std::uint64_t>{}); // two empties in a row
    const std::string payload = w.data();

    disk_cache::Reader r(payload);
    std::uint32_t a = 0;
    std::vector<float> empty{9.0f}, two;
    std::vector<std::uint64_t> empty2{1};
    REQUIRE(r.value(a));
    REQUIRE(r.values(empty, 100));
    REQUIRE(r.values(two, 100));
    REQUIRE(r.values(empty2, 100));
    CHECK(r.at_end());
    CHECK(a == 7);
    CHECK(empty.empty()); // replaced, not appended to
    CHECK(two == std::vector<float>{1.5f, -2.0f});
    CHECK(empty2.empty());
}

TEST_CASE("disk_cache Reader refuses truncated payloads and counts over the limit") {
    disk_cache::Writer w;
    w.values(std::vector<double>{1.0, 2.0, 3.0});
    const std::string payload = w.data();
    for (std::size_t cut = 0; cut < payload.size(); ++cut) {
        CAPTURE(cut);
        disk_cache::Reader r(std::string_view(payload).substr(0, cut));
        std::vector<double> v;
        CHECK_FALSE(r.values(v, 100));
        CHECK_FALSE(r.ok());
        std::uint64_t after = 0;
        CHECK_FALSE(r.value(after)); // a failed reader stays failed
    }
    disk_cache::Reader limited(payload);
    std::vector<double> v;
    CHECK_FALSE(limited.values(v, 2)); // three stored, at most two allowed
}

TEST_CASE("disk_cache Store: an entry read back, an empty payload, and a corrupt file is a miss") {
    test::ScratchDir dir;
    const disk_cache::Store store(dir.path() / "cache");
    CHECK_FALSE(store.load("test", 1).has_value()); // nothing yet, and no folder
    REQUIRE(store.save("test", 1, "payload"));
    REQUIRE(store.save("test", 2, ""));
    CHECK(store.load("test", 1) == std::optional<std::string>("payload"));
    CHECK(store.load("test", 2) == std::optional<std::string>(""));
    CHECK_FALSE(store.load("other", 1).has_value()); // another kind with the same key
    // One byte of the payload changed: the checksum no longer matches.
    auto bytes = test::read_file(store.file("test", 1));
    bytes.back() ^= 0x01;
    test::write_file(store.file("test", 1), bytes);
    CHECK_FALSE(store.load("test", 1).has_value());
    CHECK_FALSE(disk_cache::Store(std::filesystem::path()).enabled());
}
