// The live play-test channel (core/live_channel.h): framing and its cap, the handshake, a stranger and
// garbage refused with a message, and both ends surviving the other closing.
#include "core/live_channel.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>

using namespace ks;
using namespace ks::live;

namespace {

struct Pump {
    std::vector<Frame> server_frames, client_frames;
    std::vector<LiveNote> server_notes, client_notes;
    // A few rounds of both ends' polls at time `now` (everything local arrives at once).
    void run(LiveServer* server, LiveClient* client, double now) {
        for (int i = 0; i < 4; ++i) {
            if (server) server->poll(server_frames, server_notes);
            if (client) client->poll(now, client_frames, client_notes);
        }
    }
};

bool any_note(const std::vector<LiveNote>& notes, const char* text, bool error) {
    for (const auto& n : notes)
        if (n.error == error && n.text.find(text) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("live frames round-trip however the bytes are split, and refuse a type or size they do not know") {
    const std::string a = encode_frame(FrameType::Level, "{\"version\": 3}");
    const std::string b = encode_frame(FrameType::Applied, "");
    CHECK(a.size() == kFrameHeader + 14);
    FrameReader reader;
    const std::string both = a + b;
    std::vector<Frame> got;
    for (char c : both) { // one byte at a time
        reader.feed(&c, 1);
        auto f = reader.next();
        REQUIRE(f);
        if (*f) got.push_back(std::move(**f));
    }
    REQUIRE(got.size() == 2);
    CHECK(got[0].type == FrameType::Level);
    CHECK(got[0].payload == "{\"version\": 3}");
    CHECK(got[1].type == FrameType::Applied);
    CHECK(got[1].payload.empty());
    CHECK(reader.buffered() == 0);

    FrameReader garbage;
    garbage.feed("GET / HTTP/1.1\r\n", 16);
    auto g = garbage.next();
    REQUIRE_FALSE(g);
    CHECK(g.error().message.find("not a live play-test frame") != std::string::npos);

    std::string huge = encode_frame(FrameType::Level, "");
    const auto over = static_cast<std::uint32_t>(kMaxFramePayload + 1);
    for (int i = 0; i < 4; ++i) huge[i] = static_cast<char>((over >> (8 * i)) & 0xffu);
    FrameReader oversized;
    oversized.feed(huge.data(), huge.size());
    auto o = oversized.next();
    REQUIRE_FALSE(o);
    CHECK(o.error().message.find("over the limit") != std::string::npos);
}

TEST_CASE("the live channel connects its own game, carries frames both ways and refuses strangers") {
    test::ScratchDir dir;
    const auto path = dir / "live.sock";
    auto server = LiveServer::listen(path, "secret-token");
    REQUIRE(server);
    Pump pump;

    SUBCASE("its own game: welcomed, a level out and an answer back") {
        LiveClient client(path, "secret-token");
        pump.run(&*server, &client, 0.0);
        CHECK(server->connected());
        CHECK(client.connected());
        CHECK(any_note(pump.client_notes, "connected to the editor", false));
        server->send(FrameType::Level, "level text");
        client.send(FrameType::Applied, "ok");
        pump.run(&*server, &client, 0.1);
        REQUIRE(pump.client_frames.size() == 1);
        CHECK(pump.client_frames[0].payload == "level text");
        REQUIRE(pump.server_frames.size() == 1);
        CHECK(pump.server_frames[0].type == FrameType::Applied);
    }

    SUBCASE("a stranger with the wrong token is refused with a message, and the real game still gets in") {
        LiveClient stranger(path, "guessed");
        pump.run(&*server, &stranger, 0.0);
        CHECK_FALSE(server->connected());
        CHECK_FALSE(stranger.connected());
        CHECK(any_note(pump.server_notes, "not the game this editor started", true));
        CHECK(any_note(pump.client_notes, "the editor refused", true));
        LiveClient game(path, "secret-token");
        pump.run(&*server, &game, 0.0);
        CHECK(server->connected());
        CHECK(game.connected());
    }

    SUBCASE("garbage is refused with a message and the connection dropped") {
        const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strncpy(address.sun_path, path.c_str(), sizeof(address.sun_path) - 1);
        REQUIRE(connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0);
        const char junk[] = "\x01\x02\x03\x04\xff garbage";
        REQUIRE(::write(fd, junk, sizeof(junk)) > 0);
        pump.run(&*server, nullptr, 0.0);
        CHECK_FALSE(server->connected());
        CHECK(any_note(pump.server_notes, "not a live play-test frame", true));
        Connection raw(fd);
        std::vector<Frame> answer;
        (void)raw.poll(answer);
        REQUIRE_FALSE(answer.empty());
        CHECK(answer[0].type == FrameType::Refused);
    }
}

TEST_CASE("the game's end refuses an update it cannot read and survives the editor closing and coming back") {
    test::ScratchDir dir;
    const auto path = dir / "live.sock";
    Pump pump;
    LiveClient client(path, "token");
    pump.run(nullptr, &client, 0.0); // no editor yet: it waits
    CHECK_FALSE(client.connected());
    CHECK(any_note(pump.client_notes, "waiting for the editor", false));
    {
        auto server = LiveServer::listen(path, "token");
        REQUIRE(server);
        pump.run(&*server, &client, 1.5); // the retry is due
        REQUIRE(client.connected());
        server->send(FrameType::Bye, ""); // not something the editor sends: refused, the channel stays
        pump.run(&*server, &client, 1.6);
        CHECK(pump.client_frames.empty());
        CHECK(any_note(pump.client_notes, "refused an unexpected bye frame", true));
        CHECK(client.connected());
    }
    pump.client_notes.clear();
    pump.run(nullptr, &client, 1.7); // the editor closed
    CHECK_FALSE(client.connected());
    CHECK(any_note(pump.client_notes, "the editor closed the channel", false));
    auto again = LiveServer::listen(path, "token");
    REQUIRE(again);
    pump.run(&*again, &client, 1.8); // before the retry time: not yet
    CHECK_FALSE(client.connected());
    pump.run(&*again, &client, 3.0);
    CHECK(client.connected());
    CHECK(again->connected());
}

TEST_CASE("the live socket folder is private to the user and tokens differ") {
    auto folder = socket_folder();
    REQUIRE(folder);
    CHECK(std::filesystem::is_directory(*folder));
    auto a = random_token(), b = random_token();
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->size() == 32);
    CHECK(*a != *b);
}
