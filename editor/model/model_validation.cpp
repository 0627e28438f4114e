#include "model/model_validation.h"

#include "jsonio/suggest.h"
#include "level/model_entity.h"
#include "model/model_library.h"
#include "modelio/model_files.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace ks::editor {

namespace {

constexpr float kMinBoxSide = 1e-3f; // thinner than this, a box brush is degenerate

bool ends_with(const std::string& text, std::string_view tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The library's model closest in name to a file that is not there ("" when none is close).
std::string closest_model(const std::string& missing) {
    ModelLibrary library = ModelLibrary::with_default_folders();
    library.rescan();
    std::vector<std::string> names;
    for (const ModelEntry& entry : library.entries())
        if (!entry.shadowed) names.push_back(entry.name);
    return jsonio::closest_match(missing, names);
}

} // namespace

QuickFix model_quick_fix(const level::Entity& entity, const level::Diagnostic& diagnostic) {
    const auto* props = entity.try_as<level::ModelProps>();
    const std::string& path = diagnostic.error.where.path;
    if (!props) return {};
    if (ends_with(path, "props.scale") && props->scale != 1.0f)
        return {"Reset scale", fixes::SetField{"scale", FieldValue(1.0)}};
    if (ends_with(path, "props.collision") && props->collision.value != "none") {
        // A box needs some thickness along every axis: a flat model (a sign, a decal) collides with nothing.
        const auto model = level::entity_model(entity);
        const Vec3 sides = model ? (*model)->bounds.max - (*model)->bounds.min : Vec3(0.0f);
        if (props->collision.value != "box" && std::min({sides.x, sides.y, sides.z}) > kMinBoxSide)
            return {"Use box collision", fixes::SetField{"collision", FieldValue(std::string("box"))}};
        return {"No collision", fixes::SetField{"collision", FieldValue(std::string("none"))}};
    }
    std::error_code ec;
    if (ends_with(path, "props.file") && modelio::check_model_name(props->file) &&
        !std::filesystem::exists(modelio::resolve_model_file(props->file), ec))
        if (const std::string close = closest_model(props->file); !close.empty())
            return {"Use " + close, fixes::SetField{"file", FieldValue(close)}};
    return {};
}

} // namespace ks::editor
