// Shader hot reload: programs are read from a shader folder; a changed file replaces the program, a file
// that does not compile keeps the previous program and reports "path:line: message".
#include "gl_test_support.h"
#include "test_support.h"

#include "core/log.h"
#include "render/debug_draw.h"
#include "render/scene_renderer.h"
#include "render/shader_library.h"
#include "render/texture_cache.h"

#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::render;
namespace fs = std::filesystem;

namespace {
fs::path shipped_shaders() {
    return ks::test::source_dir() / "assets" / "shaders";
}

void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    // File systems with coarse timestamps: make the change visible to an mtime check for certain.
    static int bump = 0;
    fs::last_write_time(path, fs::file_time_type::clock::now() + std::chrono::seconds(2 + ++bump));
}

std::string line_frag(const char* color) {
    return std::string("#version 330 core\nin vec4 v_color;\nout vec4 o_color;\nvoid main() { o_color = ") +
           color + "; }\n";
}

// The centre pixel of a frame that draws one thick bundle of debug lines across the view.
std::array<int, 3> draw_lines(SceneRenderer& renderer) {
    auto* ctx = ks::test::gl_context();
    ctx->bind();
    DebugDraw debug;
    for (int i = -20; i <= 20; ++i) {
        float y = static_cast<float>(i) * 0.002f;
        debug.line(Vec3(-1, y, -2), Vec3(1, y, -2), Vec4(1, 0, 0, 1));
        debug.line(Vec3(static_cast<float>(i) * 0.002f, -1, -2), Vec3(static_cast<float>(i) * 0.002f, 1, -2),
                   Vec4(1, 0, 0, 1));
    }
    SceneFrame frame;
    frame.camera.position = Vec3(0.0f);
    frame.debug = &debug;
    frame.width = ctx->width();
    frame.height = ctx->height();
    renderer.render(frame);
    auto rgb = ctx->read_rgb();
    size_t at = (static_cast<size_t>(ctx->height() / 2) * static_cast<size_t>(ctx->width()) +
                 static_cast<size_t>(ctx->width() / 2)) *
                3;
    return {rgb[at], rgb[at + 1], rgb[at + 2]};
}
} // namespace

TEST_CASE(
    "shader hot reload: a changed file replaces the program; a broken one keeps it and names the line") {
    KS_REQUIRE_GL();
    ks::test::ScratchDir dir;
    for (const auto& entry : fs::directory_iterator(shipped_shaders()))
        fs::copy_file(entry.path(), dir / entry.path().filename().string());
    TextureCache textures;
    RendererSettings settings;
    settings.shader_dir = dir.path().string();
    settings.shader_hot_reload = 1;
    settings.render_scale = 1.0f;
    auto renderer = SceneRenderer::create(textures, settings);
    REQUIRE(renderer);
    SceneRenderer& r = **renderer;
    const unsigned original = r.program_id("line");
    CHECK(original != 0);
    CHECK(r.poll_shaders(true) == 0); // nothing changed
    auto red = draw_lines(r);
    CHECK(red[0] > 200);
    CHECK(red[1] < 50);

    // A working edit: the next poll rebuilds the program and the lines turn green.
    write(dir / "line.frag", line_frag("vec4(0.0, 1.0, 0.0, 1.0) * v_color.a"));
    {
        log::Capture capture;
        CHECK(r.poll_shaders(true) == 1);
        CHECK(capture.text().find("rebuilt 'line'") != std::string::npos);
    }
    const unsigned edited = r.program_id("line");
    CHECK(edited != original);
    CHECK(r.program_id("pbr") != 0); // the others are untouched
    auto green = draw_lines(r);
    CHECK(green[0] < 50);
    CHECK(green[1] > 200);

    // A broken edit on line 4: the old (green) program stays, the error names the file and the line.
    write(dir / "line.frag",
          "#version 330 core\nin vec4 v_color;\nout vec4 o_color;\nvoid main() { o_color = "
          "no_such_variable; }\n");
    {
        log::Capture capture;
        CHECK(r.poll_shaders(true) == 0);
        CHECK(capture.count(log::Level::Error) == 1);
        CAPTURE(capture.text());
        CHECK(capture.text().find((dir / "line.frag").string() + ":4:") != std::string::npos);
        CHECK(capture.text().find("keeping the previous 'line' program") != std::string::npos);
        CHECK(r.poll_shaders(true) == 0); // reported once, not every poll
        CHECK(capture.count(log::Level::Error) == 1);
    }
    CHECK(r.program_id("line") == edited);
    auto still = draw_lines(r);
    CHECK(still[1] > 200);

    // A deleted file is a failed rebuild too (the program stays), and a fixed file recovers.
    write(dir / "line.frag", line_frag("vec4(0.0, 0.0, 1.0, 1.0)"));
    CHECK(r.poll_shaders(true) == 1);
    auto blue = draw_lines(r);
    CHECK(blue[2] > 200);
}

TEST_CASE("shader library: polls at most once per interval; a missing shader folder is a clear error") {
    KS_REQUIRE_GL();
    ks::test::ScratchDir dir;
    for (const char* f : {"line.vert", "line.frag"}) fs::copy_file(shipped_shaders() / f, dir / f);
    ShaderLibrary library(dir.path());
    ShaderProgram line;
    int built = 0;
    REQUIRE(library.add(line_program(), line, [&](ShaderProgram&) { ++built; }));
    CHECK(built == 1);
    const auto t0 = ShaderLibrary::Clock::now() + std::chrono::hours(1);
    CHECK(library.poll(t0) == 0);
    write(dir / "line.frag", line_frag("vec4(1.0)"));
    CHECK(library.poll(t0 + std::chrono::milliseconds(500)) == 0); // within the interval: not checked
    CHECK(library.poll(t0 + std::chrono::milliseconds(1100)) == 1);
    CHECK(built == 2);

    ShaderLibrary nowhere(dir / "missing");
    ShaderProgram p;
    auto r = nowhere.add(line_program(), p);
    REQUIRE_FALSE(r);
    CHECK(r.error().str().find("line.vert") != std::string::npos);
    CHECK(r.error().str().find("KS_SHADER_DIR") != std::string::npos);
}
