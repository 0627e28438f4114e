// The binary glTF container checked before assimp reads it (glb_container.h).
#include "modelio/glb_container.h"

#include <array>
#include <cstring>
#include <fstream>
#include <string>

namespace ks::modelio {

namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534A; // "JSON"

std::uint32_t little_endian(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

Error glb_error(const std::filesystem::path& path, const std::string& what) {
    return Error(what, Location(path.string()), "the file is cut short or damaged; export it again as .glb");
}

} // namespace

Result<void> check_glb_container(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error("cannot open the file", Location(path.string()), "check that it can be read");
    std::error_code ec;
    const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
    if (ec) return Error("cannot read the file's size: " + ec.message(), Location(path.string()));
    std::array<unsigned char, 12> header{};
    if (!in.read(reinterpret_cast<char*>(header.data()), header.size()))
        return glb_error(path,
                         "the file is " + std::to_string(file_size) + " bytes, shorter than a GLB header");
    if (std::memcmp(header.data(), "glTF", 4) != 0)
        return glb_error(path, "the file does not start with the GLB signature \"glTF\"");
    if (const std::uint32_t version = little_endian(header.data() + 4); version != 2)
        return Error("GLB version " + std::to_string(version) + ", not 2", Location(path.string()),
                     "export as glTF 2.0 binary (.glb)");
    const std::uint32_t length = little_endian(header.data() + 8);
    if (length > file_size)
        return glb_error(path, "the GLB header says " + std::to_string(length) + " bytes, the file has " +
                                   std::to_string(file_size));
    // The chunks: each an 8-byte header (length, type) and its data, within the declared length.
    std::uint64_t at = header.size();
    for (int chunk = 0; at < length; ++chunk) {
        std::array<unsigned char, 8> chunk_header{};
        if (length - at < chunk_header.size() || !in.read(reinterpret_cast<char*>(chunk_header.data()), 8))
            return glb_error(path, "chunk " + std::to_string(chunk) + "'s header is cut off at byte " +
                                       std::to_string(at));
        const std::uint32_t chunk_length = little_endian(chunk_header.data());
        const std::uint32_t type = little_endian(chunk_header.data() + 4);
        if (chunk == 0 && type != kJsonChunk) return glb_error(path, "the first chunk is not the JSON chunk");
        at += chunk_header.size();
        if (chunk_length > length - at)
            return glb_error(path, "chunk " + std::to_string(chunk) + " says it holds " +
                                       std::to_string(chunk_length) + " bytes, only " +
                                       std::to_string(length - at) + " follow");
        at += chunk_length;
        in.seekg(static_cast<std::streamoff>(at));
    }
    if (at == header.size()) return glb_error(path, "the file has no JSON chunk");
    return ok();
}

} // namespace ks::modelio
