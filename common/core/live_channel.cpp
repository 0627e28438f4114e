// The live play-test channel (live_channel.h): framing, the socket folder and token, and both ends.
#include "core/live_channel.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <utility>

namespace ks::live {
namespace fs = std::filesystem;

namespace {

std::string errno_text(const char* what) {
    return std::string(what) + ": " + std::strerror(errno);
}

bool known_type(std::uint8_t type) {
    return type >= static_cast<std::uint8_t>(FrameType::Hello) &&
           type <= static_cast<std::uint8_t>(FrameType::Bye);
}

Result<sockaddr_un> socket_address(const fs::path& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const std::string text = path.string();
    if (text.size() >= sizeof(address.sun_path))
        return Error("socket path too long: " + text, {}, "set XDG_RUNTIME_DIR to a shorter folder");
    std::memcpy(address.sun_path, text.c_str(), text.size() + 1);
    return address;
}

void set_non_blocking(int fd) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fcntl(fd, F_SETFD, FD_CLOEXEC); // the game the editor starts must not inherit the listening socket
}

} // namespace

const char* frame_type_name(FrameType type) {
    switch (type) {
    case FrameType::Hello:
        return "hello";
    case FrameType::Welcome:
        return "welcome";
    case FrameType::Level:
        return "level";
    case FrameType::Applied:
        return "applied";
    case FrameType::Refused:
        return "refused";
    case FrameType::Bye:
        return "bye";
    }
    return "unknown";
}

std::string encode_frame(FrameType type, std::string_view payload) {
    std::string out(kFrameHeader, '\0');
    const auto size = static_cast<std::uint32_t>(payload.size());
    for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((size >> (8 * i)) & 0xffu);
    out[4] = static_cast<char>(type);
    out.append(payload);
    return out;
}

Result<std::optional<Frame>> FrameReader::next() {
    if (head_ > 0) { // frames read before: drop their bytes (a level update comes alone, so this is rare)
        buffer_.erase(0, head_);
        head_ = 0;
    }
    const std::size_t available = buffer_.size() - head_;
    if (available < kFrameHeader) return std::optional<Frame>();
    const auto* bytes = reinterpret_cast<const unsigned char*>(buffer_.data() + head_);
    const std::uint32_t size =
        bytes[0] | bytes[1] << 8 | bytes[2] << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
    if (!known_type(bytes[4]))
        return Error("not a live play-test frame (type byte " + std::to_string(bytes[4]) + ")", {},
                     "only the editor that started this game may send to it");
    if (size > kMaxFramePayload)
        return Error("frame of " + std::to_string(size) + " bytes is over the limit of " +
                         std::to_string(kMaxFramePayload),
                     {},
                     "a level document must stay under " + std::to_string(kMaxFramePayload >> 20) + " MiB");
    if (available < kFrameHeader + size) return std::optional<Frame>();
    Frame frame{static_cast<FrameType>(bytes[4]), buffer_.substr(head_ + kFrameHeader, size)};
    head_ += kFrameHeader + size;
    if (head_ == buffer_.size()) { // keep the capacity: an idle channel allocates nothing
        buffer_.clear();
        head_ = 0;
    }
    return std::optional<Frame>(std::move(frame));
}

Result<fs::path> socket_folder() {
    if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime && *runtime) {
        const fs::path folder(runtime);
        struct stat st {};
        if (folder.is_absolute() && stat(runtime, &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == getuid())
            return folder;
    }
    const fs::path folder = fs::temp_directory_path() / ("killswitch-" + std::to_string(getuid()));
    if (mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        return Error(errno_text("cannot create the live play-test folder"), Location(folder.string()), "");
    struct stat st {};
    if (lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != getuid() ||
        (st.st_mode & 077) != 0)
        return Error("the live play-test folder is not a private folder of this user",
                     Location(folder.string()), "remove it, or set XDG_RUNTIME_DIR");
    return folder;
}

Result<std::string> random_token() {
    std::ifstream random("/dev/urandom", std::ios::binary);
    unsigned char bytes[16];
    if (!random.read(reinterpret_cast<char*>(bytes), sizeof(bytes)))
        return Error("cannot read /dev/urandom for the live play-test token");
    static const char* digits = "0123456789abcdef";
    std::string token;
    for (unsigned char b : bytes) {
        token += digits[b >> 4];
        token += digits[b & 15];
    }
    return token;
}

// ---- Connection

Connection::Connection(Connection&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), reader_(std::move(other.reader_)),
      outbound_(std::move(other.outbound_)) {}

Connection& Connection::operator=(Connection&& other) noexcept {
    if (this != &other) {
        close();
        fd_ = std::exchange(other.fd_, -1);
        reader_ = std::move(other.reader_);
        outbound_ = std::move(other.outbound_);
    }
    return *this;
}

Connection::~Connection() {
    close();
}

void Connection::close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    reader_ = FrameReader{};
    outbound_.clear();
}

void Connection::send(FrameType type, std::string_view payload) {
    if (fd_ < 0) return;
    outbound_ += encode_frame(type, payload);
    flush();
}

void Connection::flush() {
    while (fd_ >= 0 && !outbound_.empty()) {
        const ssize_t n = ::send(fd_, outbound_.data(), outbound_.size(), MSG_NOSIGNAL);
        if (n > 0) {
            outbound_.erase(0, static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
        close(); // the peer went away; the reader notices on its next poll
    }
}

Result<bool> Connection::poll(std::vector<Frame>& frames) {
    flush();
    char buffer[65536];
    while (fd_ >= 0) {
        const ssize_t n = recv(fd_, buffer, sizeof(buffer), 0);
        if (n > 0) {
            reader_.feed(buffer, static_cast<std::size_t>(n));
            for (;;) {
                auto frame = reader_.next();
                if (!frame) return frame.error(); // the caller says why, then closes
                if (!*frame) break;
                frames.push_back(std::move(**frame));
            }
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) break;
        close(); // 0: the peer closed; an error: it is gone
    }
    return fd_ >= 0;
}

std::optional<unsigned> Connection::peer_uid() const {
    ucred credentials{};
    socklen_t length = sizeof(credentials);
    if (fd_ < 0 || getsockopt(fd_, SOL_SOCKET, SO_PEERCRED, &credentials, &length) != 0) return std::nullopt;
    return credentials.uid;
}

// ---- LiveServer

Result<LiveServer> LiveServer::listen(const fs::path& path, std::string token) {
    auto address = socket_address(path);
    if (!address) return address.error();
    const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0) return Error(errno_text("socket"));
    ::unlink(path.c_str()); // a socket left by an editor that crashed
    const mode_t old_mask = umask(0177);
    const int bound = bind(fd, reinterpret_cast<const sockaddr*>(&*address), sizeof(*address));
    umask(old_mask);
    if (bound != 0 || ::listen(fd, 4) != 0) {
        const Error error(errno_text("cannot listen for the live play-test"), Location(path.string()), "");
        ::close(fd);
        return error;
    }
    set_non_blocking(fd);
    LiveServer server;
    server.listen_fd_ = fd;
    server.path_ = path;
    server.token_ = std::move(token);
    return server;
}

LiveServer::LiveServer(LiveServer&& other) noexcept
    : listen_fd_(std::exchange(other.listen_fd_, -1)), path_(std::move(other.path_)),
      token_(std::move(other.token_)), peer_(std::move(other.peer_)),
      accepted_(std::exchange(other.accepted_, false)) {
    other.path_.clear();
}

LiveServer& LiveServer::operator=(LiveServer&& other) noexcept {
    std::swap(listen_fd_, other.listen_fd_);
    std::swap(path_, other.path_);
    std::swap(token_, other.token_);
    std::swap(peer_, other.peer_);
    std::swap(accepted_, other.accepted_);
    return *this; // `other` closes what this held
}

LiveServer::~LiveServer() {
    peer_.close();
    if (listen_fd_ >= 0) ::close(listen_fd_);
    listen_fd_ = -1;
    if (!path_.empty()) ::unlink(path_.c_str());
}

void LiveServer::drop_peer(std::vector<LiveNote>& notes, LiveNote why) {
    if (why.error) peer_.send(FrameType::Refused, why.text);
    peer_.close();
    accepted_ = false;
    notes.push_back(std::move(why));
}

void LiveServer::accept_new(std::vector<LiveNote>& notes) {
    for (;;) {
        const int fd = accept(listen_fd_, nullptr, nullptr);
        if (fd < 0) return;
        set_non_blocking(fd);
        Connection incoming(fd);
        const auto uid = incoming.peer_uid();
        if (!uid || *uid != getuid()) {
            incoming.send(FrameType::Refused, "live play-test: another user's process is refused");
            notes.push_back({true, "live play-test: refused a connection from another user"});
            continue;
        }
        if (peer_.open())
            drop_peer(notes, {false, "live play-test: a new game connected; the old one is let go"});
        peer_ = std::move(incoming);
        accepted_ = false;
    }
}

void LiveServer::poll(std::vector<Frame>& frames, std::vector<LiveNote>& notes) {
    if (listen_fd_ < 0) return;
    accept_new(notes);
    if (!peer_.open()) return;
    std::vector<Frame> arrived;
    auto polled = peer_.poll(arrived);
    for (Frame& f : arrived) {
        if (!accepted_) {
            if (f.type != FrameType::Hello || f.payload != token_) {
                drop_peer(notes,
                          {true, "live play-test: refused a peer that is not the game this editor started "
                                 "(no valid hello)"});
                return;
            }
            accepted_ = true;
            peer_.send(FrameType::Welcome, {});
            notes.push_back({false, "live play-test: the game is connected"});
            continue;
        }
        if (f.type == FrameType::Level || f.type == FrameType::Welcome || f.type == FrameType::Hello) {
            drop_peer(notes, {true, std::string("live play-test: the game sent an unexpected ") +
                                        frame_type_name(f.type) + " frame"});
            return;
        }
        frames.push_back(std::move(f));
    }
    if (!polled) {
        drop_peer(notes, {true, "live play-test: " + polled.error().str()});
    } else if (!*polled) {
        const bool was = accepted_;
        accepted_ = false;
        if (was) notes.push_back({false, "live play-test: the game closed the channel"});
    }
}

void LiveServer::send(FrameType type, std::string_view payload) {
    if (accepted_) peer_.send(type, payload);
}

// ---- LiveClient

std::optional<LiveClient> LiveClient::from_environment() {
    const char* path = std::getenv(kSocketVariable);
    const char* token = std::getenv(kTokenVariable);
    if (!path || !*path || !token || !*token) return std::nullopt;
    return LiveClient(path, token);
}

void LiveClient::try_connect(double now, std::vector<LiveNote>& notes) {
    if (now < next_try_) return;
    next_try_ = now + kRetrySeconds;
    auto address = socket_address(path_);
    if (!address) {
        if (!std::exchange(said_waiting_, true))
            notes.push_back({true, "live play-test: " + address.error().str()});
        return;
    }
    const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0) return;
    if (connect(fd, reinterpret_cast<const sockaddr*>(&*address), sizeof(*address)) != 0) {
        ::close(fd);
        if (!std::exchange(said_waiting_, true))
            notes.push_back({false, "live play-test: waiting for the editor at " + path_.string()});
        return;
    }
    set_non_blocking(fd);
    Connection c(fd);
    if (const auto uid = c.peer_uid(); !uid || *uid != getuid()) {
        notes.push_back({true, "live play-test: the socket belongs to another user; not connecting"});
        return;
    }
    connection_ = std::move(c);
    connection_.send(FrameType::Hello, token_);
    said_waiting_ = false;
}

void LiveClient::poll(double now, std::vector<Frame>& frames, std::vector<LiveNote>& notes) {
    if (!connection_.open()) {
        welcomed_ = false;
        try_connect(now, notes);
        if (!connection_.open()) return;
    }
    std::vector<Frame> arrived;
    auto polled = connection_.poll(arrived);
    for (Frame& f : arrived) {
        if (f.type == FrameType::Refused) {
            notes.push_back({true, "live play-test: the editor refused: " + f.payload});
            continue;
        }
        if (!welcomed_) {
            if (f.type == FrameType::Welcome) {
                welcomed_ = true;
                notes.push_back({false, "live play-test: connected to the editor"});
                continue;
            }
            connection_.close();
            notes.push_back({true, "live play-test: the peer did not welcome this game; disconnected"});
            break;
        }
        if (f.type != FrameType::Level) {
            connection_.send(FrameType::Refused,
                             std::string("unexpected ") + frame_type_name(f.type) + " frame");
            notes.push_back({true, std::string("live play-test: refused an unexpected ") +
                                       frame_type_name(f.type) + " frame"});
            continue;
        }
        frames.push_back(std::move(f));
    }
    if (!polled) {
        notes.push_back({true, "live play-test: " + polled.error().str()});
        connection_.send(FrameType::Refused, polled.error().str());
        connection_.close();
    }
    if (!connection_.open() && std::exchange(welcomed_, false))
        notes.push_back({false, "live play-test: the editor closed the channel; the game plays on"});
}

void LiveClient::send(FrameType type, std::string_view payload) {
    if (welcomed_) connection_.send(type, payload);
}

} // namespace ks::live
