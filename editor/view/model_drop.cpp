#include "view/model_drop.h"

#include "model/edit_models.h"

#include <cstring>

namespace ks::editor {

std::optional<std::string> model_payload_file(const void* data, int size) {
    constexpr int kMaxPayload = 4096;
    if (data == nullptr || size < 2 || size > kMaxPayload) return std::nullopt;
    const char* text = static_cast<const char*>(data);
    const auto length = static_cast<std::size_t>(size - 1);
    if (text[length] != '\0' || std::memchr(text, '\0', length) != nullptr) return std::nullopt;
    return std::string(text, length);
}

Vec3 model_drop_point(const Document& doc, const geometry::Ray& ray, const ShownFn& shown,
                      const Vec3& fallback) {
    return placement_for(doc, level::EntityType::Model, place_point(doc, ray, shown, fallback));
}

Result<int> place_model_at(Editor& editor, const std::string& file, const geometry::Ray& ray,
                           const ShownFn& shown, const Vec3& fallback) {
    return place_model(editor, file, model_drop_point(editor.doc(), ray, shown, fallback));
}

} // namespace ks::editor
