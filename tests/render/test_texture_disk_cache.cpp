// Textures' mip chains through the disk cache (render/texture_disk_cache.h): a hit uploads the very levels
// the driver generated (so the picture cannot change), a changed image misses, and a bad entry is decoded
// again.
#include "gl_test_support.h"
#include "test_support.h"

#include "render/texture_cache.h"
#include "render/texture_disk_cache.h"

#include <epoxy/gl.h>
#include <doctest/doctest.h>
#include <stb_image.h>

#include <filesystem>

using namespace ks;
using namespace ks::render;
namespace fs = std::filesystem;

namespace {
fs::path texture_file(const std::string& name) {
    return test::source_dir() / "assets" / "textures" / name;
}

MipChain chain_of(const Texture& t) {
    auto chain = read_back_mip_chain(t.id, t.width, t.height);
    REQUIRE(chain);
    return *chain;
}

std::vector<unsigned char> decoded_png(const fs::path& path) {
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
    REQUIRE(px);
    std::vector<unsigned char> out(px, px + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(px);
    return out;
}

// The cache files in `folder` (one per image stored).
std::vector<fs::path> entries(const fs::path& folder) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.path().filename().string().rfind("texture-", 0) == 0) out.push_back(e.path());
    return out;
}

std::uint64_t key_of(const fs::path& entry) {
    const std::string name = entry.stem().string(); // texture-<16 hex digits>
    return std::stoull(name.substr(name.size() - 16), nullptr, 16);
}
} // namespace

TEST_CASE("texture disk cache: a chain round-trips; a truncated or inconsistent payload is refused") {
    CHECK(mip_level_count(1, 1) == 1);
    CHECK(mip_level_count(1024, 512) == 11);
    CHECK(mip_level_count(5, 3) == 3);
    MipChain chain;
    chain.width = 4;
    chain.height = 2;
    chain.extra = 0.25f;
    chain.levels = {std::vector<unsigned char>(32, 7), std::vector<unsigned char>(8, 9),
                    std::vector<unsigned char>(4, 11)};
    const std::string payload = write_mip_chain(chain);
    auto back = read_mip_chain(payload);
    REQUIRE(back);
    CHECK(back->width == 4);
    CHECK(back->height == 2);
    CHECK(back->extra == 0.25f);
    REQUIRE(back->levels.size() == chain.levels.size());
    for (std::size_t level = 0; level < chain.levels.size(); ++level) {
        const auto& want = chain.levels[level];
        CHECK(back->levels[level] ==
              std::string_view(reinterpret_cast<const char*>(want.data()), want.size()));
        // A view into the payload, not a copy.
        CHECK(back->levels[level].data() >= payload.data());
        CHECK(back->levels[level].data() + back->levels[level].size() <= payload.data() + payload.size());
    }
    CHECK_FALSE(read_mip_chain(payload.substr(0, payload.size() - 1)));
    CHECK_FALSE(read_mip_chain(payload + "x"));
    CHECK_FALSE(read_mip_chain(""));
    MipChain short_chain = chain;
    short_chain.levels.pop_back(); // a level missing
    CHECK_FALSE(read_mip_chain(write_mip_chain(short_chain)));
    MipChain wrong_size = chain;
    wrong_size.levels[1].push_back(0); // a level of the wrong size
    CHECK_FALSE(read_mip_chain(write_mip_chain(wrong_size)));
    MipChain huge = chain;
    huge.width = 1 << 20;
    CHECK_FALSE(read_mip_chain(write_mip_chain(huge)));
}

TEST_CASE("texture disk cache: a hit uploads the driver's own mip chain, level for level") {
    KS_REQUIRE_GL();
    test::ScratchDir dir;
    const disk_cache::Store store(dir / "cache");
    const fs::path base = texture_file("concrete_basecolor.png");
    const fs::path orm = texture_file("concrete_orm.png");
    TextureCache first(store);
    const Texture& srgb = first.get(base, ColorSpace::Srgb);
    const Texture& linear = first.get(orm, ColorSpace::Linear);
    const TextureCache::OccludedBase occluded = first.get_occluded_base(base, orm);
    REQUIRE_FALSE(srgb.placeholder);
    REQUIRE(occluded.id != 0);
    CHECK(first.disk_stats().misses == 3);
    CHECK(first.disk_stats().hits == 0);
    first.flush_disk_writes(); // written on a worker thread
    CHECK(entries(store.folder()).size() == 3);
    // The stored level 0 is the PNG's pixels as they are (no sRGB conversion on the way back).
    const MipChain srgb_chain = chain_of(srgb);
    CHECK(srgb_chain.levels[0] == decoded_png(base));
    CHECK(srgb_chain.levels.size() == static_cast<std::size_t>(mip_level_count(srgb.width, srgb.height)));

    TextureCache second(store);
    const Texture& srgb2 = second.get(base, ColorSpace::Srgb);
    const Texture& linear2 = second.get(orm, ColorSpace::Linear);
    const TextureCache::OccludedBase occluded2 = second.get_occluded_base(base, orm);
    CHECK(second.disk_stats().hits == 3);
    CHECK(second.disk_stats().misses == 0);
    CHECK(srgb2.width == srgb.width);
    CHECK(srgb2.height == srgb.height);
    CHECK(chain_of(srgb2).levels == srgb_chain.levels);
    CHECK(chain_of(linear2).levels == chain_of(linear).levels);
    CHECK(occluded2.mean_metallic == occluded.mean_metallic);
    const Texture occluded_texture{occluded.id, srgb.width, srgb.height, false};
    const Texture occluded_texture2{occluded2.id, srgb.width, srgb.height, false};
    CHECK(chain_of(occluded_texture2).levels == chain_of(occluded_texture).levels);
    GLint min_filter = 0;
    glBindTexture(GL_TEXTURE_2D, srgb2.id);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min_filter);
    CHECK(min_filter == GL_LINEAR_MIPMAP_LINEAR);

    // No store: nothing is read or written.
    TextureCache none(disk_cache::Store({}));
    (void)none.get(base, ColorSpace::Srgb);
    CHECK(none.disk_stats().hits == 0);
}

TEST_CASE("texture disk cache: a changed image misses, a bad entry is decoded again and rewritten") {
    KS_REQUIRE_GL();
    test::ScratchDir dir;
    const disk_cache::Store store(dir / "cache");
    const fs::path image = dir / "surface.png";
    fs::copy_file(texture_file("concrete_basecolor.png"), image);
    {
        TextureCache cache(store);
        (void)cache.get(image, ColorSpace::Srgb);
        CHECK(cache.disk_stats().misses == 1);
    }
    // Another image at the same path: its bytes are the key, so the old entry is not used.
    fs::copy_file(texture_file("concrete_orm.png"), image, fs::copy_options::overwrite_existing);
    {
        TextureCache cache(store);
        const Texture& t = cache.get(image, ColorSpace::Srgb);
        CHECK(cache.disk_stats().misses == 1);
        CHECK(cache.disk_stats().hits == 0);
        CHECK(chain_of(t).levels[0] == decoded_png(image));
    }
    REQUIRE(entries(store.folder()).size() == 2);
    // Entries that pass the store's checks but are not a whole chain, and a corrupt file: decoded again.
    for (const fs::path& entry : entries(store.folder()))
        REQUIRE(store.save("texture", key_of(entry), "not a mip chain"));
    {
        TextureCache cache(store);
        const Texture& t = cache.get(image, ColorSpace::Srgb);
        CHECK(cache.disk_stats().misses == 1);
        CHECK(chain_of(t).levels[0] == decoded_png(image));
    }
    for (const fs::path& entry : entries(store.folder())) {
        std::string bytes = test::read_file(entry);
        if (bytes.size() > 100) bytes[bytes.size() / 2] ^= 0x55; // the rewritten one: checksum now wrong
        test::write_file(entry, bytes);
    }
    {
        TextureCache cache(store);
        const Texture& t = cache.get(image, ColorSpace::Srgb);
        CHECK(cache.disk_stats().misses == 1);
        CHECK(chain_of(t).levels[0] == decoded_png(image));
    }
    TextureCache cache(store); // written again by the launch before
    (void)cache.get(image, ColorSpace::Srgb);
    CHECK(cache.disk_stats().hits == 1);
}
