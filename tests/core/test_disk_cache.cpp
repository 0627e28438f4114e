#include "core/disk_cache.h"
#include "core/files.h"
#include "hardening/fault_support.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;

TEST_CASE("disk_cache Writer/Reader round-trip values and vectors, empty ones included") {
    disk_cache::Writer w;
    w.value(std::uint32_t{7});
    w.values(std::vector<float>{}); // an empty vector (its data() is null): a count of zero
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
    const auto one = store.load("test", 1), two = store.load("test", 2);
    REQUIRE(one);
    REQUIRE(two);
    CHECK(one->bytes() == "payload");
    CHECK(two->bytes().empty());
    CHECK_FALSE(store.load("other", 1).has_value()); // another kind with the same key
    // One byte of the payload changed: the checksum no longer matches.
    auto bytes = test::read_file(store.file("test", 1));
    bytes.back() ^= 0x01;
    test::write_file(store.file("test", 1), bytes);
    CHECK_FALSE(store.load("test", 1).has_value());
    CHECK_FALSE(disk_cache::Store(std::filesystem::path()).enabled());
}

TEST_CASE("disk_cache Payload: a mapped entry and a read one keep their bytes through moves") {
    test::ScratchDir dir;
    const disk_cache::Store store(dir.path() / "cache");
    std::string big(3'000'000, '\0');
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>((i * 2654435761u) >> 13);
    REQUIRE(store.save("big", 7, big));
    auto loaded = store.load("big", 7);
    REQUIRE(loaded);
    disk_cache::Payload moved = std::move(*loaded);
    CHECK(moved.bytes() == big);
    disk_cache::Payload again(std::string("x"));
    again = std::move(moved);
    CHECK(again.bytes() == big);
    CHECK(moved.bytes().empty());
    // Read into memory (where a file cannot be mapped) and moved: a short string lives inside the object.
    disk_cache::Payload owned(std::string("short"));
    owned.drop_prefix(1);
    disk_cache::Payload owned_moved = std::move(owned);
    CHECK(owned_moved.bytes() == "hort");
    std::string error;
    CHECK_FALSE(disk_cache::Payload::of_file(dir.path() / "no such file", error));
    CHECK_FALSE(error.empty());
    // Replaced while mapped (entries are written by rename): the mapping keeps the bytes it had.
    REQUIRE(store.save("big", 7, "new"));
    CHECK(again.bytes() == big);
    const auto fresh = store.load("big", 7);
    REQUIRE(fresh);
    CHECK(fresh->bytes() == "new");
}

TEST_CASE("disk_cache Hasher: every byte of a long buffer counts, in every lane and the tail") {
    std::string data(1000, '\0');
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>(i * 7);
    const std::uint64_t base = disk_cache::hash_bytes(data);
    CHECK(disk_cache::hash_bytes(data) == base); // repeatable
    int same = 0;
    for (std::size_t i = 0; i < data.size(); ++i) {
        std::string changed = data;
        changed[i] ^= 0x10;
        same += disk_cache::hash_bytes(changed) == base ? 1 : 0;
    }
    CHECK(same == 0);
    // Two lanes' words swapped, and the same bytes shifted by one: different.
    std::string swapped = data;
    std::swap_ranges(swapped.begin(), swapped.begin() + 8, swapped.begin() + 8);
    CHECK(disk_cache::hash_bytes(swapped) != base);
    CHECK(disk_cache::hash_bytes(std::string_view(data).substr(1)) !=
          disk_cache::hash_bytes(data.substr(0, 999)));
    // Lengths around the lanes' threshold and block size all differ from their neighbours.
    std::uint64_t previous = 0;
    for (std::size_t n = 240; n < 300; ++n) {
        const std::uint64_t h = disk_cache::hash_bytes(std::string_view(data).substr(0, n));
        CHECK(h != previous);
        previous = h;
    }
}

TEST_CASE("disk_cache Reader::bytes views the data read from, within its bounds") {
    disk_cache::Writer w;
    w.values(std::vector<unsigned char>{1, 2, 3, 4});
    w.value(std::uint32_t{9});
    disk_cache::Reader r(w.data());
    std::string_view view;
    REQUIRE(r.bytes(view, 4));
    CHECK(view.size() == 4);
    CHECK(view.data() == w.data().data() + 8); // after the count: no copy
    CHECK(view[3] == 4);
    std::uint32_t tail = 0;
    CHECK(r.value(tail));
    CHECK(tail == 9);
    CHECK(r.at_end());
    disk_cache::Reader limited(w.data());
    CHECK_FALSE(limited.bytes(view, 3)); // four stored, at most three allowed
    std::string truncated = w.data().substr(0, 10);
    disk_cache::Reader short_reader(truncated);
    CHECK_FALSE(short_reader.bytes(view, 100)); // the count says 4, only 2 are there
}

TEST_CASE(
    "disk_cache Store: under each write fault the save fails, the previous entry stays, the next save goes "
    "through") {
    test::ScratchDir dir;
    const disk_cache::Store store(dir.path() / "cache");
    REQUIRE(store.save("test", 7, "previous"));
    const auto before = test::read_file(store.file("test", 7));
    for (const auto fault : {files::Fault::OpenTemp, files::Fault::ShortWrite, files::Fault::BeforeRename}) {
        CAPTURE(static_cast<int>(fault));
        {
            const hardening::FaultGuard scope(fault);
            CHECK_FALSE(store.save("test", 7, "replacement that must not land"));
        }
        CHECK(test::read_file(store.file("test", 7)) == before);
        const auto kept = store.load("test", 7);
        REQUIRE(kept);
        CHECK(kept->bytes() == "previous");
    }
    REQUIRE(store.save("test", 7, "next"));
    const auto next = store.load("test", 7);
    REQUIRE(next);
    CHECK(next->bytes() == "next");
}
