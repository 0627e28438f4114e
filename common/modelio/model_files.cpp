#include "modelio/model_files.h"

#include "core/paths.h"
#include "modelio/model_lod.h"

#include <map>
#include <mutex>
#include <string>
#include <system_error>
#include <utility>

namespace ks::modelio {

std::filesystem::path user_models_dir() {
    const std::filesystem::path data = paths::user_data_dir();
    return data.empty() ? data : data / "models";
}

Result<void> check_model_name(std::string_view name) {
    if (name.empty()) return Error("no model file named", {}, "name a .glb, .gltf, .obj or .fbx file");
    if (name.find('\\') != std::string_view::npos)
        return Error("the model file \"" + std::string(name) + "\" uses '\\'", {},
                     "separate folders with '/'");
    const std::filesystem::path path{std::string(name)};
    if (path.is_absolute() || name.front() == '/')
        return Error("the model file \"" + std::string(name) + "\" is an absolute path", {},
                     "name it relative to assets/models or your models folder");
    if (name.find("//") != std::string_view::npos || name.back() == '/')
        return Error("the model file \"" + std::string(name) + "\" has an empty folder name", {},
                     "separate folders with one '/'");
    for (const auto& part : path)
        if (part == ".." || part == "." || part.empty())
            return Error("the model file \"" + std::string(name) + "\" has a \"" + part.string() + "\" part",
                         {}, "name it relative to the models folder, without . or .. parts");
    if (!has_supported_extension(path))
        return Error("the model file \"" + std::string(name) + "\" is not a .glb, .gltf, .obj or .fbx file",
                     {}, "export it as .glb (Blender: File > Export > glTF 2.0)");
    return ok();
}

std::filesystem::path resolve_model_file(std::string_view name) {
    const std::filesystem::path shipped = paths::asset("models") / std::string(name);
    std::error_code ec;
    if (std::filesystem::exists(shipped, ec)) return shipped;
    const std::filesystem::path user = user_models_dir();
    if (!user.empty() && std::filesystem::exists(user / std::string(name), ec))
        return user / std::string(name);
    return shipped;
}

namespace {

struct FileStamp {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type time{};
    bool operator==(const FileStamp&) const = default;
};

struct CacheEntry {
    FileStamp stamp;
    Result<std::shared_ptr<const ImportedModel>> result{Error("not read")};
};

FileStamp stamp_of(const std::filesystem::path& path) {
    std::error_code ec;
    FileStamp s;
    s.size = std::filesystem::file_size(path, ec);
    if (ec) s.size = static_cast<std::uintmax_t>(-1);
    s.time = std::filesystem::last_write_time(path, ec);
    return s;
}

} // namespace

Result<std::shared_ptr<const ImportedModel>> import_cached(const std::filesystem::path& path) {
    static std::mutex mutex;
    static std::map<std::string, CacheEntry> cache;
    const FileStamp stamp = stamp_of(path);
    const std::string key = path.lexically_normal().string();
    {
        std::lock_guard lock(mutex);
        auto it = cache.find(key);
        if (it != cache.end() && it->second.stamp == stamp) return it->second.result;
    }
    Result<ImportedModel> model = import_model(path);
    if (model) { // drawn many times: its triangles in draw order, and its levels of detail, made once here
        optimize_draw_order(*model);
        build_lods(*model);
    }
    CacheEntry entry{stamp, model ? Result<std::shared_ptr<const ImportedModel>>(
                                        std::make_shared<const ImportedModel>(std::move(*model)))
                                  : Result<std::shared_ptr<const ImportedModel>>(model.error())};
    std::lock_guard lock(mutex);
    cache[key] = entry;
    return entry.result;
}

} // namespace ks::modelio
