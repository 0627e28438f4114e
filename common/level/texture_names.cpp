#include "level/texture_names.h"

#include "core/files.h"
#include "core/paths.h"
#include "jsonio/json_path.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"

#include <algorithm>
#include <system_error>

namespace ks::level {
namespace {
constexpr std::string_view kBaseColour = "_basecolor.png";
constexpr std::string_view kHeight = "_height.png";

// Collects the texture fields of one props struct by walking its visit() list.
class TextureFieldCollector {
  public:
    explicit TextureFieldCollector(std::vector<TextureField>& out) : out_(out) {}
    void field(std::string& value, const FieldInfo& info) {
        if (is_texture_field(info.name)) out_.push_back({info.name, &value});
    }
    void field(brush::Brush& brush, const FieldInfo& info) {
        for (size_t i = 0; i < brush.faces().size(); ++i)
            out_.push_back({jsonio::member_path(jsonio::element_path(info.name, i), "material"),
                            &brush.faces()[i].attributes.material});
    }
    template <class T>
    void field(T&, const FieldInfo&) {}

  private:
    std::vector<TextureField>& out_;
};
} // namespace

bool is_texture_field(std::string_view field_name) {
    return field_name == "texture";
}

std::vector<std::string> surface_texture_names_in(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const std::filesystem::path& base :
         files::list(folder, kBaseColour).value_or(std::vector<std::filesystem::path>{})) {
        const std::string file = base.filename().string();
        const std::string name = file.substr(0, file.size() - kBaseColour.size());
        std::error_code file_ec;
        if (std::filesystem::is_regular_file(folder / (name + std::string(kHeight)), file_ec))
            names.push_back(name);
    }
    std::sort(names.begin(), names.end()); // by name: "wall" before "wall2" (their files sort the other way)
    return names;
}

const std::vector<std::string>& shipped_texture_names() {
    static const std::vector<std::string> names = surface_texture_names_in(paths::asset("textures"));
    return names;
}

std::vector<TextureField> texture_fields(const Entity& entity) {
    std::vector<TextureField> out;
    TextureFieldCollector collector(out);
    // visit() is non-const (the same list serves readers that write); the collector only reads.
    std::visit([&](const auto& props) { const_cast<std::decay_t<decltype(props)>&>(props).visit(collector); },
               entity.props);
    return out;
}

void check_texture_names(const Level& level, const std::vector<std::string>& known, DiagnosticSink& sink,
                         const std::vector<size_t>& source_index) {
    if (known.empty()) return;
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& entity = level.entities[i];
        for (const TextureField& texture : texture_fields(entity)) {
            const std::string& name = *texture.name;
            if (name.empty() || std::find(known.begin(), known.end(), name) != known.end()) continue;
            const size_t shown = i < source_index.size() ? source_index[i] : i;
            const std::string path = jsonio::member_path(
                jsonio::member_path(jsonio::element_path("entities", shown), "props"), texture.field);
            std::string suggestion = jsonio::closest_match(name, known);
            std::string message = entity_subject(entity) + ": texture " + jsonio::quote_text(name) +
                                  " is not a surface material in assets/textures";
            if (!suggestion.empty()) message += "; did you mean \"" + suggestion + "\"?";
            sink.warning(path, std::move(message),
                         "surface materials: " + jsonio::join(known) +
                             "; the game draws any other name magenta");
            sink.tag_last(Diagnostic::Kind::UnknownTexture, std::move(suggestion));
        }
    }
}

} // namespace ks::level
