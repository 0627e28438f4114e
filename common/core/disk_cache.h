#pragma once
// A disk cache for results the game can always compute again but that cost start-up time (the navigation
// mesh, the light bake). One file per entry, `<kind>-<key>.bin` in a folder (by default
// paths::user_cache_dir()), holding a header (magic, format, kind, key, the executable's identity, payload
// size and checksum) and the payload. The key is a content hash of everything the result depends on (the
// caller's inputs, settings and a version constant of its algorithm); the executable's identity (its file's
// size and modification time) makes every rebuild start afresh, so a result never outlives the code that
// computed it.
//
// Robust by construction: a missing, truncated, corrupt (checksum), foreign (magic, kind, key) or stale
// (another executable) file is a miss, logged and then overwritten by the recomputed result; writes are
// atomic (files::write_atomic); a folder that cannot be made or written means no caching, never an error.
// KS_DISK_CACHE=off turns the cache off (Store::user() is then a store that never hits nor writes).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace ks::disk_cache {

// A 64-bit content hash (not cryptographic): eight bytes a step, and above 256 bytes four independent lanes
// of eight (the checksum of a warm start's 80 MB of entries was a chain of dependent multiplies).
class Hasher {
  public:
    Hasher& bytes(const void* data, std::size_t size);
    template <class T>
    Hasher& value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        return bytes(&v, sizeof v);
    }
    template <class T>
    Hasher& values(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(v.size());
        return bytes(v.data(), v.size() * sizeof(T));
    }
    Hasher& text(std::string_view s) {
        value(s.size());
        return bytes(s.data(), s.size());
    }
    std::uint64_t digest() const;

  private:
    std::uint64_t state_ = 0x9e3779b97f4a7c15ULL;
    std::uint64_t length_ = 0;
};
std::uint64_t hash_bytes(std::string_view data);

// Payload writing and bounds-checked reading of plain values and vectors of them.
class Writer {
  public:
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        out_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <class T>
    void values(const std::vector<T>& v) {
        value(static_cast<std::uint64_t>(v.size()));
        out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    std::string& data() { return out_; }

  private:
    std::string out_;
};

class Reader {
  public:
    explicit Reader(std::string_view data) : data_(data) {}
    template <class T>
    bool value(T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (!ok_ || data_.size() - at_ < sizeof v) return ok_ = false;
        std::memcpy(&v, data_.data() + at_, sizeof v);
        at_ += sizeof v;
        return true;
    }
    // At most `max_count` elements (a corrupt count must not allocate the world).
    template <class T>
    bool values(std::vector<T>& v, std::uint64_t max_count) {
        std::uint64_t n = 0;
        if (!value(n) || n > max_count || n > (data_.size() - at_) / sizeof(T)) return ok_ = false;
        v.resize(static_cast<std::size_t>(n));
        if (n == 0) return true; // an empty vector's data() may be null, which memcpy must not get
        std::memcpy(v.data(), data_.data() + at_, static_cast<std::size_t>(n) * sizeof(T));
        at_ += static_cast<std::size_t>(n) * sizeof(T);
        return true;
    }
    // As values<unsigned char>, but the bytes stay where they are: `out` views the data read from.
    bool bytes(std::string_view& out, std::uint64_t max_count) {
        std::uint64_t n = 0;
        if (!value(n) || n > max_count || n > data_.size() - at_) return ok_ = false;
        out = data_.substr(at_, static_cast<std::size_t>(n));
        at_ += static_cast<std::size_t>(n);
        return true;
    }
    bool ok() const { return ok_; }
    bool at_end() const { return ok_ && at_ == data_.size(); }

  private:
    std::string_view data_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

// An entry's payload: the entry's file mapped read-only, its pages straight from the page cache (a warm start
// reads about 80 MB of entries: reading them into memory faulted in, zeroed and copied every page), or the
// file read into memory where it cannot be mapped. Valid while it lives.
class Payload {
  public:
    // The whole file; nullopt with `error` set when it cannot be read.
    static std::optional<Payload> of_file(const std::filesystem::path& path, std::string& error);
    explicit Payload(std::string owned) : owned_(std::move(owned)), view_(owned_) {}
    Payload(Payload&& other) noexcept;
    Payload& operator=(Payload&& other) noexcept;
    Payload(const Payload&) = delete;
    Payload& operator=(const Payload&) = delete;
    ~Payload();

    std::string_view bytes() const { return view_; }
    operator std::string_view() const { return view_; }
    void drop_prefix(std::size_t n) { view_.remove_prefix(std::min(n, view_.size())); }

  private:
    Payload() = default;
    void unmap();
    void* map_ = nullptr;
    std::size_t map_size_ = 0;
    std::string owned_;
    std::string_view view_;
};

class Store {
  public:
    // A store in `folder` (created on the first write); an empty folder: no caching.
    explicit Store(std::filesystem::path folder) : folder_(std::move(folder)) {}
    // The user's: paths::user_cache_dir(), or none when KS_DISK_CACHE=off or there is no such folder.
    static Store user();

    bool enabled() const { return !folder_.empty(); }
    const std::filesystem::path& folder() const { return folder_; }
    std::filesystem::path file(std::string_view kind, std::uint64_t key) const;

    // The payload stored for (kind, key) by this executable, checksum verified; nullopt otherwise (a file
    // that is there but unusable is logged as such).
    std::optional<Payload> load(std::string_view kind, std::uint64_t key) const;
    // Writes the entry atomically; false (logged once per process) when the folder cannot be written.
    bool save(std::string_view kind, std::uint64_t key, std::string_view payload) const;

  private:
    std::filesystem::path folder_;
};

// The identity of the running executable (its file's size and modification time, hashed): entries written
// by another build are misses.
std::uint64_t executable_identity();

} // namespace ks::disk_cache
