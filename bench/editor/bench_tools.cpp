// ks_bench tools: the geometry tools' per-frame work on a level of 2 025 brushes, headless (the editor's
// model and view code, no window), against the frame budget (16.7 ms at 60 Hz): what one mouse move costs
// while a box is dragged (the point on the plane, the move, the preview with its labels, and the point under
// the mouse that the overlay marks), the clip tool's preview (the cut's outline on 1, 100 and every brush
// selected), a vertex drag's mouse move (the snapped delta, the moved hulls, the preview and the handles the
// views draw, with 1 and 100 brushes selected), and each tool's commit with its undo.
#include "bench_registry.h"
#include "editor/median_time.h"
#include "model/edit_selection.h"
#include "model/editor.h"
#include "model/tool_clip.h"
#include "model/tool_draw.h"
#include "model/tool_vertex.h"
#include "view/tool_pointer.h"
#include "view/vertex_handles.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

using namespace ks;
constexpr double kToolsFrameMs = 1000.0 / 60.0;
constexpr int kSide = 45; // 45 x 45 brushes, 6 units apart

level::Level brush_field() {
    level::Level lv;
    for (int i = 0; i < kSide * kSide; ++i) {
        level::Entity e;
        e.id = lv.next_id++;
        e.position = Vec3(6.0f * static_cast<float>(i % kSide), 0.0f, 6.0f * static_cast<float>(i / kSide));
        e.props = level::BrushProps{};
        lv.entities.push_back(std::move(e));
    }
    return lv;
}

void tools_fail(const Error& e) {
    std::fprintf(stderr, "%s\n", e.str().c_str());
    std::exit(1);
}

void row(const char* what, double ms) {
    std::printf("%-64s %10.4f %10.4f\n", what, ms, ms / kToolsFrameMs);
}

int run_tools(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--quick")) quick = true;
    const int reps = quick ? 5 : 31;
    editor::Editor ed;
    ed.replace_level(brush_field(), {}, {});
    const auto shown = [](const level::Entity&) { return true; };
    const Vec3 centre(6.0f * kSide / 2.0f, 0.0f, 6.0f * kSide / 2.0f);

    editor::ViewCamera top;
    top.set_viewport({960.0f, 540.0f});
    top.set_view(editor::ViewMode::Top, centre, 80.0f);
    editor::ViewCamera eye;
    eye.set_viewport({960.0f, 540.0f});
    eye.camera.position = centre + Vec3(0.0f, 30.0f, 60.0f);
    eye.camera.pitch = -0.45f;

    std::printf("geometry tools benchmark: per-frame tool work on %zu brushes (no window); median of %d; "
                "frame = %.1f ms\n\n",
                ed.level().entities.size(), reps, kToolsFrameMs);
    std::printf("%-64s %10s %10s\n", "operation", "ms", "frames");
    int frame = 0;
    auto mouse_at = [&](int f) {
        return Vec2(300.0f + static_cast<float>(f % 200), 200.0f + static_cast<float>(f % 90));
    };

    for (const auto& [name, view] : {std::pair{"top", &top}, std::pair{"perspective", &eye}}) {
        editor::DrawTool draw;
        const auto start = editor::tool_point(ed.doc(), *view, {280.0f, 190.0f}, shown);
        if (!start) tools_fail(Error("no point under the mouse"));
        draw.press(editor::draw_plane_at(*start, *view), start->point);
        const double ms = bench::median_ms(reps, [&] {
            const Vec2 m = mouse_at(frame++);
            if (auto p = editor::point_on_plane(ed.doc(), *view, m, draw.plane())) draw.move(*p);
            const auto hover = editor::tool_point(ed.doc(), *view, m, shown);
            const editor::ToolPreview p = draw.preview();
            if (p.labels.empty() || !hover) tools_fail(Error("no preview"));
        });
        const std::string what = std::string("draw: one mouse move of a box drag, ") + name + " view";
        row(what.c_str(), ms);
    }
    {
        const double ms = bench::median_ms(reps, [&] {
            if (!editor::tool_point(ed.doc(), eye, mouse_at(frame++), shown))
                tools_fail(Error("no hover point"));
        });
        row("pointer alone: the point under the mouse (vertex, face, grid)", ms);
    }

    editor::ClipTool clip;
    for (DVec3 p : {DVec3(1, 0, -5), DVec3(1, 1, -5), DVec3(3, 0, 300)})
        if (auto r = clip.add_point(p); !r) tools_fail(r.error());
    for (int count : {1, 100, kSide * kSide}) {
        std::vector<int> ids;
        for (int i = 0; i < count; ++i) ids.push_back(ed.level().entities[static_cast<size_t>(i)].id);
        if (auto r = editor::select(ed, ids); !r) tools_fail(r.error());
        const double ms = bench::median_ms(reps, [&] {
            if (clip.preview(ed.doc()).segments.empty()) tools_fail(Error("no clip preview"));
        });
        const std::string what = "clip: preview (the cut on " + std::to_string(count) + " selected brushes)";
        row(what.c_str(), ms);
    }

    for (int count : {1, 100}) {
        std::vector<int> ids;
        for (int i = 0; i < count; ++i) ids.push_back(ed.level().entities[static_cast<size_t>(i)].id);
        if (auto r = editor::select(ed, ids); !r) tools_fail(r.error());
        editor::VertexTool vertex;
        DVec3 corner(-1e9); // the outermost corner, dragged outward (+x)
        for (const editor::VertexHandle& h : vertex.handles(ed.doc()))
            if (!h.split && h.at.x + h.at.y + h.at.z > corner.x + corner.y + corner.z) corner = h.at;
        Vec2 press;
        if (!top.project(Vec3(corner), press)) tools_fail(Error("the vertex is off screen"));
        if (auto r = vertex.grab(ed.doc(), corner); !r) tools_fail(r.error());
        const editor::VertexDrag drag = editor::start_vertex_drag(ed.doc(), top, press, corner, true);
        const double ms = bench::median_ms(reps, [&] {
            const Vec2 m = press + Vec2(30.0f + static_cast<float>(frame++ % 40), 0.0f);
            if (auto delta = editor::vertex_drag_delta(ed.doc(), top, m, drag)) vertex.drag(ed.doc(), *delta);
            if (vertex.preview(ed.doc()).segments.empty() || vertex.handles(ed.doc()).empty())
                tools_fail(Error("no vertex drag preview: " + vertex.preview(ed.doc()).problem));
        });
        vertex.cancel();
        const std::string what =
            "vertex: one mouse move of a vertex drag (" + std::to_string(count) + " brushes selected)";
        row(what.c_str(), ms);
    }

    if (auto r = editor::select(ed, {ed.level().entities.front().id}); !r) tools_fail(r.error());
    row("clip: apply to 1 brush + undo", bench::median_ms(reps, [&] {
            editor::ClipTool once = clip;
            if (auto r = once.apply(ed); !r) tools_fail(r.error());
            ed.undo();
        }));
    row("draw: commit a box + undo", bench::median_ms(reps, [&] {
            editor::DrawTool box;
            box.press({1, 0.0, std::nullopt}, {-20, 0, -20});
            box.move({-12, 0, -14});
            if (auto r = box.release(ed); !r) tools_fail(r.error());
            ed.undo();
        }));
    return 0;
}

bench::Registrar registrar(
    {"tools",
     "editor geometry tools (draw drag, clip preview, vertex drag, commits) on a 2 025-brush level, "
     "against one frame",
     run_tools});

} // namespace
