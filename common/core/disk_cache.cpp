#include "core/disk_cache.h"

#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"

#include <sys/stat.h>

#include <atomic>
#include <bit>
#include <cstdio>
#include <cstdlib>

namespace ks::disk_cache {
namespace {

constexpr std::uint64_t kPrime1 = 0x9e3779b185ebca87ULL, kPrime2 = 0xc2b2ae3d27d4eb4fULL;
constexpr char kMagic[8] = {'K', 'S', 'C', 'A', 'C', 'H', 'E', '1'};
constexpr std::size_t kKindBytes = 16;

std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= kPrime2;
    h ^= h >> 29;
    h *= kPrime1;
    h ^= h >> 32;
    return h;
}

struct Header {
    char magic[8];
    char kind[kKindBytes];
    std::uint64_t key;
    std::uint64_t executable;
    std::uint64_t payload_size;
    std::uint64_t payload_hash;
};
static_assert(sizeof(Header) == 8 + kKindBytes + 4 * 8, "the header is written as it lies in memory");

Header make_header(std::string_view kind, std::uint64_t key, std::string_view payload) {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    std::memcpy(h.kind, kind.data(), std::min(kind.size(), kKindBytes));
    h.key = key;
    h.executable = executable_identity();
    h.payload_size = payload.size();
    h.payload_hash = hash_bytes(payload);
    return h;
}

std::atomic<bool> g_write_failure_logged{false};

} // namespace

Hasher& Hasher::bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    if (size >= 256) { // four lanes, folded into the state: a quarter of the multiplies' latency per byte
        std::uint64_t lane[4] = {state_, state_ ^ kPrime1, state_ ^ kPrime2, ~state_};
        for (; i + 32 <= size; i += 32)
            for (int k = 0; k < 4; ++k) {
                std::uint64_t w = 0;
                std::memcpy(&w, p + i + 8 * static_cast<std::size_t>(k), 8);
                lane[k] = std::rotl(lane[k] ^ (w * kPrime2), 31) * kPrime1;
            }
        for (std::uint64_t l : lane) state_ = std::rotl(state_ ^ mix(l), 27) * kPrime1;
    }
    for (; i + 8 <= size; i += 8) {
        std::uint64_t w = 0;
        std::memcpy(&w, p + i, 8);
        state_ = std::rotl(state_ ^ (w * kPrime2), 31) * kPrime1;
    }
    if (i < size) {
        std::uint64_t w = 0;
        std::memcpy(&w, p + i, size - i);
        state_ = std::rotl(state_ ^ ((w + (size - i)) * kPrime2), 31) * kPrime1;
    }
    length_ += size;
    return *this;
}

std::uint64_t Hasher::digest() const {
    return mix(state_ ^ mix(length_));
}

std::uint64_t hash_bytes(std::string_view data) {
    return Hasher().bytes(data.data(), data.size()).digest();
}

std::uint64_t executable_identity() {
    static const std::uint64_t identity = [] {
        struct stat st {};
        if (::stat("/proc/self/exe", &st) != 0) return std::uint64_t{0};
        return Hasher()
            .value(static_cast<std::int64_t>(st.st_size))
            .value(static_cast<std::int64_t>(st.st_mtim.tv_sec))
            .value(static_cast<std::int64_t>(st.st_mtim.tv_nsec))
            .digest();
    }();
    return identity;
}

Store Store::user() {
    if (const char* off = std::getenv("KS_DISK_CACHE"); off && std::string_view(off) == "off")
        return Store({});
    return Store(paths::user_cache_dir());
}

std::filesystem::path Store::file(std::string_view kind, std::uint64_t key) const {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(key));
    return folder_ / (std::string(kind) + "-" + hex + ".bin");
}

std::optional<Payload> Store::load(std::string_view kind, std::uint64_t key) const {
    if (!enabled() || kind.size() > kKindBytes) return std::nullopt;
    const std::filesystem::path path = file(kind, key);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    std::string error;
    auto text = Payload::of_file(path, error);
    if (!text) {
        log::info(path.string(), ": cache entry unreadable, computing it again (", error, ")");
        return std::nullopt;
    }
    const Header want = make_header(kind, key, {});
    Header got{};
    const char* why = nullptr;
    if (text->bytes().size() < sizeof(Header)) {
        why = "truncated header";
    } else {
        std::memcpy(&got, text->bytes().data(), sizeof got);
        const std::string_view payload = text->bytes().substr(sizeof(Header));
        if (std::memcmp(got.magic, want.magic, sizeof got.magic) != 0)
            why = "not a Killswitch cache file";
        else if (std::memcmp(got.kind, want.kind, kKindBytes) != 0 || got.key != key)
            why = "written for other inputs";
        else if (got.executable != want.executable)
            return std::nullopt; // another build wrote it: expected after every rebuild, not worth a line
        else if (got.payload_size != payload.size())
            why = "truncated";
        else if (got.payload_hash != hash_bytes(payload))
            why = "checksum mismatch";
        else {
            text->drop_prefix(sizeof(Header));
            return std::move(*text);
        }
    }
    log::info(path.string(), ": cache entry ignored (", why, "), computing it again");
    return std::nullopt;
}

bool Store::save(std::string_view kind, std::uint64_t key, std::string_view payload) const {
    if (!enabled() || kind.size() > kKindBytes) return false;
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    const Header h = make_header(kind, key, payload);
    std::string data(reinterpret_cast<const char*>(&h), sizeof h);
    data.append(payload);
    auto written = files::write_atomic(file(kind, key), data);
    if (written) return true;
    if (!g_write_failure_logged.exchange(true))
        log::info(folder_.string(), ": cannot write the cache (", written.error().message,
                  "); starting without it");
    return false;
}

} // namespace ks::disk_cache
