#pragma once
// The live play-test channel between the editor and the game it started (docs/editor.md, "Live
// play-test"): a Unix domain socket in the user's runtime folder (never a network port). The editor listens
// (LiveServer) and the game connects (LiveClient); both poll without blocking once a frame. Frames are
// length-prefixed (kFrameHeader bytes: a little-endian 32-bit payload size, then the frame type) and capped
// at kMaxFramePayload; a peer that sends anything else is refused with a message and dropped. A peer is
// accepted only when it runs as the same user (SO_PEERCRED) and its first frame is a Hello carrying the
// session's random token, which the editor gives only to the game it starts (in its environment, readable
// by that user alone). Either side may close at any time: the server takes a new game, the client tries
// again every kRetrySeconds.
#include "core/result.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::live {

enum class FrameType : std::uint8_t {
    Hello = 1,   // game -> editor: the session token
    Welcome = 2, // editor -> game: the token accepted
    Level = 3,   // editor -> game: the whole level document (the JSON the editor would save)
    Applied = 4, // game -> editor: the level update is playing (payload: a summary)
    Refused = 5, // either way: what was refused and why (the sender keeps running)
    Bye = 6,     // game -> editor: the player chose "Back to editor"
};
const char* frame_type_name(FrameType type);

inline constexpr std::size_t kFrameHeader = 5;
inline constexpr std::size_t kMaxFramePayload = 16u << 20; // a level document is well under 1 MiB
inline constexpr double kRetrySeconds = 1.0;

// The environment the editor gives the game: the socket's path and the session's token.
inline constexpr const char* kSocketVariable = "KS_LIVE_SOCKET";
inline constexpr const char* kTokenVariable = "KS_LIVE_TOKEN";

struct Frame {
    FrameType type = FrameType::Hello;
    std::string payload;
};

std::string encode_frame(FrameType type, std::string_view payload);

// Bytes in, whole frames out. A header with an unknown type or a size over the cap is an error (the
// stream cannot be trusted after it: the connection is dropped).
class FrameReader {
  public:
    void feed(const char* data, std::size_t size) { buffer_.append(data, size); }
    // The next complete frame, nullopt while one is incomplete, or an Error naming what was wrong.
    Result<std::optional<Frame>> next();
    std::size_t buffered() const { return buffer_.size(); }

  private:
    std::string buffer_;
    std::size_t head_ = 0; // consumed bytes at the front of buffer_
};

// The folder for the socket: $XDG_RUNTIME_DIR (absolute and owned by the user), else a 0700 folder
// /tmp/killswitch-UID created on demand (refused when it exists with another owner or wider permissions).
Result<std::filesystem::path> socket_folder();
// 32 hex characters from the system's random source.
Result<std::string> random_token();

// One connected socket: non-blocking sends (an outbound queue flushed on each poll) and reads.
class Connection {
  public:
    Connection() = default;
    explicit Connection(int fd) : fd_(fd) {}
    Connection(Connection&& other) noexcept;
    Connection& operator=(Connection&& other) noexcept;
    ~Connection();

    bool open() const { return fd_ >= 0; }
    void send(FrameType type, std::string_view payload);
    // Flushes what is queued and reads what arrived; complete frames are appended to `frames`. False when
    // the peer closed; an Error (garbage, a frame over the cap) leaves it to the caller to say why and close.
    Result<bool> poll(std::vector<Frame>& frames);
    void close();
    // The user id of the process at the other end (SO_PEERCRED), or nullopt.
    std::optional<unsigned> peer_uid() const;

  private:
    void flush();

    int fd_ = -1;
    FrameReader reader_;
    std::string outbound_;
};

// What a poll saw, for the side's status line and log.
struct LiveNote {
    bool error = false;
    std::string text;
};

// The editor's end: listens at `path` (created 0600 inside socket_folder()), takes one game at a time.
class LiveServer {
  public:
    static Result<LiveServer> listen(const std::filesystem::path& path, std::string token);
    LiveServer(LiveServer&& other) noexcept;
    LiveServer& operator=(LiveServer&& other) noexcept;
    ~LiveServer(); // closes and removes the socket file

    // Accepts, checks and reads; frames from the accepted game go to `frames`, what happened to `notes`.
    void poll(std::vector<Frame>& frames, std::vector<LiveNote>& notes);
    bool connected() const { return accepted_; }
    void send(FrameType type, std::string_view payload);
    const std::filesystem::path& path() const { return path_; }
    const std::string& token() const { return token_; }

  private:
    LiveServer() = default;
    void accept_new(std::vector<LiveNote>& notes);
    void drop_peer(std::vector<LiveNote>& notes, LiveNote why);

    int listen_fd_ = -1;
    std::filesystem::path path_;
    std::string token_;
    Connection peer_;
    bool accepted_ = false; // the peer sent the right Hello
};

// The game's end: connects to `path` and says Hello with `token`; after a refusal or the editor closing it
// tries again every kRetrySeconds of `now` (seconds, any clock).
class LiveClient {
  public:
    LiveClient(std::filesystem::path path, std::string token)
        : path_(std::move(path)), token_(std::move(token)) {}
    // The game's environment (kSocketVariable, kTokenVariable), or nullopt when it was not started live.
    static std::optional<LiveClient> from_environment();

    void poll(double now, std::vector<Frame>& frames, std::vector<LiveNote>& notes);
    bool connected() const { return welcomed_; }
    void send(FrameType type, std::string_view payload);

  private:
    void try_connect(double now, std::vector<LiveNote>& notes);

    std::filesystem::path path_;
    std::string token_;
    Connection connection_;
    bool welcomed_ = false;
    bool said_waiting_ = false;
    double next_try_ = 0.0;
};

} // namespace ks::live
