#include "render/texture_disk_cache.h"

#include "render/window_target.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace ks::render {

namespace {
constexpr int kMaxSize = 16384; // no texture is larger; a bigger stated size is a corrupt entry

std::size_t level_bytes(int width, int height, int level) {
    return static_cast<std::size_t>(std::max(1, width >> level)) *
           static_cast<std::size_t>(std::max(1, height >> level)) * 4;
}
} // namespace

int mip_level_count(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size >>= 1) ++levels;
    return levels;
}

std::optional<MipChain> read_back_mip_chain(unsigned texture, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize) return std::nullopt;
    while (glGetError() != GL_NO_ERROR) {
    }
    GLint pack_buffer = 0;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, texture);
    MipChain chain;
    chain.width = width;
    chain.height = height;
    const int count = mip_level_count(width, height);
    bool sizes_ok = true;
    for (int level = 0; level < count && sizes_ok; ++level) {
        GLint w = 0, h = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &h);
        sizes_ok = w == std::max(1, width >> level) && h == std::max(1, height >> level);
        chain.levels.emplace_back(level_bytes(width, height, level));
        if (sizes_ok)
            glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, chain.levels.back().data());
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
    if (!sizes_ok || glGetError() != GL_NO_ERROR) return std::nullopt;
    return chain;
}

void upload_mip_chain(const MipChainView& chain, unsigned internal_format) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t level = 0; level < chain.levels.size(); ++level) {
        const int l = static_cast<int>(level);
        glTexImage2D(GL_TEXTURE_2D, l, static_cast<GLint>(internal_format), std::max(1, chain.width >> l),
                     std::max(1, chain.height >> l), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     chain.levels[level].data());
    }
}

std::string write_mip_chain(const MipChain& chain) {
    disk_cache::Writer w;
    w.value(chain.width);
    w.value(chain.height);
    w.value(chain.extra);
    w.value(static_cast<std::uint64_t>(chain.levels.size()));
    for (const auto& level : chain.levels) w.values(level);
    return std::move(w.data());
}

std::optional<MipChainView> read_mip_chain(std::string_view payload) {
    disk_cache::Reader r(payload);
    MipChainView chain;
    std::uint64_t count = 0;
    if (!r.value(chain.width) || !r.value(chain.height) || !r.value(chain.extra) || !r.value(count))
        return std::nullopt;
    if (chain.width < 1 || chain.height < 1 || chain.width > kMaxSize || chain.height > kMaxSize ||
        count != static_cast<std::uint64_t>(mip_level_count(chain.width, chain.height)))
        return std::nullopt;
    chain.levels.resize(static_cast<std::size_t>(count));
    for (std::size_t level = 0; level < chain.levels.size(); ++level) {
        const std::size_t want = level_bytes(chain.width, chain.height, static_cast<int>(level));
        if (!r.bytes(chain.levels[level], want) || chain.levels[level].size() != want) return std::nullopt;
    }
    if (!r.at_end()) return std::nullopt;
    return chain;
}

ChainWriter::~ChainWriter() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void ChainWriter::save(std::string_view kind, std::uint64_t key, MipChain chain) {
    if (!store_.enabled()) return;
    {
        std::lock_guard lock(mutex_);
        queue_.push_back({std::string(kind), key, std::move(chain)});
        if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    }
    wake_.notify_one();
}

void ChainWriter::flush() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

void ChainWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty()) return; // stopped, everything written
        Job job = std::move(queue_.front());
        queue_.pop_front();
        busy_ = true;
        lock.unlock();
        (void)store_.save(job.kind, job.key, write_mip_chain(job.chain));
        lock.lock();
        busy_ = false;
        if (queue_.empty()) idle_.notify_all();
    }
}

disk_cache::Hasher texture_key_base() {
    disk_cache::Hasher h;
    h.value(kTextureCacheVersion).text(gl_renderer_name()).text(gl_version_name());
    return h;
}

} // namespace ks::render
