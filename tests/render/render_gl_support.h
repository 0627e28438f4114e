#pragma once
// Shared by the renderer's GL tests (tests/render/test_render_gl.cpp and test_render_gl_main_level.cpp).
#include "test_support.h"

#include <filesystem>

namespace ks::test::render_gl {

// The committed assets the renderer loads (models, textures), as the game finds them.
inline std::filesystem::path assets_dir() {
    return ks::test::source_dir() / "assets";
}

} // namespace ks::test::render_gl
