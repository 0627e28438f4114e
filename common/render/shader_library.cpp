#include "render/shader_library.h"

#include "core/log.h"

namespace ks::render {

bool default_shader_hot_reload() {
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

std::filesystem::file_time_type ShaderLibrary::mtime(const char* file) const {
    std::error_code ec;
    auto t = std::filesystem::last_write_time(dir_ / file, ec);
    return ec ? std::filesystem::file_time_type{} : t;
}

Result<void> ShaderLibrary::add(const ProgramFiles& files, ShaderProgram& target,
                                std::function<void(ShaderProgram&)> on_built) {
    Entry e{&files, &target, std::move(on_built), mtime(files.vertex), mtime(files.fragment)};
    auto program = build_program(files, dir_);
    if (!program) return program.error();
    target = std::move(*program);
    if (e.on_built) {
        target.use();
        e.on_built(target);
    }
    entries_.push_back(std::move(e));
    return ok();
}

int ShaderLibrary::poll(Clock::time_point now, bool force) {
    if (!force && now - last_poll_ < interval) return 0;
    last_poll_ = now;
    int replaced = 0;
    for (Entry& e : entries_) {
        auto vt = mtime(e.files->vertex), ft = mtime(e.files->fragment);
        if (vt == e.vertex_time && ft == e.fragment_time) continue;
        // Remember the new times whether or not the build works: a broken file is reported once, and
        // retried when it is saved again.
        e.vertex_time = vt;
        e.fragment_time = ft;
        auto program = build_program(*e.files, dir_);
        if (!program) {
            ++failures_;
            log::error(program.error().str(), "\n  (shader hot reload: keeping the previous '", e.files->name,
                       "' program)");
            continue;
        }
        *e.target = std::move(*program);
        if (e.on_built) {
            e.target->use();
            e.on_built(*e.target);
        }
        log::info("shader hot reload: rebuilt '", e.files->name, "' from ", dir_.string());
        ++replaced;
    }
    return replaced;
}

} // namespace ks::render
