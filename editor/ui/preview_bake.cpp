// The viewport's preview light bake on a worker thread (preview_bake.h).
#include "ui/preview_bake.h"

#include <cstdio>

namespace ks::editor::ui {

std::string PreviewBake::label() const {
    if (!running()) return {};
    char text[32];
    std::snprintf(text, sizeof(text), "  |  lighting %d%%", static_cast<int>(progress() * 100.0f));
    return text;
}

} // namespace ks::editor::ui
