#pragma once
// Textures' mip chains through the disk cache (core/disk_cache.h). On the first load of an image the driver
// builds the mip chain (glGenerateMipmap: on llvmpipe a draw per level) and every level is read back and
// stored; later launches upload the stored levels one by one (glTexImage2D) and skip both the PNG decode and
// the mip generation. Reading back what the driver made, rather than filtering on the CPU, keeps the picture
// the same texel for texel. The key hashes kTextureCacheVersion, the GL renderer and version strings (another
// driver filters differently), the colour space and the image files' bytes; the disk cache adds the
// executable's identity. Anything that does not parse as a whole chain of the stated size is a miss.
#include "core/disk_cache.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace ks::render {

inline constexpr std::uint32_t kTextureCacheVersion = 1;

struct MipChain {
    int width = 0, height = 0;
    std::vector<std::vector<unsigned char>> levels; // RGBA8 rows, level 0 first, down to 1x1
    float extra = 0.0f;                             // a value computed with the image (the mean metalness)
};
// A chain read from a cache entry: its levels are views into the entry's bytes (uploaded from there, not
// copied first), valid while the entry's disk_cache::Payload lives.
struct MipChainView {
    int width = 0, height = 0;
    std::vector<std::string_view> levels;
    float extra = 0.0f;
};

// The number of levels of a full chain for a w x h image (down to 1x1).
int mip_level_count(int width, int height);

// Every level of `texture` as the driver holds it (glGetTexImage as RGBA8, no conversion); nullopt when the
// driver reports an error or a level of an unexpected size.
std::optional<MipChain> read_back_mip_chain(unsigned texture, int width, int height);
// Uploads every level of `chain` into the bound GL_TEXTURE_2D with `internal_format`.
void upload_mip_chain(const MipChainView& chain, unsigned internal_format);

std::string write_mip_chain(const MipChain& chain);
// nullopt when the payload is not one whole, consistent chain (sizes, level count, bytes per level).
std::optional<MipChainView> read_mip_chain(std::string_view payload);

// Stores chains on a worker thread (serialising and the atomic write's flush to disk cost a cold start's
// main thread more than the readback itself). The destructor writes what is queued, then returns.
class ChainWriter {
  public:
    explicit ChainWriter(disk_cache::Store store) : store_(std::move(store)) {}
    ~ChainWriter();
    ChainWriter(const ChainWriter&) = delete;
    ChainWriter& operator=(const ChainWriter&) = delete;
    void save(std::string_view kind, std::uint64_t key, MipChain chain);
    void flush(); // returns when everything queued so far is written

  private:
    void run();
    struct Job {
        std::string kind;
        std::uint64_t key = 0;
        MipChain chain;
    };
    disk_cache::Store store_;
    std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::deque<Job> queue_;
    bool busy_ = false, stop_ = false;
    std::thread thread_; // started with the first save
};

// The hasher every texture key starts from: version, the current GL context's renderer and version strings.
disk_cache::Hasher texture_key_base();

} // namespace ks::render
